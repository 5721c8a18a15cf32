#include "io/core/selection.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/core/format_table.h"
#include "io/core/read_guard.h"
#include "io/core/readers.h"

namespace tg::io {

namespace {

constexpr const char* kPlaneNames[3] = {"sagittal", "coronal", "axial"};  // across x (R), y (A), z (S)

}  // namespace

SliceSpec parseSlice(const std::string& text) {
  SliceSpec s;
  const auto sep = text.find_first_of(":=");
  if (sep == std::string::npos)
    throw std::invalid_argument("expected axis:index[:thickness] or axis=position[mm][:thickness], got \"" + text +
                                "\"");
  const bool world = text[sep] == '=';
  const std::string axis = text.substr(0, sep);
  int named = -1;
  for (int a = 0; a < 3; ++a)
    if (axis == kPlaneNames[a]) named = a;
  if (named >= 0) s.worldAxis = named;
  else if (axis == "x" || axis == "i" || axis == "0") s.axis = 0;
  else if (axis == "y" || axis == "j" || axis == "1") s.axis = 1;
  else if (axis == "z" || axis == "k" || axis == "2") s.axis = 2;
  else throw std::invalid_argument("unknown axis \"" + axis + "\"; choose i, j, k (x, y, z, 0, 1, 2: voxel axes) or axial, coronal, sagittal");
  if (world && named < 0) {
    if (axis != "x" && axis != "y" && axis != "z")
      throw std::invalid_argument("a world position takes x, y, z or axial, coronal, sagittal, not \"" + axis + "\"");
    s.worldAxis = s.axis;
  }
  const auto c2 = text.find(':', sep + 1);
  auto part = [&](std::size_t b, std::size_t e) {
    return std::string_view(text).substr(b, std::min(e, text.size()) - b);
  };
  auto integer = [&](std::string_view t, const char* what) {
    long long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || t.empty())
      throw std::invalid_argument(std::string(what) + " \"" + std::string(t) + "\" is not an integer");
    return v;
  };
  if (world) {
    std::string_view t = part(sep + 1, c2);
    if (t.size() > 2 && t.substr(t.size() - 2) == "mm") t.remove_suffix(2);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || t.empty() || !std::isfinite(v))
      throw std::invalid_argument("position \"" + std::string(part(sep + 1, c2)) + "\" is not a number (world units; \"mm\" optional)");
    s.positionWC = v;
  } else {
    s.index = integer(part(sep + 1, c2), "index");
    if (s.index < 0) throw std::invalid_argument("index must not be negative");
  }
  if (c2 != std::string::npos) s.thickness = integer(part(c2 + 1, text.size()), "thickness");
  if (s.thickness < 1) throw std::invalid_argument("thickness must be at least 1");
  return s;
}

std::string SliceSpec::text() const {
  std::string t;
  if (positionWC) {
    char b[48];
    std::snprintf(b, sizeof b, "%.9g", *positionWC);
    t = std::string(1, "xyz"[worldAxis]) + "=" + b;
  } else {
    // Appended, not `":" + std::to_string(...)`: GCC 12 warns falsely (-Wrestrict).
    t = worldAxis >= 0 ? std::string(kPlaneNames[worldAxis]) : std::string(1, "xyz"[axis]);
    t.append(":").append(std::to_string(index));
  }
  if (thickness > 1) t.append(":").append(std::to_string(thickness));
  return t;
}

SliceSpec resolveSlice(const SliceSpec& s, const GridPlacement& p, const int dims[3]) {
  if (s.worldAxis < 0) return s;
  SliceSpec out = s;
  const int w = s.worldAxis;
  double best = -1;
  for (int k = 0; k < 3; ++k) {
    const double len = std::hypot(p.axesWC[k], p.axesWC[3 + k], p.axesWC[6 + k]);
    const double along = len > 0 ? std::abs(p.axesWC[3 * w + k]) / len : 0;
    if (along > best) best = along, out.axis = k;
  }
  if (!s.positionWC) return out;
  // Along the voxel axis through the grid's centre: where world coordinate
  // w reaches the position. Clamped far outside any grid before rounding.
  const int a = out.axis;
  double at = p.originWC[w];
  for (int k = 0; k < 3; ++k) at += p.axesWC[3 * w + k] * 0.5 * (dims[k] - 1);
  const double step = p.axesWC[3 * w + a];
  const double t = 0.5 * (dims[a] - 1) + (*s.positionWC - at) / step;
  out.index = std::isfinite(t) ? std::llround(std::clamp(t, -1e15, 1e15)) : -1;
  return out;
}

