#version 450 core
// Anti-aliasing by coverage (render/antialias_pass.h): at a pixel whose 3x3
// block of ids holds another id (lib/aa_edge.glsl), each further sample
// point casts a ray against the glyphs those nine pixels show, with the
// kind's own set-up and cast (the raster programs' and the CPU path's
// functions), and keeps the nearest hit, or the nearer of the context and
// background pixels around it. Its colour is the lit colour of the pixel
// of the block nearest the sample that shows the same surface: coverage is
// exact per sample, shading is per pixel (as a multisampled raster shades
// once per pixel and primitive). The pixel's colour is the samples' mean.
// Only edge pixels run it: AntialiasPass marks them in the depth buffer
// first (aa_mark.frag), and the early depth test rejects the rest before
// shading, which llvmpipe does per block.
// TG_AA_MARCH (superquadrics) and TG_AA_PRISM (with TG_CYLINDER: Teem's
// cylinders, else boxes) choose the cast; neither: ellipsoids.
#pragma tg option TG_AA_MARCH
#pragma tg option TG_AA_PRISM
#pragma tg option TG_CYLINDER
#include "lib/bindings.h"
#include "lib/camera.glsl"
#include "lib/glyph_record.glsl"
#include "lib/ellipsoid.glsl"
#include "lib/glyph_size.glsl"
#include "lib/selection.glsl"
#include "lib/pixel_centres.glsl"
#include "lib/ellipsoid_sprite.glsl"
#include "lib/superquadric.glsl"
#include "lib/superquadric_march.glsl"
#include "lib/superquadric_sprite.glsl"
#include "lib/superquadric_cast.glsl"
#include "lib/prism.glsl"
#include "lib/aa_edge.glsl"

#ifdef TG_CYLINDER
const bool kCylinder = true;
#else
const bool kCylinder = false;
#endif

layout(early_fragment_tests) in;

layout(binding = TG_UNIT_AA_SAMPLE) uniform sampler2D uLit;      // the frame's lit colour
layout(binding = TG_UNIT_AA_DEPTH) uniform sampler2D uWindowDepth;  // the G-buffer's (reversed)
// Where each input id's record lies: with uDenseIds, the record of id i at
// [i] (kNoId for none); else (id, record) pairs sorted by id.
layout(std430, binding = TG_SSBO_AA_ID_RECORDS) readonly buffer IdRecords { uint idRecords[]; };
uniform int uDenseIds;

uniform float uGamma;
uniform float uEpsilon;
uniform int uMaxIterations;
uniform int uSamples;
uniform vec4 uSampleOffsets[16];  // xy: GL window axes; [0] is the centre

const uint kNoId = 0xFFFFFFFFu;
const uint kContextIdBase = 0xFFFFFF00u;  // render/context_item.h
const float kNone = 1.0 / 0.0;

out vec4 oColor;

// The record of input id `id`, or kNoId.
uint recordOf(uint id) {
  if (uDenseIds == 1) return id < uint(idRecords.length()) ? idRecords[id] : kNoId;
  int lo = 0, hi = idRecords.length() / 2 - 1;
  while (lo <= hi) {
    int mid = (lo + hi) / 2;
    uint m = idRecords[2 * mid];
    if (m == id) return idRecords[2 * mid + 1];
    if (m < id) lo = mid + 1;
    else hi = mid - 1;
  }
  return kNoId;
}

// A glyph set up once for its casts: the sprite stage's own set-up.
struct Caster {
  bool ok;
  vec3 centreVC;
  mat3 gcFromVC;
  vec3 shape;
};

// Only the frame: a glyph some pixel of the block shows needs no cull.
Caster setUp(GlyphRecord g) {
  Caster c;
  vec3 axes = glyphAxes(g.eigenvalues_id.xyz);
  vec3 centreVC = (uViewWCVC * vec4(g.posWC_fa.xyz, 1.0)).xyz;
  c.shape = vec3(1.0);
  c.centreVC = centreVC;
#if defined(TG_AA_MARCH)
  SuperquadricSprite s;
  superquadricFrame(g, axes, centreVC, uGamma, s);
  c.gcFromVC = s.gcFromVC;
  c.shape = s.shape.xyz;
#elif defined(TG_AA_PRISM)
  PrismSprite s;
  vec3 e0, e1, e2;
  prismFrame(g, axes, kCylinder, s, e0, e1, e2);
  c.gcFromVC = s.gcFromVC;
#else
  c.gcFromVC = ellipsoidGcFromVC(mat3(uViewWCVC) * quatToMat3(g.frameWC), axes);
#endif
  c.ok = max(axes.x, max(axes.y, axes.z)) > 0.0;
  return c;
}

