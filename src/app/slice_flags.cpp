#include "app/slice_flags.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "app/scale/cli_values.h"
#include "app/scale/option_ranges.h"
#include "io/core/format_table.h"
#include "io/core/readers.h"
#include "render/slice_plane.h"
#include "tensor/anisotropy.h"
#include "tensor/eigen.h"

namespace tg::app {
namespace {

constexpr const char* kFieldScalars[] = {"fa", "md", "cl", "cp"};

render::PlaneSpec parsePlane(const std::string& text) {
  io::SliceSpec s;
  try {
    s = io::parseSlice(text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--plane: ") + e.what());
  }
  if (text.find(':') != text.rfind(':') || s.worldAxis >= 0)
    throw UsageError("--plane: expected x|y|z:INDEX (voxel axes of the underlay's grid; --plane-at for a world "
                     "position), got \"" + text + "\"");
  render::PlaneSpec p;
  p.axis = s.axis;
  p.index = s.index;
  return p;
}

}  // namespace

void SliceFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::SliceParams d;
  auto param = [this](const char* flag) {
    if (firstParameterFlag.empty()) firstParameterFlag = flag;
  };
  const std::string group = ap.groupDefault();
  ap.setGroup("context");
  ap.arg("--underlay SOURCE")
      .help("scalar volume under the glyphs: " + io::extensionList(io::kScalarUse) + " on any grid, placed by its "
            "own index-to-world map; or fa, md, cl, cp of the field itself (default fa when only --plane is given)")
      .action([this](Args a) {
        if (!*a[1]) throw UsageError("--underlay needs a file or fa, md, cl or cp");
        underlay = a[1];
      });
  ap.arg("--plane SLICE")
      .help("a slice plane of the underlay's grid, SLICE = x|y|z:INDEX (default with --underlay: the middle z slice)")
      .repeats().action([this](Args a) { planes.push_back(parsePlane(a[1])); });
  ap.arg("--plane-at PX PY PZ NX NY NZ")
      .help("an oblique slice plane through point P with normal N, in world coordinates")
      .repeats().range(ranges::kAnyFloat).action([this](Args a) {
        render::PlaneSpec p;
        p.axis = -1;
        p.pointWC = parseVec3("--plane-at", std::span<const char* const>(a.data() + 1, 3));
        p.normalWC = parseVec3("--plane-at", std::span<const char* const>(a.data() + 4, 3));
        if (!(p.normalWC != glm::dvec3(0.0))) throw UsageError("--plane-at: the normal must not be zero");
        planes.push_back(p);
      });
  ap.arg("--underlay-colormap NAME")
      .help(std::string("gray (default), viridis or diverging")).oneOf(render::kColormapNames)
      .action([this, param](Args a) {
        param("--underlay-colormap");
        const auto c = render::colormapNamed(a[1]);
        if (!c) throw UsageError(std::string("--underlay-colormap: unknown colormap \"") + a[1] + "\"; choose " +
                                 render::kColormapNames);
        params.colormap = *c;
      });
  ap.arg("--underlay-window LO HI")
      .help("values mapped onto the colormap's ends (default: percentiles " + formatNumber(d.percentileLo) + " and " +
            formatNumber(d.percentileHi) + " of the volume's finite values)")
      .range(ranges::kAnyFloat).action([this, param](Args a) {
        param("--underlay-window");
        const double lo = parseDouble("--underlay-window", a[1]), hi = parseDouble("--underlay-window", a[2]);
        if (!(lo < hi)) throw UsageError("--underlay-window: LO must be below HI");
        // The planes map the volume's floats in single precision (slice_plane.frag):
        // beyond its range a window is infinite, and within its step LO is HI.
        if (!(std::abs(lo) <= FLT_MAX && std::abs(hi) <= FLT_MAX))
          throw UsageError("--underlay-window: LO and HI must lie within +-3.4e38 (single precision)");
        if (!(float(lo) < float(hi)))
          throw UsageError("--underlay-window: LO and HI are the same number in single precision; widen the window");
        params.window = std::pair(lo, hi);
      });
  ap.arg("--underlay-percentiles LO HI")
      .help("without --underlay-window: the percentiles of the volume's finite values mapped onto the "
            "colormap's ends (default " + formatNumber(d.percentileLo) + " " + formatNumber(d.percentileHi) + ")")
      .range(ranges::kPercent).action([this, param](Args a) {
        param("--underlay-percentiles");
        const double lo = parseDouble(a[0], a[1]);
        const double hi = parseDouble(a[0], a[2]);
        if (!(lo < hi)) throw UsageError("--underlay-percentiles: LO must be below HI");
        params.percentileLo = lo;
        params.percentileHi = hi;
        percentilesGiven = true;
      });
  ap.arg("--underlay-nearest")
      .help("sample the nearest voxel (for masks and labels) instead of trilinear interpolation (the default)")
      .action([this, param](Args) {
        param("--underlay-nearest");
        params.linear = false;
      });
  ap.arg("--plane-offset R")
      .help("draw planes R largest glyph radii behind themselves, away from the viewer, so glyphs centred on "
            "them are not cut; 0: true depth (default " + formatNumber(d.depthOffsetRadii) + ")")
      .range(ranges::kPlaneOffsetRadii).action([this, param](Args a) {
        param("--plane-offset");
        params.depthOffsetRadii = parseDouble(a[0], a[1]);
      });
  ap.setGroup(group);
}

void SliceFlags::validate() const {
  if (!firstParameterFlag.empty() && !any())
    throw UsageError(firstParameterFlag + " needs --underlay or --plane");
  if (percentilesGiven && params.window)
    throw UsageError("--underlay-percentiles and --underlay-window exclude each other");
}

bool SliceFlags::fromField() const {
  if (underlay.empty()) return true;
  for (const char* s : kFieldScalars)
    if (underlay == s) return true;
  return false;
}

std::vector<render::PlaneSpec> SliceFlags::planesFor(const render::UnderlayVolume& v) const {
  if (!planes.empty()) return planes;
  render::PlaneSpec p;
  p.axis = 2;
  p.index = v.dims[2] / 2;
  return {p};
}

render::UnderlayVolume loadUnderlay(const SliceFlags& f, const io::TensorField& field, const char* command) {
  render::UnderlayVolume v;
  const std::string who = field.path.empty() ? "the built-in scene" : field.path;
  const auto placeOnGrid = [&v](const io::GridInfo& g) {
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) v.indexToWC[c][r] = g.directions[3 * r + c] * g.spacing[c];
    v.indexToWC[3] = glm::dvec4(g.origin[0], g.origin[1], g.origin[2], 1.0);
  };
  if (!f.fromField()) {
    io::ScalarVolume s = f.underlayVolume ? *f.underlayVolume : io::readUnderlay(f.underlay);
    v.name = f.underlay;
    std::copy(s.dims, s.dims + 3, v.dims);
    v.values = std::move(s.values);
    if (s.placement) {
      const io::GridPlacement& p = *s.placement;
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) v.indexToWC[c][r] = p.axesWC[3 * r + c];
      v.indexToWC[3] = glm::dvec4(p.originWC[0], p.originWC[1], p.originWC[2], 1.0);
    } else {
      // An array given without an affine (files always place theirs): it
      // takes the tensors' grid, which must be its own.
      if (!field.grid)
        throw io::InputError(std::string(command) + ": " + f.underlay + ": an array without an affine takes the "
                             "tensors' grid, and " + who + " is a point set; give the array's affine (underlay_affine=)");
      if (!std::equal(s.dims, s.dims + 3, field.grid->dims))
        throw io::InputError(std::string(command) + ": " + f.underlay + ": shape " + io::gridText(s.dims) +
                             " is not the tensor grid " + io::gridText(field.grid->dims) + " of " + who +
                             ", whose affine it would take; give the array's own (underlay_affine=)");
      placeOnGrid(*field.grid);
    }
    // Voxel axes that span no volume (two alike, or a NaN that slipped into
    // the header) would draw the volume flattened somewhere.
    const glm::dmat3 axes(v.indexToWC);
    const double det = glm::determinant(axes);
    const double size = glm::length(axes[0]) * glm::length(axes[1]) * glm::length(axes[2]);
    if (!std::isfinite(det) || !std::isfinite(size) || !(std::abs(det) > 1e-9 * size))
      throw io::InputError(std::string(command) + ": " + f.underlay +
                           ": the underlay's voxel axes are singular or not finite");
    return v;
  }
  const std::string scalar = f.underlay.empty() ? "fa" : f.underlay;
  if (!field.grid)
    throw io::InputError(std::string(command) + ": " + who + ": --underlay " + scalar +
                         " needs a field on a grid; this is a point set (give --underlay FILE)");
  const io::GridInfo& g = *field.grid;
  v.name = scalar;
  std::copy(g.dims, g.dims + 3, v.dims);
  placeOnGrid(g);
  // Voxels without a kept tensor (masked, unselected, not finite) are holes.
  v.values.assign(v.voxels(), NAN);
  for (std::size_t k = 0; k < field.size(); ++k) {
    const float* t = &field.tensors[6 * k];
    const tensor::Eigensystem e = tensor::eigensolve({t[0], t[1], t[2], t[3], t[4], t[5]});
    const tensor::Anisotropy a = tensor::anisotropy(e.values);
    const double x = scalar == "fa" ? a.fa : scalar == "md" ? a.md : scalar == "cl" ? a.cl : a.cp;
    if (field.ids[k] < v.values.size()) v.values[field.ids[k]] = float(x);
  }
  return v;
}