std::string gridText(const int d[3]) {
  return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

std::string maskGridMismatch(const int got[3], const int* want) {
  if (!want) {
    // An underlay, on a grid of its own: its values, the wire's copy and the
    // caller's must fit in this load's memory.
    const long double bytes = (long double)got[0] * got[1] * got[2] * sizeof(float) * 3;
    const std::uint64_t budget = defaultMemoryBudget();
    if (bytes > (long double)budget)
      return "grid " + gridText(got) + " would need " + std::to_string(std::uint64_t(bytes / (1 << 20))) +
             " MiB, more than the " + std::to_string(budget >> 20) + " MiB this load may use";
    return "";
  }
  // Reordered axes are the same grid, if the placements say so (Selector).
  if (std::is_permutation(got, got + 3, want)) return "";
  return "mask grid " + gridText(got) + " differs from the tensor grid " + gridText(want);
}

ScalarVolume readScalarVolume(const std::string& path, const int* dims) {
  checkInputFile("readScalarVolume", path);
  const InputFormatRow* row = inputFormatRowOf(path);
  if (!row || !row->readScalars)
    throw InputError("readScalarVolume: " + path + ": unknown mask format; use " + extensionList(kScalarUse, ", ", " or "));
  return row->readScalars(path, dims);
}

namespace {

// A mask is applied voxel by voxel, so it must lie where the tensors do:
// the same dims on another placement (another origin, spacing or axis order)
// would mask the wrong voxels. Tolerance: 1e-3 of the grid's longest step.
double placementTolerance(const GridPlacement& tensors) {
  double step = 0;
  for (double a : tensors.axesWC) step = std::max(step, std::abs(a));
  return 1e-3 * std::max(step, 1e-30);
}

// The mask's values in the tensors' voxel order when its grid holds the same
// points with its axes reversed or reordered (mrconvert stores the mask of a
// LAS NIfTI with i reversed, near RAS); nullopt when it does not.
std::optional<std::vector<float>> alignedMask(const GridPlacement& t, const int dims[3], const ScalarVolume& m) {
  const GridPlacement& p = *m.placement;
  const double tol = placementTolerance(t);
  int axis[3], sign[3];
  bool used[3] = {false, false, false};
  for (int k = 0; k < 3; ++k) {
    bool found = false;
    for (int j = 0; j < 3 && !found; ++j)
      for (int s = 1; s >= -1 && !found; s -= 2) {
        if (used[j]) continue;
        bool same = true;
        for (int r = 0; r < 3; ++r) same = same && std::abs(t.axesWC[3 * r + k] - s * p.axesWC[3 * r + j]) <= tol;
        if (same) {
          axis[k] = j, sign[k] = s, used[j] = found = true;
        }
      }
    if (!found || m.dims[axis[k]] != dims[k]) return std::nullopt;
  }
  // The tensors' first voxel in the mask's index space: along each tensor
  // axis k, (t.origin - p.origin) . a_k / |a_k|^2 steps of the mask's axis.
  long long first[3];
  double rest[3];
  for (int r = 0; r < 3; ++r) rest[r] = t.originWC[r] - p.originWC[r];
  for (int k = 0; k < 3; ++k) {
    double dot = 0, norm = 0;
    for (int r = 0; r < 3; ++r) {
      dot += rest[r] * t.axesWC[3 * r + k];
      norm += t.axesWC[3 * r + k] * t.axesWC[3 * r + k];
    }
    const double steps = sign[k] * dot / norm;
    first[axis[k]] = std::llround(steps);
    if (!(std::abs(steps - double(first[axis[k]])) * std::sqrt(norm) <= tol)) return std::nullopt;
  }
  // What the axes leave of the offset must be nothing; and every voxel inside.
  for (int r = 0; r < 3; ++r) {
    double off = rest[r];
    for (int k = 0; k < 3; ++k) off -= double(sign[k] * first[axis[k]]) * t.axesWC[3 * r + k];
    if (!(std::abs(off) <= tol)) return std::nullopt;
  }
  for (int k = 0; k < 3; ++k) {
    const long long last = first[axis[k]] + sign[k] * (dims[k] - 1);
    if (std::min(first[axis[k]], last) < 0 || std::max(first[axis[k]], last) >= m.dims[axis[k]]) return std::nullopt;
  }
  const std::size_t voxels = std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]);
  std::vector<float> out(voxels);
  std::size_t v = 0;
  long long at[3];
  for (int i2 = 0; i2 < dims[2]; ++i2)
    for (int i1 = 0; i1 < dims[1]; ++i1)
      for (int i0 = 0; i0 < dims[0]; ++i0, ++v) {
        const int i[3] = {i0, i1, i2};
        for (int k = 0; k < 3; ++k) at[axis[k]] = first[axis[k]] + sign[k] * i[k];
        out[v] = m.values[std::size_t(at[0] + m.dims[0] * (at[1] + (long long)m.dims[1] * at[2]))];
      }
  return out;
}

