#include "io/core/array_field.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "io/core/volume_sink.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(std::string_view arg, const std::string& what) {
  throw std::invalid_argument(std::string(arg) + ": " + what);
}

std::string shapeText(const ArrayRef& a) {
  std::string s = "(";
  for (std::size_t k = 0; k < a.shape.size(); ++k) s += (k ? ", " : "") + std::to_string(a.shape[k]);
  return s + (a.shape.size() == 1 ? ",)" : ")");
}

void checkView(std::string_view arg, const ArrayRef& a) {
  if (a.itemBytes != 4 && a.itemBytes != 8)
    throw std::domain_error(std::string(arg) + ": values must be float32 or float64");
  if (a.shape.size() != a.strides.size()) fail(arg, "shape and strides disagree");
  for (std::int64_t n : a.shape)
    if (n < 0) fail(arg, "negative extent in shape " + shapeText(a));
  if (!a.data && !a.shape.empty() && a.shape[0] > 0) fail(arg, "no data");
}

double valueAt(const ArrayRef& a, std::int64_t offsetBytes) {
  const char* p = static_cast<const char*>(a.data) + offsetBytes;
  if (a.itemBytes == 4) {
    float f;
    std::memcpy(&f, p, 4);
    return f;
  }
  double d;
  std::memcpy(&d, p, 8);
  return d;
}

// The values of the element at `base` along the axes from `firstInner` on
// (one or two), in row-major order; false if one is NaN/Inf.
bool readElement(const ArrayRef& a, std::int64_t base, std::size_t firstInner, double* out) {
  std::size_t n = 0;
  if (a.shape.size() - firstInner == 2) {
    for (std::int64_t r = 0; r < a.shape[firstInner]; ++r)
      for (std::int64_t c = 0; c < a.shape[firstInner + 1]; ++c)
        out[n++] = valueAt(a, base + r * a.strides[firstInner] + c * a.strides[firstInner + 1]);
  } else {
    for (std::int64_t c = 0; c < a.shape[firstInner]; ++c) out[n++] = valueAt(a, base + c * a.strides[firstInner]);
  }
  bool finite = true;
  for (std::size_t k = 0; k < n; ++k) finite &= std::isfinite(out[k]);
  return finite;
}

// Symmetric input only: (D + Dᵀ)/2 hides nothing below this relative asymmetry.
constexpr double kMaxAsymmetry = 1e-4;

bool symmetric(const double t[9]) {
  const double asym = std::abs(t[1] - t[3]) + std::abs(t[2] - t[6]) + std::abs(t[5] - t[7]);
  double norm = 0;
  for (int k = 0; k < 9; ++k) norm += std::abs(t[k]);
  return asym <= kMaxAsymmetry * norm;
}

const NiftiLayout& layoutNamed(std::string_view layout) {
  const NiftiLayout* l = niftiLayoutNamed(layout.empty() ? "fsl" : layout, kArrayInput);
  if (!l) fail("layout", "unknown order \"" + std::string(layout) + "\"; choose " + layoutChoices(kArrayInput));
  return *l;
}

// The order check a NIfTI file gets (adviseLayout), in Python's words: a
// DIPY user's fit.lower_triangular() is "nifti", not the default "fsl".
void adviseInto(TensorField& f, const LayoutSample& sample, const NiftiLayout& chosen, bool byDefault,
                const Plausibility& criteria, bool refuseUnexplained) {
  const LayoutAdvice a = adviseLayout(sample, chosen, byDefault, kArrayInput, criteria, pythonLayoutName,
                                      refuseUnexplained);
  if (!a.refusal.empty()) fail("layout", a.refusal);
  if (!a.warning.empty()) f.warnings.push_back(a.warning);
}

}  // namespace

