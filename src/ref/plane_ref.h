#pragma once
// The CPU reference for slice planes: each pixel's ray against a plane's quad
// in double precision, merged into a reference image by depth. It shares the
// quad (view/underlay.h) and the camera with the GPU path, never its
// arithmetic. Depth is that of the plane moved `offsetWC` away from the eye
// along its normal, as the GPU's view-dependent offset puts it.
#include <cstdint>

#include "ref/ellipsoid_ref.h"
#include "view/underlay.h"

namespace tg::ref {

// Where the quad is nearer than what `img` holds (+inf where empty), the
// pixel takes `id`, the offset depth and the normal facing the eye. With
// `volume`, only where the plane lies inside its voxel cells (an oblique
// quad is the rectangle around its cut).
void addPlane(RefImage& img, const render::Camera& cam, const render::PlaneQuad& quad, std::uint32_t id,
              double offsetWC, const render::UnderlayVolume* volume = nullptr);

}  // namespace tg::ref
