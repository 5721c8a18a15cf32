// The compute glyph path's shared code (render/compute_glyphs.h): a glyph's
// set-up and cast for one cast class, the visibility buffer and the tiles.
// The set-ups and casts are the raster programs' and the CPU path's own
// functions (lib/ellipsoid_sprite.glsl, lib/superquadric_sprite.glsl,
// lib/superquadric_cast.glsl, lib/prism.glsl); this file only chooses
// between them and packs what a cast needs.
//
// The class, one per program: TG_CAST_MARCH (superquadrics, with the march
// variant's own TG_MARCH_CONVEX or TG_MARCH_MIXED), TG_CAST_PRISM (with
// TG_CYLINDER: Teem's cylinders, else boxes), neither: ellipsoids.
// TG_VIS64: the visibility buffer is written by one 64-bit atomic minimum
// (GL_NV_shader_atomic_int64; the top-level file enables the extensions);
// without it, in two passes of 32-bit minima, depth (uPass 0) then record
// (uPass 1) where the depth is the pixel's.
#pragma tg option TG_CAST_MARCH
#pragma tg option TG_CAST_PRISM
#pragma tg option TG_CYLINDER
#pragma tg option TG_VIS64
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

#ifdef TG_CYLINDER
const bool kCylinder = true;
#else
const bool kCylinder = false;
#endif

uniform float uGamma;
uniform float uEpsilon;
uniform int uMaxIterations;
// The bound chunk of the records (render/compute_glyphs.h, RecordChunk):
// glyphs[k] is record uRecordBase + k, for k < uRecordCount.
uniform int uRecordBase;
uniform int uRecordCount;
uniform int uGroupLo;  // the class's glyph groups: [uGroupLo, uGroupHi)
uniform int uGroupHi;
uniform int uPass;    // without TG_VIS64: 0 depth, 1 record

const int kTilePx = 16;  // render/tile_binning.h's kTilePx
const uint kEmptyKey = 0xFFFFFFFFu;

// What a cast needs of one glyph (std430, 80 bytes): the sprite stage's
// centre, GC frame and nearest depth, the march's shape, and its pixels.
struct CastCandidate {
  vec4 centreVC_near;  // xyz: centre in VC; w: no hit lies nearer (view depth)
  vec4 gc0_shapeX;     // gcFromVC's columns; w: the march's shape (a, b, c)
  vec4 gc1_shapeY;
  vec4 gc2_shapeZ;
  uvec4 record_rect;   // x: record; y: x0 | y0 << 16; z: x1 | y1 << 16 (inclusive); w: the symmetry axis
};

mat3 candidateGcFromVC(CastCandidate c) { return mat3(c.gc0_shapeX.xyz, c.gc1_shapeY.xyz, c.gc2_shapeZ.xyz); }
vec3 candidateShape(CastCandidate c) { return vec3(c.gc0_shapeX.w, c.gc1_shapeY.w, c.gc2_shapeZ.w); }
ivec4 candidateRect(CastCandidate c) {
  return ivec4(c.record_rect.y & 0xFFFFu, c.record_rect.y >> 16, c.record_rect.z & 0xFFFFu, c.record_rect.z >> 16);
}

// The pixel centres (k + 0.5) within rectNDC, inclusive: the CPU path's
// rounding (render/tile_binning.h, pixelsOf), so that both paths cast the
// same pixels. False where none lies in the viewport.
bool pixelRectOf(vec4 rectNDC, out ivec4 r) {
  vec4 dc = (rectNDC + 1.0) * 0.5 * vec4(uViewportDC, uViewportDC);
  ivec2 hi = ivec2(uViewportDC) - 1;
  r = ivec4(max(ivec2(0), ivec2(ceil(dc.xy - 0.5))), min(hi, ivec2(floor(dc.zw - 0.5))));
  return r.x <= r.z && r.y <= r.w;
}

// tg::tensor::glyphGroup: 0 spheres, 1 definite, 2 mixed signs; records
// are ordered by group only within each tile of 256, so each class's
// programs pick their records by it.
int glyphGroupOf(vec3 l) {
  if (l.x == l.z) return 0;
  return l.z > 0.0 || l.x < 0.0 ? 1 : 2;
}

bool inClass(GlyphRecord g) {
  int group = glyphGroupOf(g.eigenvalues_id.xyz);
  return group >= uGroupLo && group < uGroupHi;
}

