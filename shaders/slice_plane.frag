#version 450 core
// A slice plane into the G-buffer: the underlay sampled at the fragment's
// world point through its own index-to-world map, its depth that of the
// plane moved behind the glyph layer (render/slice_plane.h).
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/color.glsl"

layout(binding = TG_UNIT_SLICE) uniform sampler3D uVolume;
uniform mat4 uTexFromWC;
uniform vec4 uPlaneVC;  // the offset plane: dot(xyz, pVC) = w, xyz facing the camera
uniform vec3 uNormalWC;
uniform vec2 uWindow;
uniform int uColormap;  // tg::render::Colormap (lib/color.glsl)
uniform int uIdBits;

in vec3 vPointWC;

layout(depth_less) out float gl_FragDepth;
layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalWC;
layout(location = 2) out uint oId;

void main() {
  vec3 tc = (uTexFromWC * vec4(vPointWC, 1.0)).xyz;
  if (any(lessThan(tc, vec3(0.0))) || any(greaterThan(tc, vec3(1.0)))) discard;
  float v = texture(uVolume, tc).r;
  // Filtering gives NaN wherever a hole is among the 8 voxels, even at zero
  // weight, which would erase a mask one voxel thick: take the nearest voxel
  // there (UnderlayVolume::sample does the same).
  if (isnan(v) || isinf(v)) {
    ivec3 n = textureSize(uVolume, 0);
    v = texelFetch(uVolume, clamp(ivec3(floor(tc * vec3(n))), ivec3(0), n - 1), 0).r;
  }
  if (isnan(v) || isinf(v)) discard;  // a hole in the volume
  vec3 originVC, dirVC;
  rayThroughFragment(gl_FragCoord.xy, originVC, dirVC);
  float depth = (uPlaneVC.w - dot(uPlaneVC.xyz, originVC)) / dot(uPlaneVC.xyz, dirVC);
  if (!(depth >= uNearVC)) discard;
  gl_FragDepth = windowDepthFromViewDepth(depth);
  // Halved first: a window from -3e38 to 3e38 is wider than a float holds.
  float x = clamp((0.5 * v - 0.5 * uWindow.x) / (0.5 * uWindow.y - 0.5 * uWindow.x), 0.0, 1.0);
  oAlbedo = vec4(colormap(uColormap, x), 1.0);
  oNormalWC = vec4(uNormalWC, 0.0);
  oId = uint(uIdBits);
}
