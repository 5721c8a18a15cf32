// The command line's refusal of a value out of range (app/scale/option_ranges.h),
// in its words, with the property's name: ParaView's range domains bound the
// GUI's widgets only, and Python sets any value, so the setter is where a
// value is refused. The value held is kept.
#pragma once
#include <cstddef>
#include <string>

#include <vtkObject.h>

#include "app/scale/option_ranges.h"

namespace tg::paraview {

// True when `v` is taken and differs from `field`; else `field` is kept and
// a refusal ("SETTER: PROPERTY must be within RANGE; kept V") goes to
// ParaView's output messages when `v` is out of `r` (a NaN is).
template <class T>
bool acceptValue(vtkObject* self, const char* setter, const char* property, T& field, T v,
                 const app::NumberRange& r) {
  if (!r.contains(double(v))) {
    vtkErrorWithObjectMacro(self, << setter << ": " << app::rangeMessage(property, r) << "; kept " << field);
    return false;
  }
  if (field == v) return false;
  field = v;
  return true;
}

// An enumeration's values, 0..count-1.
inline app::NumberRange choices(std::size_t count) { return {0.0, double(count) - 1.0, true}; }

}  // namespace tg::paraview
