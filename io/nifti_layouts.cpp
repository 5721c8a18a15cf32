#include "io/nifti_layouts.h"

#include <algorithm>
#include <cmath>

#include "io/readers.h"
#include "io/volume_sink.h"

namespace tg::io {

const std::vector<NiftiLayout>& niftiLayouts() {
  // The writers of each order are in README, "Reading data".
  static const std::vector<NiftiLayout> layouts = {
      {"fsl", {0, 1, 2, 3, 4, 5}, TensorFrame::Fsl, "xx xy xz yy yz zz"},
      {"nifti", {0, 1, 3, 2, 4, 5}, TensorFrame::Voxel, "xx xy yy xz yz zz"},
      {"mrtrix", {0, 3, 4, 1, 5, 2}, TensorFrame::World, "xx yy zz xy xz yz"},
      {"vtk", {0, 3, 5, 1, 4, 2}, TensorFrame::Voxel, "xx yy zz xy yz xz"},
  };
  return layouts;
}

const NiftiLayout* niftiLayoutNamed(std::string_view name) {
  for (const NiftiLayout& l : niftiLayouts())
    if (name == l.name) return &l;
  return nullptr;
}

bool isNiftiLayout(const std::string& name) { return niftiLayoutNamed(name) != nullptr; }

std::optional<TensorFrame> tensorFrameNamed(std::string_view name) {
  if (name == "voxel") return TensorFrame::Voxel;
  if (name == "fsl") return TensorFrame::Fsl;
  if (name == "world") return TensorFrame::World;
  return std::nullopt;
}

const char* tensorFrameName(TensorFrame f) {
  switch (f) {
    case TensorFrame::Voxel: return "voxel";
    case TensorFrame::Fsl: return "fsl";
    case TensorFrame::World: return "world";
  }
  return "?";
}

namespace {

// Sylvester's criterion for semi-definiteness (every principal minor >= 0),
// with a tolerance relative to the tensor's size so that rounding in a
// near-singular fit does not count.
bool positiveSemiDefinite(const double s[6]) {  // xx xy xz yy yz zz
  const double a = s[0], d = s[1], e = s[2], b = s[3], f = s[4], c = s[5];
  double m = 0;
  for (int k = 0; k < 6; ++k) m = std::max(m, std::abs(s[k]));
  const double tol = 1e-2 * m;
  if (a < -tol || b < -tol || c < -tol) return false;
  const double tol2 = tol * m;
  if (a * b - d * d < -tol2 || a * c - e * e < -tol2 || b * c - f * f < -tol2) return false;
  return a * (b * c - f * f) - d * (d * c - f * e) + e * (d * f - b * e) >= -tol2 * m;
}

}  // namespace

Definiteness definiteness(const std::vector<float>& values, std::size_t voxels, const std::array<int, 6>& sym,
                          std::size_t maxSamples) {
  Definiteness d;
  const std::size_t step = std::max<std::size_t>(1, voxels / std::max<std::size_t>(maxSamples, 1));
  for (std::size_t v = 0; v < voxels && d.sampled < maxSamples; v += step) {
    float x[6];  // component-major, as the reader keeps them
    for (std::size_t c = 0; c < 6; ++c) x[c] = values[c * voxels + v];
    if (std::all_of(x, x + 6, [](float c) { return c == 0.0f; }) ||
        !std::all_of(x, x + 6, [](float c) { return std::isfinite(c); }))
      continue;  // background and skipped voxels say nothing about the order
    double s[6];
    for (int k = 0; k < 6; ++k) s[k] = x[sym[std::size_t(k)]];
    ++d.sampled;
    d.indefinite += !positiveSemiDefinite(s);
  }
  return d;
}

std::string implausibleLayoutWarning(const std::vector<float>& values, std::size_t voxels, const NiftiLayout& chosen,
                                     bool onlyIfAnotherFits) {
  const Definiteness mine = definiteness(values, voxels, chosen.sym);
  if (mine.sampled == 0 || 2 * mine.indefinite <= mine.sampled) return "";
  std::string msg = std::to_string(mine.indefinite) + " of " + std::to_string(mine.sampled) +
                    " sampled tensors are indefinite (FA > 1 or negative eigenvalues) as --layout " + chosen.name +
                    " (" + chosen.order + "), which no diffusion tensor is";
  std::string better;
  for (const NiftiLayout& l : niftiLayouts()) {
    if (&l == &chosen || l.sym == chosen.sym) continue;
    const Definiteness other = definiteness(values, voxels, l.sym);
    // Clearly better: a minority indefinite, and at most half as many.
    if (2 * other.indefinite < other.sampled && 2 * other.indefinite <= mine.indefinite)
      better += std::string(better.empty() ? "" : " or ") + "--layout " + l.name + " --frame " +
                tensorFrameName(l.frame) + " (" + std::to_string(other.indefinite) + " indefinite)";
  }
  if (better.empty() && onlyIfAnotherFits) return "";
  return msg + (better.empty() ? "; no other layout reads them as diffusion tensors" : "; try " + better);
}

FrameMap tensorFrameMap(TensorFrame frame, const double axesWC[9], bool fromAffine) {
  FrameMap m;
  if (frame == TensorFrame::World) {
    m.description = "the affine's world axes, not rotated";
    return m;
  }
  std::array<double, 9> t = orthogonalPart(axesWC);
  // FSL's voxel frame is radiological: x runs opposite to i when the
  // sform (else qform) keeps handedness (det > 0). Without either FSL
  // takes the image as radiological already (newimage's left_right_order).
  const bool mirror = frame == TensorFrame::Fsl && determinant3(axesWC) > 0 && fromAffine;
  if (mirror)
    for (int r = 0; r < 3; ++r) t[std::size_t(3 * r)] = -t[std::size_t(3 * r)];
  m.tensorToWC = t;
  m.description = frame == TensorFrame::Voxel ? "the voxel axes"
                  : mirror                    ? "FSL's voxel axes, i reversed as the affine's det > 0"
                  : fromAffine                ? "FSL's voxel axes, the voxel axes as the affine's det < 0"
                                              : "FSL's voxel axes, the voxel axes as there is no sform or qform";
  m.description += ", rotated by the affine's orthogonal part";
  return m;
}

}  // namespace tg::io
