#include "io/core/nifti_layouts.h"

#include <algorithm>
#include <cmath>

#include "io/core/readers.h"
#include "io/core/volume_sink.h"

namespace tg::io {

const std::vector<NiftiLayout>& niftiLayouts() {
  // The writers of each order are in docs/formats.md, "Reading data". VTK's order is
  // vtkMath::TensorFromSymmetricTensor's (vtkMath.h: "XX, YY, ZZ, XY, YZ,
  // XZ"), which vtkTensorGlyph and ParaView's Tensor Glyph read 6-component
  // arrays with. Abaqus writes S11 S22 S33 S12 S13 S23 (its manual,
  // "Conventions"); Voigt's notation is 11 22 33 23 13 12.
  constexpr unsigned all = kNiftiInput | kVtkInput | kArrayInput, notVtk = kNiftiInput | kArrayInput,
                     fem = kVtkInput | kArrayInput;
  static const std::vector<NiftiLayout> layouts = {
      {"fsl", {0, 1, 2, 3, 4, 5}, TensorFrame::Fsl, "xx xy xz yy yz zz", notVtk},
      {"nifti", {0, 1, 3, 2, 4, 5}, TensorFrame::Voxel, "xx xy yy xz yz zz", notVtk},
      {"mrtrix", {0, 3, 4, 1, 5, 2}, TensorFrame::World, "xx yy zz xy xz yz", notVtk},
      {"vtk", {0, 3, 5, 1, 4, 2}, TensorFrame::Voxel, "xx yy zz xy yz xz", all},
      {"paraview", {0, 3, 5, 1, 4, 2}, TensorFrame::Voxel, "xx yy zz xy yz xz", all},
      {"abaqus", {0, 3, 4, 1, 5, 2}, TensorFrame::World, "S11 S22 S33 S12 S13 S23: xx yy zz xy xz yz", fem},
      {"voigt", {0, 5, 4, 1, 3, 2}, TensorFrame::World, "xx yy zz yz xz xy", fem},
  };
  return layouts;
}

const NiftiLayout* niftiLayoutNamed(std::string_view name, unsigned input) {
  for (const NiftiLayout& l : niftiLayouts())
    if (name == l.name) return (l.inputs & input) ? &l : nullptr;
  return nullptr;
}

std::string layoutChoices(unsigned input) {
  std::vector<std::string> names;
  for (const NiftiLayout& l : niftiLayouts())
    if (l.inputs & input) names.push_back(l.name);
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return s;
}

bool isLayoutName(const std::string& name) { return niftiLayoutNamed(name) != nullptr; }

std::string unusableLayout(std::string_view name, unsigned input, const char* inputName) {
  const std::string n(name);
  return (niftiLayoutNamed(name) ? "--layout " + n + " does not apply to " + inputName : "unknown layout \"" + n + "\"") +
         "; choose " + layoutChoices(input);
}

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

// The six values of a reading, xx xy xz yy yz zz, of stored `row`.
std::array<double, 6> readingOf(const double* row, const NiftiLayout& l) {
  std::array<double, 6> s{};
  for (int k = 0; k < 6; ++k) s[std::size_t(k)] = row[l.sym[std::size_t(k)]];
  return s;
}

// The out-of-plane shears of a tensor xx xy xz yy yz zz for plane normal a:
// x: xy xz; y: xy yz; z: xz yz.
constexpr int kShears[3][2] = {{1, 2}, {1, 4}, {2, 4}};
constexpr const char* kShearNames[3] = {"xy or xz", "xy or yz", "xz or yz"};
constexpr const char* kAxisNames = "xyz";

struct Count {
  std::size_t sampled = 0, failing = 0;
};

Count indefinite(const std::vector<double>& rows, const NiftiLayout& l) {
  Count c;
  for (std::size_t r = 0; r + 6 <= rows.size(); r += 6) {
    const std::array<double, 6> s = readingOf(&rows[r], l);
    ++c.sampled;
    c.failing += !positiveSemiDefinite(s.data());
  }
  return c;
}

Count outOfPlane(const std::vector<double>& rows, const NiftiLayout& l, int normal) {
  double scale = 0;
  for (double v : rows) scale = std::max(scale, std::abs(v));
  Count c;
  for (std::size_t r = 0; r + 6 <= rows.size(); r += 6) {
    const std::array<double, 6> s = readingOf(&rows[r], l);
    ++c.sampled;
    const double shear = std::max(std::abs(s[std::size_t(kShears[normal][0])]), std::abs(s[std::size_t(kShears[normal][1])]));
    c.failing += shear > 1e-3 * scale;
  }
  return c;
}

// Why the reading in `l` is implausible (fails a criterion clearly: more than
// half indefinite, more than a tenth with out-of-plane shear), or "".
std::string failure(const std::vector<double>& rows, const NiftiLayout& l, const Plausibility& p) {
  const auto as = [&] { return std::string(" as ") + l.name + " (" + l.order + ")"; };
  if (p.diffusion) {
    const Count c = indefinite(rows, l);
    if (2 * c.failing > c.sampled)
      return std::to_string(c.failing) + " of " + std::to_string(c.sampled) +
             " sampled tensors are indefinite (FA > 1 or negative eigenvalues)" + as() + ", which no diffusion tensor is";
  }
  if (p.planeNormal >= 0) {
    const Count c = outOfPlane(rows, l, p.planeNormal);
    if (10 * c.failing > c.sampled)
      return std::to_string(c.failing) + " of " + std::to_string(c.sampled) + " sampled tensors have out-of-plane shear (" +
             kShearNames[p.planeNormal] + ")" + as() + ", though the points lie in a plane of constant " +
             kAxisNames[p.planeNormal] + ", where a plate's or a 2-D model's is zero";
  }
  return "";
}

// Whether the reading in `l` is plausible: at most a fifth indefinite, at
// most 1% with out-of-plane shear. Between the two bounds a reading is
// neither offered nor refused.
bool plausible(const std::vector<double>& rows, const NiftiLayout& l, const Plausibility& p) {
  if (p.diffusion) {
    const Count c = indefinite(rows, l);
    if (5 * c.failing > c.sampled) return false;
  }
  if (p.planeNormal >= 0) {
    const Count c = outOfPlane(rows, l, p.planeNormal);
    if (100 * c.failing > c.sampled) return false;
  }
  return true;
}

}  // namespace

