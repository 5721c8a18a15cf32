#pragma once
// A GPU frame against the CPU reference, pixel by pixel: coverage, ids, depth
// and normals. Shared by the GL tests (thresholds) and `bench accuracy`
// (reported figures), so both measure the same thing.
#include <cstddef>
#include <cstdint>
#include <functional>

#include "ref/ellipsoid_ref.h"
#include "view/camera.h"
#include "view/frame_image.h"

namespace tg::ref {

// Nearest-rank percentiles.
struct ErrorSummary {
  std::size_t count = 0;
  double median = 0, p99 = 0, max = 0;
};

struct ImageDiff {
  std::size_t refCovered = 0, gpuCovered = 0;
  std::size_t coverageMismatch = 0;  // covered in one image only
  std::size_t interiorMismatch = 0;  // of those, off the reference's silhouettes
  std::size_t idMismatch = 0;        // both covered, other glyph, off silhouettes, not a tie
  std::size_t nonFinite = 0;         // NaN/Inf in any GPU channel
  ErrorSummary depth;                // |depth error| / depthUnit
  ErrorSummary normalDeg;            // angle between the normals
};

struct DiffOptions {
  // Divides each depth error; default: the reference depth for perspective
  // (float keeps relative precision there), the depth range for orthographic
  // projection (a linear depth buffer).
  std::function<double(std::uint32_t id, double refDepth)> depthUnit;
  // Whether depth and normal errors include silhouette pixels, where a
  // sub-pixel shift of the outline shows as an unbounded depth difference.
  bool includeSilhouettes = false;
};

// A pixel is on a silhouette when its 3x3 neighbourhood in the reference holds
// another id (or none). Two glyphs whose surfaces meet at one depth (relative
// 1e-6) may win a pixel either way: such an id difference is a tie, not an
// error.
ImageDiff diffImages(const render::FrameImage& gpu, const RefImage& ref, const render::Camera& cam,
                     const DiffOptions& opt = {});

}  // namespace tg::ref