TensorField fieldFromPoints(const ArrayRef& tensors, std::string_view layout, const ArrayRef& positions,
                            const Selection& selection) {
  checkView("tensors", tensors);
  checkView("positions", positions);
  const bool full = tensors.shape.size() == 3 && tensors.shape[1] == 3 && tensors.shape[2] == 3;
  const bool six = tensors.shape.size() == 2 && tensors.shape[1] == 6;
  if (!full && !six) fail("tensors", "shape " + shapeText(tensors) + " is neither (N, 3, 3) nor (N, 6)");
  const std::int64_t n = tensors.shape[0];
  if (positions.shape.size() != 2 || positions.shape[1] != 3 || positions.shape[0] != n)
    fail("positions", "shape " + shapeText(positions) + " is not (" + std::to_string(n) + ", 3)");
  if (std::uint64_t(n) > kMaxInputs) fail("tensors", "more than 2^32-256 tensors");
  if (full && !layout.empty()) fail("layout", "applies to (N, 6) tensors, not (N, 3, 3)");
  const NiftiLayout* l = six ? &layoutNamed(layout) : nullptr;
  TensorField f;
  f.path = "<array>";
  f.description = "points from arrays, " + std::to_string(n) + " tensors";
  f.layout = six ? std::string(l->name) + ": " + l->order : "3x3";
  f.frame = "world: the tensors are given in WC";
  const Selector sel(selection, f.path, nullptr);
  f.reserve(std::size_t(sel.keptBound(std::uint64_t(n))));
  LayoutSample sample{std::uint64_t(n)};
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (std::int64_t i = 0; i < n; ++i) {
    const auto where = [i] { return "index " + std::to_string(i); };
    double p[3], v[9], s6[6];
    if (!readElement(positions, i * positions.strides[0], 1, p)) fail("positions", "NaN or Inf at " + where());
    // addSym would count it as a tensor that overflows: it is the position.
    if (std::abs(p[0]) > FLT_MAX || std::abs(p[1]) > FLT_MAX || std::abs(p[2]) > FLT_MAX)
      fail("positions", "beyond single precision (3.4e38) at " + where());
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    // A tensor with a NaN/Inf component, or beyond single precision, is
    // skipped and counted by addSym, as the file readers skip it: the same
    // data as an array or a file draws alike.
    if (!sel.admit(std::uint64_t(i), p, f)) continue;
    const bool finite = readElement(tensors, i * tensors.strides[0], 1, v);
    if (full) {
      if (finite && !symmetric(v)) fail("tensors", "the 3x3 tensor at " + where() + " is not symmetric");
      symmetricPart(v, s6);
    } else {
      for (int k = 0; k < 6; ++k) s6[k] = v[l->sym[std::size_t(k)]];
      if (finite) sample.offer(std::uint64_t(i), v);
    }
    f.addSym(std::uint32_t(i), p, s6);
  }
  // Points have no convention of their own: the default (FSL's, a
  // diffusion order) must read them as diffusion tensors, or the one order
  // that does is named, or the caller is asked for theirs. Points in a
  // coordinate plane are also held to a 2-D field's zero out-of-plane shear.
  if (six)
    adviseInto(f, sample, *l, layout.empty(), Plausibility{layout.empty(), coordinatePlaneNormal(lo, hi)},
               layout.empty());
  // As the VTK reader estimates it for points: spacing-mode sizing (the
  // default) needs it, and the same points must draw as their file does.
  f.sampleSpacing = estimateSampleSpacing(f.positions);
  return f;
}

GridPlacement placementFromAffine(std::string_view arg, const double affine[16]) {
  for (int k = 0; k < 16; ++k)
    if (!std::isfinite(affine[k])) fail(arg, "non-finite value");
  // A transposed affine (translation in the last row) is the usual slip.
  if (affine[12] != 0 || affine[13] != 0 || affine[14] != 0 || affine[15] != 1)
    fail(arg, "the last row must be 0 0 0 1");
  GridPlacement p;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) p.axesWC[3 * r + c] = affine[4 * r + c];
    p.originWC[r] = affine[4 * r + 3];
  }
  const double det = determinant3(p.axesWC);
  // A scale near 1e300 is not singular: its determinant overflows.
  if (!std::isfinite(det)) fail(arg, "too large: its determinant overflows double precision");
  if (!(std::abs(det) > 0)) fail(arg, "singular");
  return p;
}

