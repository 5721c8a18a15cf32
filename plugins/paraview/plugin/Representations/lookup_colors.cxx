#include "lookup_colors.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <vtkDataArray.h>
#include <vtkScalarsToColors.h>

namespace tg::paraview {
namespace {

constexpr vtkIdType kContinuousSamples = 1024;

glm::vec4 mapped(vtkScalarsToColors* lut, double v) {
  const unsigned char* c = lut->MapValue(v);
  return glm::vec4(float(c[0]) / 255.0f, float(c[1]) / 255.0f, float(c[2]) / 255.0f, 1.0f);
}

}  // namespace

LookupReading lookupReading(vtkScalarsToColors* lut) {
  LookupReading r;
  r.magnitude = lut->GetVectorMode() != vtkScalarsToColors::COMPONENT;
  r.component = std::max(0, lut->GetVectorComponent());
  r.log = lut->UsingLogScale() != 0;
  return r;
}

std::vector<float> lookupScalars(vtkDataArray* array, std::span<const std::uint32_t> pointOfRecord,
                                 const LookupReading& r) {
  std::vector<float> out(pointOfRecord.size());
  const int nc = array->GetNumberOfComponents();
  const vtkIdType n = array->GetNumberOfTuples();
  const bool magnitude = nc > 1 && r.magnitude;
  const int component = std::min(r.component, nc - 1);
  for (std::size_t i = 0; i < pointOfRecord.size(); ++i) {
    const vtkIdType p = vtkIdType(pointOfRecord[i]);
    double v = std::numeric_limits<double>::quiet_NaN();
    if (p < n) {
      if (magnitude) {
        double s = 0;
        for (int c = 0; c < nc; ++c) s += array->GetComponent(p, c) * array->GetComponent(p, c);
        v = std::sqrt(s);
      } else {
        v = array->GetComponent(p, component);
      }
    }
    if (r.log) v = v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
    out[i] = float(v);
  }
  return out;
}

LookupTable sampleLookupTable(vtkScalarsToColors* lut, const LookupReading& r) {
  LookupTable t;
  const double* range = lut->GetRange();
  double lo = range[0], hi = range[1];
  if (r.log) {
    lo = lo > 0.0 ? std::log10(lo) : std::log10(std::numeric_limits<double>::min());
    hi = hi > 0.0 ? std::log10(hi) : lo;
  }
  t.window = glm::dvec2(lo, hi);
  const vtkIdType available = lut->GetNumberOfAvailableColors();
  const vtkIdType n = available > 0 && available <= 4096 ? available : kContinuousSamples;
  t.colors.reserve(std::size_t(n) + 3);
  for (vtkIdType i = 0; i < n; ++i) {
    const double x = lo + (double(i) + 0.5) / double(n) * (hi - lo);  // the middle of part i
    t.colors.push_back(mapped(lut, r.log ? std::pow(10.0, x) : x));
  }
  const double lowest = r.log ? std::pow(10.0, lo) : lo, highest = r.log ? std::pow(10.0, hi) : hi;
  t.colors.push_back(mapped(lut, std::numeric_limits<double>::quiet_NaN()));
  t.colors.push_back(mapped(lut, std::nextafter(lowest, -std::numeric_limits<double>::infinity())));
  t.colors.push_back(mapped(lut, std::nextafter(highest, std::numeric_limits<double>::infinity())));
  return t;
}

}  // namespace tg::paraview
