#include "io/selection.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/format_table.h"
#include "io/read_guard.h"
#include "io/readers.h"

namespace tg::io {

SliceSpec parseSlice(const std::string& text) {
  SliceSpec s;
  const auto c1 = text.find(':');
  if (c1 == std::string::npos) throw std::invalid_argument("expected axis:index[:thickness], got \"" + text + "\"");
  const std::string axis = text.substr(0, c1);
  if (axis == "x" || axis == "i" || axis == "0") s.axis = 0;
  else if (axis == "y" || axis == "j" || axis == "1") s.axis = 1;
  else if (axis == "z" || axis == "k" || axis == "2") s.axis = 2;
  else throw std::invalid_argument("unknown axis \"" + axis + "\"; choose x, y or z (or 0, 1, 2)");
  const auto c2 = text.find(':', c1 + 1);
  auto number = [&](std::size_t b, std::size_t e, const char* what) {
    long long v = 0;
    const char* first = text.data() + b;
    const char* last = text.data() + std::min(e, text.size());
    const auto [end, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || end != last || first == last)
      throw std::invalid_argument(std::string(what) + " \"" + std::string(first, last) + "\" is not an integer");
    return v;
  };
  s.index = number(c1 + 1, c2, "index");
  if (c2 != std::string::npos) s.thickness = number(c2 + 1, text.size(), "thickness");
  if (s.index < 0) throw std::invalid_argument("index must not be negative");
  if (s.thickness < 1) throw std::invalid_argument("thickness must be at least 1");
  return s;
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
    const SliceSpec& s = *sel.slice;
    if (s.index >= dims_[s.axis])
      throw SliceOutOfRange("Selector: " + path + ": slice index " + std::to_string(s.index) + " is beyond axis " +
                                std::to_string(s.axis) + " of size " + std::to_string(dims_[s.axis]),
                            s, dims_[s.axis]);
    slabLo_ = s.index - (s.thickness - 1) / 2;
    slabHi_ = s.index + s.thickness / 2;
  }
  if (!sel.maskPath.empty()) {
    mask_ = readScalarVolume(sel.maskPath, dims_);
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
    if (sel_.slice && sel_.slice->axis == k) along = std::min(along, std::uint64_t(slabHi_ - slabLo_ + 1));
    kept *= along;
  }
  return std::min(kept, n);
}

Selector::Verdict Selector::judge(std::uint64_t index, const double p[3]) const {
  if (grid_) {
    const std::uint64_t nx = std::uint64_t(dims_[0]), ny = std::uint64_t(dims_[1]);
    const long long ijk[3] = {(long long)(index % nx), (long long)(index / nx % ny), (long long)(index / (nx * ny))};
    if (sel_.slice && (ijk[sel_.slice->axis] < slabLo_ || ijk[sel_.slice->axis] > slabHi_)) return Verdict::Unselected;
    if (sel_.stride > 1 && (ijk[0] % sel_.stride || ijk[1] % sel_.stride || ijk[2] % sel_.stride))
      return Verdict::Unselected;
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
  const Selector selector(sel, f.path, f.grid ? f.grid->dims : nullptr);
  if (selector.selectsAll()) return;
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