TensorField fieldFromVolume(const ArrayRef& tensors, std::string_view layout, const double affine[16],
                            std::string_view frame, const Selection& selection) {
  checkView("tensors", tensors);
  const std::size_t rank = tensors.shape.size();
  const bool full = rank == 5 && tensors.shape[3] == 3 && tensors.shape[4] == 3;
  const bool six = rank == 4 && tensors.shape[3] == 6;
  if (!full && !six) fail("tensors", "shape " + shapeText(tensors) + " is neither (X, Y, Z, 6) nor (X, Y, Z, 3, 3)");
  if (full && !layout.empty()) fail("layout", "applies to (X, Y, Z, 6) tensors, not (X, Y, Z, 3, 3)");
  std::uint64_t voxels = 1;
  VolumeGeometry g;
  for (int k = 0; k < 3; ++k) {
    if (tensors.shape[std::size_t(k)] < 1 || tensors.shape[std::size_t(k)] > INT32_MAX)
      fail("tensors", "shape " + shapeText(tensors) + " has an empty or too large axis");
    g.dims[k] = int(tensors.shape[std::size_t(k)]);
    voxels *= std::uint64_t(g.dims[k]);
  }
  if (voxels > kMaxInputs) fail("tensors", "more than 2^32-256 voxels");
  const GridPlacement fromAffine = placementFromAffine("affine", affine);
  std::copy(fromAffine.axesWC, fromAffine.axesWC + 9, g.axesWC);
  std::copy(fromAffine.originWC, fromAffine.originWC + 3, g.originWC);
  const NiftiLayout* l = six ? &layoutNamed(layout) : nullptr;
  std::optional<TensorFrame> named;
  if (!frame.empty()) {
    named = tensorFrameNamed(frame);
    if (!named) fail("frame", "unknown frame \"" + std::string(frame) + "\"; choose " + kTensorFrameChoices);
  } else if (l) {
    named = l->frame;
  } else {
    // (X, Y, Z, 3, 3) is how DIPY hands tensors over (fit.quadratic_form),
    // in the array's own axes i, j, k, which the affine takes to the world.
    named = TensorFrame::Voxel;
  }
  const FrameMap map = tensorFrameMap(*named, g.axesWC, true);
  g.tensorToWC = map.tensorToWC;
  TensorField f;
  f.path = "<array>";
  f.description = "volume from arrays, " + std::to_string(g.dims[0]) + "x" + std::to_string(g.dims[1]) + "x" +
                  std::to_string(g.dims[2]);
  f.layout = six ? std::string(l->name) + ": " + l->order : "3x3";
  // A voxel-to-world affine as nibabel and DIPY hand it: NIfTI's, RAS+.
  f.space = "RAS (the affine's, as NIfTI's)";
  f.tensorToWC = map.tensorToWC;
  f.otherFrames = otherFrames(*named, g.axesWC, true);
  f.frame = std::string(tensorFrameName(*named)) + ": " + map.description;
  ComponentLayout cl;
  cl.count = six ? 6 : 9;
  cl.full = full;
  if (six) cl.sym = l->sym;
  const GridPlacement placed = placementOf(g);
  const Selector sel(selection, f.path, g.dims, &placed);
  VolumeSink sink(f, g, cl, sel, 0.0);
  LayoutSample sample{voxels};
  std::uint64_t index = 0;
  double v[9];
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const std::int64_t base = i * tensors.strides[0] + j * tensors.strides[1] + k * tensors.strides[2];
        const auto where = [&] {
          return "voxel (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + ")";
        };
        const bool finite = readElement(tensors, base, 3, v);  // else skipped and counted, as by the readers
        if (finite && full && !symmetric(v)) fail("tensors", "the 3x3 tensor at " + where() + " is not symmetric");
        if (six && finite) sample.offer(index, v);
        ++index;
        sink.push(v);
      }
  sink.finish();
  // A volume's six values are a NIfTI file's: diffusion tensors, checked
  // as readNifti checks them.
  if (six) adviseInto(f, sample, *l, layout.empty(), Plausibility{true, -1}, false);
  return f;
}

std::string inapplicableArrayOption(const ReadOptions& opt) {
  if (!opt.arrayName.empty()) return "--array";
  if (opt.confidenceGiven) return "--confidence-min";
  return "";
}

}  // namespace tg::io