void checkSamePlacement(const GridPlacement& tensors, const GridPlacement& mask, const std::string& maskPath,
                        const std::string& path) {
  const double tol = placementTolerance(tensors);
  double worst = 0;
  for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(tensors.originWC[k] - mask.originWC[k]));
  for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(tensors.axesWC[k] - mask.axesWC[k]));
  if (!(worst <= tol)) {
    std::ostringstream m;
    m << "Selector: " << maskPath << ": mask lies elsewhere than the tensors of " << path << " (origin "
      << mask.originWC[0] << " " << mask.originWC[1] << " " << mask.originWC[2] << " against " << tensors.originWC[0]
      << " " << tensors.originWC[1] << " " << tensors.originWC[2] << ", or other axes; differs by up to " << worst
      << ")";
    throw InputError(m.str());
  }
}

}  // namespace

Selector::Selector(const Selection& sel, const std::string& path, const int* dims, const GridPlacement* placement)
    : sel_(sel) {
  if (sel.stride < 1) throw InputError("Selector: " + path + ": stride must be at least 1");
  all_ = !sel.slice && sel.stride == 1 && !sel.roiWC && sel.maskPath.empty();
  if (!dims) {
    if (sel.slice) throw InputError("Selector: " + path + ": --slice needs a grid; this file is a point set");
    if (!sel.maskPath.empty()) throw InputError("Selector: " + path + ": --mask needs a grid; this file is a point set");
    return;
  }
  grid_ = true;
  std::copy(dims, dims + 3, dims_);
  if (sel.slice) {
    // Anatomical and world slices in voxel terms, on this grid's placement
    // (the voxel axes themselves when it has none).
    sel_.slice = resolveSlice(*sel.slice, placement ? *placement : GridPlacement{}, dims_);
    const SliceSpec& s = *sel_.slice;
    if (s.index < 0 || s.index >= dims_[s.axis])
      throw SliceOutOfRange("Selector: " + path + ": slice " + sel.slice->text() + " (index " + std::to_string(s.index) +
                                " along voxel axis " + "ijk"[s.axis] + ") is outside the grid's 0.." +
                                std::to_string(dims_[s.axis] - 1),
                            s, dims_[s.axis]);
    slabLo_ = s.index - (s.thickness - 1) / 2;
    slabHi_ = s.index + s.thickness / 2;
  }
  if (!sel.maskPath.empty()) {
    mask_ = sel.maskVolume ? *sel.maskVolume : readScalarVolume(sel.maskPath, dims_);
    const std::size_t voxels = std::size_t(dims_[0]) * std::size_t(dims_[1]) * std::size_t(dims_[2]);
    if (mask_.values.size() != voxels || !std::is_permutation(dims_, dims_ + 3, mask_.dims))
      throw InputError("Selector: " + sel.maskPath + ": mask grid " + gridText(mask_.dims) +
                       " differs from the tensor grid " + gridText(dims_) + " of " + path);
    // Masks are applied by voxel index: the same grid stored in another
    // axis order is first put in the tensors' order, by where its voxels lie.
    std::optional<std::vector<float>> aligned;
    if (placement && mask_.placement) aligned = alignedMask(*placement, dims_, mask_);
    if (aligned) {
      mask_.values = std::move(*aligned);
      std::copy(dims_, dims_ + 3, mask_.dims);
    } else if (!std::equal(dims_, dims_ + 3, mask_.dims)) {
      throw InputError("Selector: " + sel.maskPath + ": mask grid " + gridText(mask_.dims) +
                       " differs from the tensor grid " + gridText(dims_) + " of " + path);
    } else if (placement && mask_.placement) {
      checkSamePlacement(*placement, *mask_.placement, sel.maskPath, path);
    }
  }
}

