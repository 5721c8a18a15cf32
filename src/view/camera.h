#pragma once
// Pinhole and orthographic cameras, GL-free so the CPU reference shares them.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace tg::render {

enum class Projection { Perspective, Orthographic };

// What the user asks for (CLI: --eye --look-at --up --fov --ortho).
struct CameraDesc {
  glm::dvec3 eyeWC{0, 0, 1}, lookAtWC{0.0}, upWC{0, 1, 0};
  Projection projection = Projection::Perspective;
  double fovYDeg = 30.0;      // vertical, over the image height
  double orthoHeight = 1.0;   // view height in world units
};

struct RayWC {
  glm::dvec3 origin, direction;  // direction has unit component along the view axis
};

// A camera bound to an image size and to the depth range of a scene.
// Depth is reversed (near -> 1, far -> 0) with glClipControl's [0,1] range, so
// a float depth buffer keeps constant relative precision; perspective uses an
// infinite far plane.
struct Camera {
  CameraDesc desc;
  int width = 1, height = 1;
  double nearVC = 0.1, farVC = 1.0;  // distances along the view axis; far used by ortho only
  glm::dmat4 viewWCVC{1.0};
  glm::dmat4 projVCCC{1.0};  // to clip coordinates
  // Sub-pixel jitter (withPixelOffset): the ray of window position p passes
  // where p + pixelOffsetDC's did without it; zero but for anti-aliasing's samples.
  glm::dvec2 pixelOffsetDC{0.0};

  // Pixel (i, j) has its centre at (i + 0.5, j + 0.5), row 0 at the top.
  RayWC rayThroughPixel(double px, double py) const;
  // The same, with inverse(viewWCVC) computed once by the caller.
  RayWC rayThroughPixel(double px, double py, const glm::dmat4& wcFromVC) const;
  double windowDepthFromViewDepth(double d) const;
  double viewDepthFromWindowDepth(double z) const;
  glm::dvec3 viewDirectionWC() const;
};

// `cam` with its image shifted by `offsetDC` pixels (x right, y down, as
// rayThroughPixel's rows): the projection moves the scene by -offset so that
// each pixel centre sees the point offset from it; the depth range is kept.
Camera withPixelOffset(const Camera& cam, const glm::dvec2& offsetDC);

// Check a description before use: finite, eye != look-at, up not parallel to
// the view axis, fov in (0, 180), ortho height > 0. Returns "" when valid.
const char* validateCamera(const CameraDesc& d);

// Single precision: the GPU casts rays and keeps depth in floats, so a pixel
// at the look-at point must span at least two float steps of the camera's
// coordinates (the eye's, the look-at point's, their distance), or the image
// cannot show what lies there. Returns the smallest view height (orthographic,
// world units) or vertical field of view (perspective, degrees) an image
// `height` pixels high can use with `d`'s eye and look-at point.
double smallestResolvedView(const CameraDesc& d, int height);

// Binds a valid description to an image and a scene box (WC, glyph extents
// included), choosing near/far so that the whole box is in range.
Camera makeCamera(const CameraDesc& d, int width, int height, const glm::dvec3& sceneLoWC,
                  const glm::dvec3& sceneHiWC);

// The default view: looking down -Z at the box centre, +Y up (or from the
// unit direction towardEyeWC with the orthogonal unit upWC), framing its
// bounding sphere (ParaView's and Slicer's axial default).
CameraDesc frameBox(const glm::dvec3& loWC, const glm::dvec3& hiWC, Projection p, double fovYDeg, double aspect,
                    const glm::dvec3& towardEyeWC = {0, 0, 1}, const glm::dvec3& upWC = {0, 1, 0});

// The default still view: looking down -Z at the box centre, +Y up (or along
// the given axes, as frameBox), from the distance at which the box's corners
// fill the narrower side of the frustum with a 5% margin. Tighter than
// frameBox's bounding sphere, which leaves a cubic field half the image height.
CameraDesc fitBox(const glm::dvec3& loWC, const glm::dvec3& hiWC, Projection p, double fovYDeg, double aspect,
                  const glm::dvec3& towardEyeWC = {0, 0, 1}, const glm::dvec3& upWC = {0, 1, 0});

}  // namespace tg::render
