#pragma once
// View-frustum planes and conservative box tests, GL-free so that the CPU
// decides cheaply when a frame needs no culling pass at all, and tests can
// check the GPU pass (shaders/cull_chunks.comp mirrors boxOutside).
#include <array>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "view/camera.h"

namespace tg::render {

// The clip volume's planes in WC (Gribb & Hartmann 2001): rows of
// projVCCC * viewWCVC combined so that a point p is inside when
// dot(plane.xyz, p) + plane.w >= 0 for all six. Depth follows ClipControl
// ZERO_TO_ONE with reversed Z (0 <= z_c <= w_c); the perspective far plane is
// at infinity, so its plane is satisfied by every point in front of the eye.
using FrustumWC = std::array<glm::dvec4, 6>;
FrustumWC frustumPlanesWC(const Camera& cam);

// True when the box is wholly outside one plane. Conservative: a box near a
// frustum edge may be kept though it is outside, never the reverse.
bool boxOutside(const FrustumWC& f, const glm::dvec3& lo, const glm::dvec3& hi);
// True when all of the box is inside every plane.
bool boxInside(const FrustumWC& f, const glm::dvec3& lo, const glm::dvec3& hi);

}  // namespace tg::render