// The view depth where the ray through fragDC meets the glyph, or kNone;
// also kNone where it could only lie behind `nearer` (the march is skipped).
float castAt(Caster c, vec2 fragDC, float nearer) {
  float depth;
  vec3 pGC, nGC;
#if defined(TG_AA_MARCH)
  SuperquadricRay r = superquadricRay(fragDC, c.centreVC, c.gcFromVC, c.shape, uEpsilon);
  if (!r.inReach || superquadricEntryVC(r) > nearer) return kNone;
  MarchResult m = marchSuperquadricRay(r, c.shape, uMaxIterations, uEpsilon);
  return superquadricHitDepth(r, m, depth) ? depth : kNone;
#elif defined(TG_AA_PRISM)
  return castPrism(fragDC, c.centreVC, c.gcFromVC, kCylinder, depth, pGC, nGC) ? depth : kNone;
#else
  return castEllipsoid(fragDC, c.centreVC, c.gcFromVC, depth, nGC) ? depth : kNone;
#endif
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 hiPx = textureSize(uFrameId, 0) - 1;
  uint ids[9];
  float depths[9];  // view depth at each pixel centre; kNone for the background
  vec2 centres[9];
  // The block's glyphs, each once.
  uint cands[9];
  float candDepth[9];
  int n = 0;
  for (int k = 0; k < 9; ++k) {
    ivec2 q = clamp(p + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), hiPx);
    centres[k] = vec2(q) + 0.5;
    ids[k] = texelFetch(uFrameId, q, 0).r;
    depths[k] = ids[k] == kNoId ? kNone : viewDepthFromWindowDepth(texelFetch(uWindowDepth, q, 0).r);
    bool seen = ids[k] >= kContextIdBase;
    for (int j = 0; j < n; ++j) seen = seen || cands[j] == ids[k];
    if (seen) continue;
    // Nearest first (by the pixel that listed it), so that glyphs behind
    // the first hit skip their march.
    int at = n++;
    for (; at > 0 && candDepth[at - 1] > depths[k]; --at) {
      cands[at] = cands[at - 1];
      candDepth[at] = candDepth[at - 1];
    }
    cands[at] = ids[k];
    candDepth[at] = depths[k];
  }
  float best[16];
  uint bestId[16];
  for (int s = 1; s < uSamples; ++s) {
    best[s] = kNone;
    bestId[s] = kNoId;
  }
  for (int c = 0; c < n; ++c) {
    uint r = recordOf(cands[c]);
    if (r == kNoId) continue;
    Caster g = setUp(glyphs[r]);
    if (!g.ok) continue;
    for (int s = 1; s < uSamples; ++s) {
      float d = castAt(g, vec2(p) + 0.5 + uSampleOffsets[s].xy, best[s]);
      if (d < best[s]) {
        best[s] = d;
        bestId[s] = cands[c];
      }
    }
  }
  vec4 sum = texelFetch(uLit, p, 0);
  for (int s = 1; s < uSamples; ++s) {
    vec2 fragDC = vec2(p) + 0.5 + uSampleOffsets[s].xy;
    // What else the sample may see: the context or background pixel of the
    // block nearest it, at that pixel's depth.
    int other = -1;
    float otherDist = 1e30;
    for (int k = 0; k < 9; ++k) {
      vec2 d = centres[k] - fragDC;
      if (ids[k] >= kContextIdBase && dot(d, d) < otherDist) {
        other = k;
        otherDist = dot(d, d);
      }
    }
    // The winner's pixel: of the glyph's, the one nearest the sample; else
    // the other one; else (a gap between glyphs no pixel shows) the centre.
    int pick = other;
    if (bestId[s] != kNoId && (other < 0 || best[s] <= depths[other])) {
      float pickDist = 1e30;
      for (int k = 0; k < 9; ++k) {
        vec2 d = centres[k] - fragDC;
        if (ids[k] == bestId[s] && dot(d, d) < pickDist) {
          pick = k;
          pickDist = dot(d, d);
        }
      }
    }
    sum += texelFetch(uLit, pick >= 0 ? clamp(p + ivec2(pick % 3 - 1, pick / 3 - 1), ivec2(0), hiPx) : p, 0);
  }
  oColor = sum / float(uSamples);
}
