// Which reading options each format uses; the rest are refused, not ignored.
#include <algorithm>

#include "io/readers.h"

namespace tg::io {

InputFormat inputFormatOf(const std::string& path) {
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const auto dot = lower.find_last_of('.');
  const std::string ext = dot == std::string::npos ? "" : lower.substr(dot + 1);
  if (ext == "vtk" || ext == "vti" || ext == "vtu" || ext == "vtp" || ext == "vts") return InputFormat::Vtk;
  if (ext == "nrrd" || ext == "nhdr") return InputFormat::Nrrd;
  if (ext == "nii" || lower.ends_with(".nii.gz")) return InputFormat::Nifti;
  if (ext == "mif" || ext == "mih") return InputFormat::Mif;
  return InputFormat::Unknown;
}

const char* inputFormatName(InputFormat f) {
  switch (f) {
    case InputFormat::Vtk: return "VTK";
    case InputFormat::Nrrd: return "NRRD";
    case InputFormat::Nifti: return "NIfTI";
    case InputFormat::Mif: return "MRtrix";
    case InputFormat::Unknown: break;
  }
  return "unknown";
}

std::string inapplicableOption(InputFormat format, const ReadOptions& opt) {
  // NRRD and MRtrix state their own component order and frame (kind and
  // measurement frame; MRtrix's in scanner space); NIfTI leaves both to
  // convention, and a 6-component VTK array its order (VTK's own by default,
  // but FEM codes write theirs), in world axes. Only VTK has named arrays;
  // only NRRD has confidence.
  if (format != InputFormat::Nifti && format != InputFormat::Vtk && !opt.layout.empty()) return "--layout";
  if (format != InputFormat::Nifti && !opt.frame.empty()) return "--frame";
  if (format != InputFormat::Vtk && !opt.arrayName.empty()) return "--array";
  if (format != InputFormat::Nrrd && opt.confidenceGiven) return "--confidence-min";
  return "";
}

}  // namespace tg::io