// The set-up of the chunk's record k for this class: false where no pixel
// centre can see it (the sprite's own culls: selection, size, depth range,
// its rectangle).
bool glyphCandidate(uint k, out CastCandidate c) {
  GlyphRecord g = glyphs[k];
  vec3 shape = vec3(1.0);
  uint axis = 0u;
  vec4 rectNDC;
  mat3 gc;
#if defined(TG_CAST_MARCH)
  SuperquadricSprite s;
  if (!superquadricSprite(g, uGamma, uEpsilon, s)) return false;
  c.centreVC_near = vec4(s.centreVC, s.nearVC);
  gc = s.gcFromVC;
  shape = s.shape.xyz;
  axis = uint(s.shape.w);
  rectNDC = s.rectNDC;
#elif defined(TG_CAST_PRISM)
  PrismSprite s;
  if (!prismSprite(g, kCylinder, s)) return false;
  c.centreVC_near = vec4(s.centreVC, s.nearVC);
  gc = s.gcFromVC;
  axis = uint(s.src.z);
  rectNDC = s.rectNDC;
#else
  EllipsoidSprite s;
  if (!ellipsoidSprite(g, s)) return false;
  c.centreVC_near = vec4(s.centreVC, max(s.dist - s.radius, uNearVC));
  gc = ellipsoidGcFromVC(s.rotVC, s.axes);
  rectNDC = s.rectNDC;
#endif
  ivec4 r;
  if (!pixelRectOf(rectNDC, r)) return false;
  c.gc0_shapeX = vec4(gc[0], shape.x);
  c.gc1_shapeY = vec4(gc[1], shape.y);
  c.gc2_shapeZ = vec4(gc[2], shape.z);
  c.record_rect = uvec4(uint(uRecordBase) + k, uint(r.x) | uint(r.y) << 16, uint(r.z) | uint(r.w) << 16, axis);
  return true;
}

// The ray through fragDC against c: its view depth, and what the normal
// and the sign colour need (ellipsoids: the GC hit; prisms: the hit and the
// face's GC normal; superquadrics: the hit and the gauge's gradient).
bool castCandidate(vec2 fragDC, CastCandidate c, out float depthVC, out vec3 pGC, out vec3 gradGC) {
  vec3 centreVC = c.centreVC_near.xyz;
  mat3 gc = candidateGcFromVC(c);
  gradGC = vec3(0.0);
#if defined(TG_CAST_MARCH)
  vec3 shape = candidateShape(c);
  SuperquadricRay r = superquadricRay(fragDC, centreVC, gc, shape, uEpsilon);
  if (!r.inReach) return false;
  MarchResult m = marchSuperquadricRay(r, shape, uMaxIterations, uEpsilon);
  if (!superquadricHitDepth(r, m, depthVC)) return false;
  gradGC = m.gradGC;
  pGC = superquadricHitGC(r, m);
  return true;
#elif defined(TG_CAST_PRISM)
  return castPrism(fragDC, centreVC, gc, kCylinder, depthVC, pGC, gradGC);
#else
  return castEllipsoid(fragDC, centreVC, gc, depthVC, pGC);
#endif
}

vec3 candidateNormalWC(CastCandidate c, vec3 pGC, vec3 gradGC) {
#if defined(TG_CAST_MARCH)
  return superquadricNormalWC(candidateGcFromVC(c), gradGC);
#elif defined(TG_CAST_PRISM)
  return prismNormalWC(candidateGcFromVC(c), gradGC);
#else
  return ellipsoidNormalWC(candidateGcFromVC(c), pGC);
#endif
}

// The hit in the ellipsoid's axis order, for the sign colour
// (cpu_gbuffer.frag): GC axis k is eigenvector src[k], src the cyclic
// permutation that ends with the symmetry axis.
vec3 candidateHitGC(CastCandidate c, vec3 pGC) {
#if defined(TG_CAST_MARCH) || defined(TG_CAST_PRISM)
  int axis = int(c.record_rect.w);
  vec3 e = vec3(0.0);
  e[(axis + 1) % 3] = pGC.x;
  e[(axis + 2) % 3] = pGC.y;
  e[axis] = pGC.z;
  return e;
#else
  return pGC;
#endif
}

// The visibility buffer: per pixel (rows bottom first) the record (low
// word) and the key of the window depth (high word), the nearest hit's:
// depth is reversed, so the key inverts it and the minimum of (key, record)
// keeps the nearest hit and, of equal depths, the lower record, as the
// raster path's GL_GREATER test keeps the glyph drawn first.
uint visKey(float windowDepth) { return ~floatBitsToUint(windowDepth); }

