// Which reading options each format uses, from the table of formats
// (io/core/format_table.h); the rest are refused, not ignored.
#include "io/core/format_table.h"

namespace tg::io {

InputFormat inputFormatOf(const std::string& path) {
  const InputFormatRow* row = inputFormatRowOf(path);
  return row && row->readTensors ? row->format : InputFormat::Unknown;
}

const char* inputFormatName(InputFormat f) {
  for (const InputFormatRow& row : inputFormats())
    if (row.format == f && f != InputFormat::Unknown) return row.name;
  return "unknown";
}

std::string inapplicableOption(InputFormat format, const ReadOptions& opt) {
  unsigned takes = 0;
  for (const InputFormatRow& row : inputFormats())
    if (row.format == format && format != InputFormat::Unknown) takes |= row.options;
  // Every tensor format takes it; only the built-in scene has no stored axes.
  if (format == InputFormat::Unknown && !opt.tensorAxes.empty()) return "--tensor-axes";
  if (!(takes & kLayoutOption) && !opt.layout.empty()) return "--layout";
  if (!(takes & kFrameOption) && !opt.frame.empty()) return "--frame";
  if (!(takes & kArrayOption) && !opt.arrayName.empty()) return "--array";
  if (!(takes & kConfidenceOption) && opt.confidenceGiven) return "--confidence-min";
  return "";
}

}  // namespace tg::io