void checkPlanes(const SliceFlags& f, const render::UnderlayVolume& volume, const char* command) {
  for (const render::PlaneSpec& p : f.planes)
    if (p.axis >= 0 && (p.index < 0 || p.index >= volume.dims[p.axis]))
      throw UsageError(std::string("--plane ") + "xyz"[p.axis] + ":" + std::to_string(p.index) + ": index " +
                       std::to_string(p.index) +
                       " is outside 0.." + std::to_string(volume.dims[p.axis] - 1) + " along " + "xyz"[p.axis] +
                       " of the underlay's grid (" + volume.name + ")");
  try {
    for (const render::PlaneSpec& p : f.planesFor(volume)) render::planeQuad(volume, p);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string(command) + ": " + volume.name + ": " + e.what());
  }
}

std::vector<std::string> underlayWarnings(const SliceFlags& f, const render::UnderlayVolume& volume,
                                          const glm::dvec3& glyphLoWC, const glm::dvec3& glyphHiWC) {
  std::vector<std::string> lines;
  const auto [lo, hi] = volume.boundsWC();
  bool overlap = true;
  for (int a = 0; a < 3; ++a) overlap = overlap && lo[a] <= glyphHiWC[a] && hi[a] >= glyphLoWC[a];
  auto box = [](const glm::dvec3& l, const glm::dvec3& h) {
    char b[160];
    std::snprintf(b, sizeof b, "(%g, %g, %g)..(%g, %g, %g)", l.x, l.y, l.z, h.x, h.y, h.z);
    return std::string(b);
  };
  if (!overlap) {
    lines.push_back("the underlay's box " + box(lo, hi) + " does not overlap the glyphs' " +
                    box(glyphLoWC, glyphHiWC) + ": another grid, other units or another affine?");
  }
  for (const render::PlaneSpec& p : f.planesFor(volume)) {
    // A plane beside the glyphs' box lies in front of or behind all of them:
    // the image shows the plane alone (another grid whose box still overlaps).
    if (overlap) {
      std::optional<render::PlaneQuad> q;
      try {
        q = render::planeQuad(volume, p);
      } catch (const std::invalid_argument&) {
      }
      bool above = false, below = false;
      for (int c = 0; q && c < 8; ++c) {
        const glm::dvec3 corner(c & 1 ? glyphHiWC.x : glyphLoWC.x, c & 2 ? glyphHiWC.y : glyphLoWC.y,
                                c & 4 ? glyphHiWC.z : glyphLoWC.z);
        const double d = glm::dot(q->normalWC, corner - q->pointWC);
        above |= d >= 0;
        below |= d <= 0;
      }
      if (q && !(above && below))
        lines.push_back(p.label() + " passes beside the glyphs' box " + box(glyphLoWC, glyphHiWC) +
                        ", in front of or behind every glyph: another grid, other units or another affine?");
    }
    if (p.axis < 0 || p.index < 0 || p.index >= volume.dims[p.axis]) continue;
    const int a = p.axis, b = (a + 1) % 3, c = (a + 2) % 3;
    bool any = false;
    int ijk[3];
    ijk[a] = int(p.index);
    for (ijk[c] = 0; ijk[c] < volume.dims[c] && !any; ++ijk[c])
      for (ijk[b] = 0; ijk[b] < volume.dims[b] && !any; ++ijk[b])
        any = std::isfinite(volume.values[std::size_t(ijk[0]) +
                                          std::size_t(volume.dims[0]) *
                                              (std::size_t(ijk[1]) + std::size_t(volume.dims[1]) * std::size_t(ijk[2]))]);
    if (!any) lines.push_back(p.label() + " shows nothing: every voxel of that slice is a hole (masked, unselected or not finite)");
  }
  return lines;
}

std::vector<render::SlicePlane*> addSlicePlanes(render::GlyphRenderer& r, const gl::Api& gl,
                                                const gl::ShaderLibrary& lib, const SliceFlags& f,
                                                render::UnderlayVolume volume, double maxAbsEigenvalue) {
  std::vector<render::SlicePlane*> added;
  if (!f.any()) return added;
  const std::string name = volume.name;
  const std::vector<render::PlaneSpec> planes = f.planesFor(volume);
  try {
    auto shared = std::make_shared<const render::SliceVolume>(gl, lib, std::move(volume));
    for (const render::PlaneSpec& p : planes) {
      auto plane = std::make_unique<render::SlicePlane>(shared, p, f.params, maxAbsEigenvalue);
      added.push_back(plane.get());
      r.addContext(std::move(plane));
    }
  } catch (const std::invalid_argument& e) {
    throw io::InputError("render: " + name + ": " + e.what());
  }
  return added;
}

}  // namespace tg::app
