#include "app/scale/option_ranges.h"

#include "app/scale/cli_values.h"
#include "util/number_text.h"

namespace tg::app {

std::string NumberRange::text() const {
  const std::string span = util::numberText(lo) + ".." + util::numberText(hi);
  return zeroOff ? "0 (off) or " + span : span;
}

std::string rangeMessage(std::string_view name, const NumberRange& r) {
  return std::string(name) + " must be within " + r.text();
}

double checkedNumber(std::string_view name, std::string_view text, const NumberRange& r) {
  // An integer range reads integers only ("2.5" is no count), checked before
  // any narrowing; "1e300" is a number outside the range, said so.
  const double v = parseDouble(name, text);
  if (!r.contains(v)) throw UsageError(rangeMessage(name, r));
  return r.integer ? double(parseInt(name, text)) : v;
}

}  // namespace tg::app