#ifdef TG_VIS64
layout(std430, binding = TG_SSBO_VIS) buffer Vis { uint64_t vis[]; };
void visWrite(uint px, float windowDepth, uint record) {
  atomicMin(vis[px], packUint2x32(uvec2(record, visKey(windowDepth))));
}
uint visKeyAt(uint px) { return unpackUint2x32(vis[px]).y; }
#else
layout(std430, binding = TG_SSBO_VIS) buffer Vis { uint vis[]; };
void visWrite(uint px, float windowDepth, uint record) {
  uint key = visKey(windowDepth);
  if (uPass == 0) atomicMin(vis[2u * px + 1u], key);
  else if (vis[2u * px + 1u] == key) atomicMin(vis[2u * px], record);
}
uint visKeyAt(uint px) { return vis[2u * px + 1u]; }
#endif

// The frame's counters (render/compute_glyphs.cpp, ComputeState).
layout(std430, binding = TG_SSBO_COMPUTE_STATE) buffer ComputeState {
  uint tiledCount;      // tiled glyphs this class set up (may pass the capacity)
  uint entryCount;      // their tiles, in all
  uint tiledCapacity;   // candidates[]'s length
  uint entryCapacity;   // tileList[]'s length
  uvec4 binDispatch;    // compute_bin.comp's indirect dispatch (xyz)
  uint tiledNeeded;     // the most of tiledCount and entryCount over the frame's classes
  uint entryNeeded;
  uint drawn;           // glyphs that reached a pixel
  uint entryOverflow;   // this class's tiles of glyphs past the capacity
  uvec4 setupDispatch;  // compute_setup.comp's indirect dispatch: x kBatchRecords / 64, y the chunk's kept batches
  uint batchesKept;     // the frame's kept batches over its chunks, classes and passes
  uvec4 castDispatch;   // compute_cast.comp's indirect dispatch: a workgroup per active tile
  uvec4 sortDispatch;   // compute_sort.comp's: x an active tile, y a run of kSortRun entries
};

// Records in batches of kBatchRecords (render/compute_glyphs.h, BatchBounds),
// each with the box of its centres and what bounds its glyphs' size and
// selection, so that compute_batches.comp culls whole batches each frame.
const uint kBatchRecords = 8192u;
struct BatchBounds {
  vec4 loWC_maxAbs;  // xyz: the least centre; w: the largest |eigenvalue|
  vec4 hiWC_maxFA;   // xyz: the greatest centre; w: the largest FA (-1 where none is a number)
};
layout(std430, binding = TG_SSBO_BATCH_BOUNDS) readonly buffer Batches { BatchBounds batches[]; };
layout(std430, binding = TG_SSBO_BATCH_LIST) buffer BatchList { uint keptBatches[]; };
layout(std430, binding = TG_SSBO_CANDIDATES) buffer Candidates { CastCandidate candidates[]; };
layout(std430, binding = TG_SSBO_TILE_COUNT) buffer TileCount { uint tileCount[]; };
layout(std430, binding = TG_SSBO_TILE_START) buffer TileStart { uint tileStart[]; };  // tiles + 1, then the cursors
layout(std430, binding = TG_SSBO_TILE_LIST) buffer TileList { uint tileList[]; };
layout(std430, binding = TG_SSBO_ACTIVE_TILES) buffer ActiveTiles { uint activeTiles[]; };  // in tile order

uniform int uTilesX;
uniform int uTiles;

// Workgroups are more than a dispatch's 65535 along x at 10^8 glyphs.
uint linearInvocation(uint localSize) {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * localSize + gl_LocalInvocationIndex;
}

// Tile lists are sorted by nearest depth in runs of kSortRun entries
// (compute_sort.comp), each run front to back.
const uint kSortRun = 1024u;
const uint kSortRunsMax = 65535u;  // a dispatch's workgroups along y: later runs stay unsorted

// Floats as uints that order as the floats do (negative ones reversed).
uint orderKey(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

// An x-major dispatch of at most 65535 workgroups along x over n items.
uvec4 dispatchOver(uint n) {
  uint x = min(n, 65535u);
  return uvec4(x, x == 0u ? 0u : (n + x - 1u) / x, 1u, 0u);
}

// The chunk's record of this invocation of a dispatch over the kept
// batches (setupDispatch: a workgroup row of kBatchRecords per batch).
uint keptRecord(uint localSize) {
  return keptBatches[gl_WorkGroupID.y] * kBatchRecords + gl_WorkGroupID.x * localSize + gl_LocalInvocationIndex;
}