int coordinatePlaneNormal(const double lo[3], const double hi[3]) {
  double big = 0;
  for (int k = 0; k < 3; ++k) big = std::max(big, hi[k] - lo[k]);
  if (!(big > 0) || !std::isfinite(big)) return -1;
  int flat = -1, flats = 0;
  for (int k = 0; k < 3; ++k)
    if (hi[k] - lo[k] <= 1e-6 * big) flat = k, ++flats;
  return flats == 1 ? flat : -1;
}

LayoutSample::LayoutSample(std::uint64_t count) : step_(std::max<std::uint64_t>(1, count / 16384)) {}

void LayoutSample::offer(std::uint64_t index, const double v[6]) {
  if (index % step_ != 0 || std::all_of(v, v + 6, [](double c) { return c == 0.0; }) ||
      !std::all_of(v, v + 6, [](double c) { return std::isfinite(c); }))
    return;
  rows_.insert(rows_.end(), v, v + 6);
}

LayoutSample LayoutSample::ofComponents(const std::vector<float>& values, std::size_t voxels) {
  LayoutSample s{voxels};
  double v[6];
  for (std::size_t i = 0; i < voxels; i += std::size_t(s.step_)) {
    for (std::size_t c = 0; c < 6; ++c) v[c] = values[c * voxels + i];
    s.offer(i, v);
  }
  return s;
}

std::string cliLayoutName(const NiftiLayout& l) { return std::string("--layout ") + l.name; }
std::string cliNiftiLayoutName(const NiftiLayout& l) {
  return cliLayoutName(l) + " --frame " + tensorFrameName(l.frame);
}
std::string pythonLayoutName(const NiftiLayout& l) { return std::string("layout=\"") + l.name + "\""; }

LayoutAdvice adviseLayout(const LayoutSample& sample, const NiftiLayout& chosen, bool byDefault, unsigned input,
                          const Plausibility& criteria, LayoutNamer name, bool refuseUnexplained) {
  const std::vector<double>& rows = sample.rows();
  LayoutAdvice a;
  const std::string problem = rows.empty() ? "" : failure(rows, chosen, criteria);
  if (problem.empty()) return a;
  // The other readings that pass, grouped by the tensors they give here
  // (abaqus and voigt agree where xy and yz are both zero).
  std::vector<std::vector<const NiftiLayout*>> groups;
  const auto same = [&](const NiftiLayout& x, const NiftiLayout& y) {
    for (std::size_t r = 0; r + 6 <= rows.size(); r += 6)
      if (readingOf(&rows[r], x) != readingOf(&rows[r], y)) return false;
    return true;
  };
  for (const NiftiLayout& l : niftiLayouts()) {
    if (!(l.inputs & input) || same(l, chosen) || !plausible(rows, l, criteria)) continue;
    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& grp) { return same(*grp[0], l); });
    if (g == groups.end()) groups.push_back({&l});
    else g->push_back(&l);
  }
  // Judged as stress (no diffusion criterion), a group is named by its FEM
  // orders first: a plate's S is abaqus's, whatever else reads it alike.
  if (!criteria.diffusion)
    for (auto& g : groups)
      std::stable_partition(g.begin(), g.end(), [](const NiftiLayout* l) { return !(l->inputs & kNiftiInput); });
  const auto groupText = [&](const std::vector<const NiftiLayout*>& g) {
    std::string s = name(*g[0]);
    for (std::size_t k = 1; k < g.size(); ++k) s += std::string(k == 1 ? " (or " : ", ") + g[k]->name;
    return s + (g.size() > 1 ? ": the same tensors here)" : "");
  };
  if (byDefault && groups.size() == 1) {
    a.refusal = problem + "; only " + groupText(groups[0]) + " reads them plausibly: give it (or " + name(chosen) +
                " to draw this reading)";
  } else if (byDefault && groups.empty() && refuseUnexplained) {
    a.refusal = problem + "; no order reads them plausibly: name theirs (" + layoutChoices(input) + ")";
  } else {
    std::string better;
    for (const auto& g : groups) better += (better.empty() ? "" : " or ") + groupText(g);
    a.warning = problem + (better.empty() ? "; no other layout reads them plausibly" : "; try " + better);
  }
  return a;
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

std::vector<FrameChoice> otherFrames(TensorFrame applied, const double axesWC[9], bool fromAffine) {
  const auto mapOf = [&](TensorFrame f) { return tensorFrameMap(f, axesWC, fromAffine).tensorToWC; };
  const auto own = mapOf(applied);
  std::vector<FrameChoice> out;
  for (TensorFrame f : {TensorFrame::Voxel, TensorFrame::Fsl, TensorFrame::World})
    if (auto m = mapOf(f); m != own) out.push_back({tensorFrameName(f), m});
  return out;
}

}  // namespace tg::io