std::uint64_t Selector::keptBound(std::uint64_t n) const {
  const std::uint64_t stride = std::uint64_t(sel_.stride);
  if (!grid_) return (n + stride - 1) / stride;
  std::uint64_t kept = 1;
  for (int k = 0; k < 3; ++k) {
    std::uint64_t along = (std::uint64_t(dims_[k]) + stride - 1) / stride;
    if (sel_.slice && sel_.slice->axis == k) along = std::min(std::uint64_t(dims_[k]), std::uint64_t(slabHi_ - slabLo_ + 1));
    kept *= along;
  }
  return std::min(kept, n);
}

double Selector::keptSpacing(const double spacing[3]) const {
  double s = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const bool slab = sel_.slice && sel_.slice->axis == k;
    const long long from = slab ? std::max(0LL, slabLo_) : 0;
    const long long to = slab ? std::min<long long>(dims_[k] - 1, slabHi_) : dims_[k] - 1;
    const long long step = slab ? 1 : sel_.stride;
    if (to - from >= step && spacing[k] > 0) s = std::min(s, spacing[k] * double(step));
  }
  return s;
}

Selector::Verdict Selector::judge(std::uint64_t index, const double p[3]) const {
  if (grid_) {
    const std::uint64_t nx = std::uint64_t(dims_[0]), ny = std::uint64_t(dims_[1]);
    const long long ijk[3] = {(long long)(index % nx), (long long)(index / nx % ny), (long long)(index / (nx * ny))};
    if (sel_.slice && (ijk[sel_.slice->axis] < slabLo_ || ijk[sel_.slice->axis] > slabHi_)) return Verdict::Unselected;
    // The stride thins within a slice: its own axis keeps the whole slab.
    const int spared = sel_.slice ? sel_.slice->axis : -1;
    if (sel_.stride > 1)
      for (int k = 0; k < 3; ++k)
        if (k != spared && ijk[k] % sel_.stride) return Verdict::Unselected;
  } else if (sel_.stride > 1 && index % std::uint64_t(sel_.stride)) {
    return Verdict::Unselected;
  }
  if (sel_.roiWC) {
    const auto& b = *sel_.roiWC;
    for (int k = 0; k < 3; ++k)
      if (!(p[k] >= std::min(b[k], b[k + 3]) && p[k] <= std::max(b[k], b[k + 3]))) return Verdict::Unselected;
  }
  if (!mask_.values.empty() && !(mask_.values[index] >= sel_.maskMin)) return Verdict::Masked;
  return Verdict::Keep;
}

bool Selector::admitJudged(std::uint64_t index, const double p[3], TensorField& f) const {
  const Verdict verdict = judge(index, p);
  if (verdict == Verdict::Keep) return true;
  ++f.totalPoints;
  ++(verdict == Verdict::Masked ? f.masked : f.unselected);
  return false;
}

void applySelection(TensorField& f, const Selection& sel) {
  std::optional<GridPlacement> placed;
  if (f.grid) {
    placed.emplace();
    for (int r = 0; r < 3; ++r) {
      placed->originWC[r] = f.grid->origin[r];
      for (int c = 0; c < 3; ++c) placed->axesWC[3 * r + c] = f.grid->directions[3 * r + c] * f.grid->spacing[c];
    }
  }
  const Selector selector(sel, f.path, f.grid ? f.grid->dims : nullptr, placed ? &*placed : nullptr);
  if (selector.selectsAll()) return;
  if (f.grid)
    if (const double s = selector.keptSpacing(f.grid->spacing); std::isfinite(s)) f.sampleSpacing = s;
  std::size_t w = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double p[3] = {f.positions[3 * i], f.positions[3 * i + 1], f.positions[3 * i + 2]};
    // Already counted in totalPoints when it was added; only the reason is new.
    const auto verdict = selector.judge(f.ids[i], p);
    if (verdict != Selector::Verdict::Keep) {
      ++(verdict == Selector::Verdict::Masked ? f.masked : f.unselected);
      continue;
    }
    std::copy_n(&f.positions[3 * i], 3, &f.positions[3 * w]);
    std::copy_n(&f.tensors[6 * i], 6, &f.tensors[6 * w]);
    f.ids[w++] = f.ids[i];
  }
  f.positions.resize(3 * w);
  f.tensors.resize(6 * w);
  f.ids.resize(w);
}

}  // namespace tg::io
