#pragma once
// The CPU reference: an exact double-precision ellipsoid ray caster. It is the
// tests' oracle, so it shares only the camera and the glyph record with the
// GPU path, never its arithmetic.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "view/camera.h"
#include "tensor/glyph.h"
#include "tensor/glyph_scale.h"

namespace tg::ref {

inline constexpr std::uint32_t kNoGlyph = std::numeric_limits<std::uint32_t>::max();

// Same channels as the GPU output; row 0 is the top row.
struct RefImage {
  int width = 0, height = 0;
  std::vector<double> depth;         // along the view axis from the eye; +inf where empty
  std::vector<glm::dvec3> normalWC;  // outward unit normal
  std::vector<std::uint32_t> id;     // input index, kNoGlyph where empty
};

struct RefParams {
  // A constructor, so that {scale, faMin} still reads as linear, unclamped glyphs.
  RefParams(double scale_ = 1.0, double faMin_ = 0.0, const tensor::SizeMapping& sizing_ = {})
      : scale(scale_), faMin(faMin_), sizing(sizing_) {}
  double scale;
  double faMin;
  tensor::SizeMapping sizing;  // as render::FrameParams::sizing
  // Blobs (ref/blob_ref.h): render::BlobParams' threshold and blobbiness.
  double blobThreshold = 1.0, blobBlobbiness = -2.0;
};

// The visible point of a pixel is the first intersection along its ray at or
// beyond the near plane, over all glyphs with FA >= faMin.
RefImage renderEllipsoids(const render::Camera& cam, std::span<const tensor::GlyphRecord> glyphs,
                          const RefParams& p);

// Sigg et al. 2006, eq. (5): the tight screen rectangle of an ellipsoid, in
// normalised device coordinates. `full` is set when the ellipsoid touches the
// eye plane (w = 0), where no finite rectangle exists.
struct RectNDC {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  bool full = false;
};
RectNDC ellipsoidRectNDC(const render::Camera& cam, const tensor::GlyphRecord& g, double scale);

}  // namespace tg::ref
