#pragma once
// Slice planes' data, GL-free so that the CPU reference and picking share it:
// a scalar volume placed in world coordinates by its own index-to-world map,
// the planes cut through it, and their look (one parameter struct).
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace tg::render {

// Values at voxel centres: voxel (i, j, k) lies at indexToWC * (i, j, k, 1).
// Non-finite values are holes: nothing is drawn there.
struct UnderlayVolume {
  std::string name;  // the file, or "fa" etc. for the field's own scalar
  int dims[3] = {0, 0, 0};
  std::vector<float> values;  // i fastest
  glm::dmat4 indexToWC{1.0};

  std::size_t voxels() const { return std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]); }
  // Trilinear (linear) or nearest-voxel value at a world point, as the plane
  // samples it; none outside the voxel cells. Linear next to a hole is the
  // nearest voxel's value (none if that is the hole).
  std::optional<double> sample(const glm::dvec3& pointWC, bool linear) const;
  // The box of the voxel cells (voxel centres +- half a step), in WC.
  std::pair<glm::dvec3, glm::dvec3> boundsWC() const;
};

// shaders/lib/color.glsl's colormap(): diverging is blue, white at the
// middle, orange (the sign colour's ramp).
enum class Colormap { Gray, Viridis, Diverging };
inline constexpr const char* kColormapNames = "gray, viridis or diverging";
std::optional<Colormap> colormapNamed(const std::string& name);

// One home for the planes' look: the CLI, the viewer and scripts share it.
struct SliceParams {
  Colormap colormap = Colormap::Gray;
  // The value range mapped onto the colormap; none: the percentiles below of
  // the volume's finite values.
  std::optional<std::pair<double, double>> window;
  double percentileLo = 1.0, percentileHi = 99.0;
  // Trilinear filtering of the volume (false: nearest voxel, for masks and labels).
  bool linear = true;
  // The plane's depth is that of the plane moved this many of the largest
  // glyph radii away from the viewer along its normal, so that glyphs
  // centred on it are not cut (0: its true depth).
  double depthOffsetRadii = 1.0;
  bool operator==(const SliceParams&) const = default;
};

// --plane x|y|z:INDEX (an index plane of the volume's grid) or an oblique
// plane through pointWC with normalWC.
struct PlaneSpec {
  int axis = 2;  // 0, 1, 2; -1: oblique
  long long index = 0;
  glm::dvec3 pointWC{0.0}, normalWC{0, 0, 1};
  std::string label() const;
  bool operator==(const PlaneSpec&) const = default;
};

// A plane's quad in WC: for an index plane the whole slice of voxel cells,
// for an oblique one the rectangle in the plane that holds its cut through
// the volume's box (the fragments outside the volume are discarded).
struct PlaneQuad {
  glm::dvec3 cornersWC[4];  // in order around the quad
  glm::dvec3 pointWC, normalWC;  // unit normal
};
// Throws std::invalid_argument (one line, without the file) for an index
// outside the grid or an oblique plane that misses the volume.
PlaneQuad planeQuad(const UnderlayVolume& v, const PlaneSpec& s);

// The [lo, hi] percentiles (0..100) of the finite values; {0, 1} when none.
std::pair<double, double> percentileWindow(const std::vector<float>& values, double lo, double hi);

}  // namespace tg::render
