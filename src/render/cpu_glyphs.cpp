#include "render/cpu_glyphs.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "render/camera_uniforms.h"
#include "render/cpu_blobs.h"
#include "render/glyph_kind.h"
#include "render/glsl_cpp.h"
#include "render/kind_programs.h"
#include "render/march_groups.h"
#include "render/raster_glyphs.h"
#include "render/shadow_pass.h"
#include "shaders/lib/bindings.h"

namespace tg::render {

namespace {

static_assert(sizeof(glsl::GlyphRecord) == sizeof(tensor::GlyphRecord));

using Candidate = CastCandidate;

// CastShape::kind: the ellipsoid cast, 1 + the march variant, or a prism's.
constexpr std::uint8_t kCastEllipsoid = 0, kCastCylinder = 4, kCastBox = 5;
std::uint8_t castKindOf(MarchVariant v) { return std::uint8_t(1 + int(v)); }
MarchVariant variantOfKind(std::uint8_t kind) { return MarchVariant(int(kind) - 1); }

// Which groups march, and how (render/march_groups.h, as the raster path).
struct CastMarch {
  int split = 3;
  bool variants = true;
  bool marches() const { return split < 3; }
  std::optional<MarchVariant> variantOf(const tensor::GlyphRecord& g) const {
    return marchVariant(int(tensor::glyphGroup(g)), split, variants);
  }
};

CastMarch castMarch(const FrameParams& p) { return {marchSplit(p), p.marchVariants}; }

// f(the variant's shaders): the march code is compiled once per variant.
template <class F>
bool withVariant(MarchVariant v, glsl::MarchGeneral& general, glsl::MarchConvex& convex, glsl::MarchMixed& mixed,
                 F&& f) {
  switch (v) {
    case MarchVariant::Convex: return f(convex);
    case MarchVariant::Mixed: return f(mixed);
    default: return f(general);
  }
}

// A superquadric's GC point in its ellipsoid's axis order, for the sign
// colour (cpu_gbuffer.frag): GC axis k is eigenvector src[k], src the cyclic
// permutation that ends with `axis` (lib/superquadric_sprite.glsl).
glsl::vec3 ellipsoidOrderGC(const glsl::vec3& pGC, int axis) {
  glsl::vec3 e(0.0f);
  e[(axis + 1) % 3] = pGC.x;
  e[(axis + 2) % 3] = pGC.y;
  e[axis] = pGC.z;
  return e;
}

// `s` without its records: the bounds and counts the path reads.
tensor::GlyphSet withoutRecords(const tensor::GlyphSet& s) {
  tensor::GlyphSet m;
  m.boundsMinWC = s.boundsMinWC;
  m.boundsMaxWC = s.boundsMaxWC;
  m.sizedBoundsMinWC = s.sizedBoundsMinWC;
  m.sizedBoundsMaxWC = s.sizedBoundsMaxWC;
  m.maxAbsEigenvalue = s.maxAbsEigenvalue;
  m.mdMin = s.mdMin;
  m.mdMax = s.mdMax;
  m.eigenvalueMin = s.eigenvalueMin;
  m.eigenvalueMax = s.eigenvalueMax;
  m.sphereCount = s.sphereCount;
  m.definiteCount = s.definiteCount;
  m.droppedByShape = s.droppedByShape;
  return m;
}

}  // namespace

void beginCasts(CpuCasts& out, int width, int height, bool hitGC) {
  if (width > kMaxCastSide || height > kMaxCastSide)
    throw std::invalid_argument("GlyphRenderer::render: " + std::to_string(width) + " x " + std::to_string(height) +
                                " pixels; the cpu glyph path casts at most " + std::to_string(kMaxCastSide) + " a side");
  const std::size_t n = std::size_t(width) * std::size_t(height);
  out.width = width;
  out.height = height;
  if (out.into) {
    const CastStorage& s = *out.into;
    out.windowDepth = {s.windowDepth, n};
    out.record = {s.record, n};
    out.normalWC = {s.normalWC, s.normalWC ? n : 0};
    out.hitGC = {s.hitGC, s.hitGC && hitGC ? n : 0};
  } else {
    out.ownDepth.resize(n);
    out.ownRecord.resize(n);
    out.ownNormal.resize(n);
    out.ownHit.resize(hitGC ? n : 0);
    out.windowDepth = out.ownDepth;
    out.record = out.ownRecord;
    out.normalWC = out.ownNormal;
    out.hitGC = out.ownHit;
  }
  std::fill(out.record.begin(), out.record.end(), 0u);
}

std::uint64_t castGlyphs(std::span<const tensor::GlyphRecord> records, const Camera& cam, const FrameParams& p,
                         bool hitGC, int threads, CpuCasts& out) {
  // One set of uniforms per march variant, as the raster path's programs.
  glsl::MarchGeneral general;
  glsl::MarchConvex convex;
  glsl::MarchMixed mixed;
  for (glsl::Shaders* v : std::initializer_list<glsl::Shaders*>{&general, &convex, &mixed}) {
    v->setCamera(cam);
    v->setGlyph(p);
  }
  glsl::Shaders& sh = general;
  const CastMarch march = castMarch(p);
  const float gamma = float(p.gamma), eps = float(p.march.epsilon);
  const int maxIter = p.march.maxIterations;
  const int w = cam.width, h = cam.height;
  beginCasts(out, w, h, hitGC);

  // Set-up, the vertex stage's: part k writes its glyphs, in record order,
  // from its first record's slot on; then the parts close up.
  const std::size_t m = records.size();
  // Teem's cylinders and boxes: one closed form for every group (prismSprite, castPrism).
  const bool prisms = glyphKind(p.glyph).draw == KindDraw::ClosedForm;
  const bool cylinders = p.glyph == GlyphKind::Cylinder;
  if (out.nearVC.size() < m) {
    out.nearVC.resize(m);
    out.rects.resize(m);
  }
  // Set-ups within out.keptSetUpBytes are kept from the first pass; larger
  // frames bound each glyph by a sphere there and set up in the tiles only
  // what they cast.
  const bool kept = m * sizeof(CastSetUp) <= out.keptSetUpBytes;
  if (kept && out.setUps.size() < m) out.setUps.resize(m);
  // Record i's sprite: what its fragments would receive. The first pass
  // keeps only its rectangle and nearest depth; a tile sets up again those
  // it casts, with the same arithmetic, so that no frame holds every
  // glyph's set-up (2 M glyphs: 144 MB).
  const auto sprite = [&](std::size_t i, Candidate& c, CastShape& shape, PixelRect& r) {
    glsl::GlyphRecord g;
    std::memcpy(&g, &records[i], sizeof g);
    if (prisms) {
      glsl::PrismSprite s;
      if (!general.prismSprite(g, cylinders, s) || !pixelsOf(s.rectNDC, w, h, r)) return false;
      shape = {glsl::vec3(0.0f), cylinders ? kCastCylinder : kCastBox, std::uint8_t(s.src.z)};
      c = {s.centreVC, s.gcFromVC, s.nearVC, std::uint32_t(i)};
      return true;
    }
    const std::optional<MarchVariant> v = march.variantOf(records[i]);
    if (!v) {
      glsl::EllipsoidSprite s;
      if (!general.ellipsoidSprite(g, s) || !pixelsOf(s.rectNDC, w, h, r)) return false;
      shape = {glsl::vec3(1.0f), kCastEllipsoid, 0};
      c = {s.centreVC, general.ellipsoidGcFromVC(s.rotVC, s.axes), std::max(s.dist - s.radius, general.uNearVC),
           std::uint32_t(i)};
      return true;
    }
    const std::uint8_t kind = castKindOf(*v);
    return withVariant(*v, general, convex, mixed, [&](auto& sq) {
      typename std::remove_reference_t<decltype(sq)>::SuperquadricSprite s;
      if (!sq.superquadricSprite(g, gamma, eps, s) || !pixelsOf(s.rectNDC, w, h, r)) return false;
      shape = {glsl::vec3(s.shape), kind, std::uint8_t(s.shape.w)};
      c = {s.centreVC, s.gcFromVC, s.nearVC, std::uint32_t(i)};
      return true;
    });
  };
  // A lean frame's first pass: the sphere about the glyph's centre that
  // holds what its cast can hit (the ellipsoid's longest semi-axis; the
  // box's half-diagonal for the march, grown by its tolerance as the march's
  // nearVC is, and for prisms), its rectangle with the sprites' margins and
  // its nearest depth. Both bound the exact sprite's, which the tile clips
  // to once it sets the glyph up (2 M glyphs at 1920x1080: this pass 66 ms
  // against the sprites' 110 on two cores).
  const float marchGrow = 1.0f + 4.0f * eps + 1e-5f;
  const float marginPx = (prisms ? 1.0f : 0.25f) + 1.0f / 64.0f;
  const glsl::vec2 marginNDC = 2.0f * marginPx / sh.uViewportDC;
  const auto bound = [&](std::size_t i, float& nearVC, PixelRect& r) {
    glsl::GlyphRecord g;
    std::memcpy(&g, &records[i], sizeof g);
    if (!sh.glyphSelected(g.posWC_fa)) return false;
    const glsl::vec3 axes = sh.glyphAxes(glsl::vec3(g.eigenvalues_id));
    const bool ellipsoid = !prisms && !march.variantOf(records[i]);
    const float radius =
        ellipsoid ? std::max(axes.x, std::max(axes.y, axes.z)) * (1.0f + 1e-5f) : glm::length(axes) * marchGrow;
    if (!(radius > 0.0f)) return false;
    const glsl::vec3 centreVC = glsl::vec3(sh.uViewWCVC * glsl::vec4(glsl::vec3(g.posWC_fa), 1.0f));
    const float dist = -centreVC.z;
    if (dist + radius < sh.uNearVC || (sh.uOrtho == 1 && dist - radius > sh.uFarVC)) return false;
    glsl::vec4 rect;
    if (!sh.ellipsoidFrameRectNDC(glsl::mat3(radius), centreVC, rect)) rect = glsl::vec4(-1.0f, -1.0f, 1.0f, 1.0f);
    else if (sh.rectMissesEveryPixelCentre(rect, sh.kPixelCentreMarginDC)) return false;
    rect = glm::clamp(rect + glsl::vec4(-marginNDC, marginNDC), -1.0f, 1.0f);
    if (!pixelsOf(rect, w, h, r)) return false;
    nearVC = std::max(dist - radius, sh.uNearVC);
    return true;
  };
  // Slot i is record i's: a glyph that reaches no pixel centre keeps an
  // empty rectangle, which reaches no tile.
  std::atomic<std::size_t> reached{0};
  runParts(threads, [&](int part, int parts) {
    std::size_t mine = 0;
    for (std::size_t i = partBegin(m, part, parts); i < partBegin(m, part + 1, parts); ++i) {
      if (!kept) {
        if (bound(i, out.nearVC[i], out.rects[i])) ++mine;
        else out.rects[i] = kNoPixels;
        continue;
      }
      Candidate c;
      CastShape shape;
      if (sprite(i, c, shape, out.rects[i])) {
        out.nearVC[i] = c.nearVC;
        if (kept) out.setUps[i] = {c, shape};
        ++mine;
      } else {
        out.rects[i] = kNoPixels;
      }
    }
    reached += mine;
  });
  const std::size_t count = reached;
  out.count = count;
  const bool masked = out.masked();
  const std::vector<float>& nearVC = out.nearVC;
  const std::vector<PixelRect>& rects = out.rects;
  TileBins& bins = out.bins;
  binToTiles(std::span(rects.data(), m), w, h, threads, bins);

  // Per tile, its glyphs nearest first, each cast at the pixel centres of
  // its rectangle where no hit so far lies nearer than the glyph can be; the
  // tile stops at the first glyph behind every pixel's hit. Each pixel thus
  // casts what a pixel-by-pixel walk of the sorted list would, in the same
  // order, at the cost of the glyphs' rectangles rather than the tile's
  // pixels times its glyphs. The depth test is the raster path's (reversed
  // window depth, GL_GREATER: of equal depths the glyph drawn first, the
  // lower record, stays; records run by group, in the order the raster path
  // draws its programs).
  constexpr int kTilePixels = kTilePx * kTilePx;
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::atomic<std::size_t> nextTile{0};
  runParts(threads, [&](int, int) {
    struct Key {
      float nearVC;
      std::uint32_t k;
    };
    // The tile's glyphs set up, in the order first cast, with their exact
    // rectangles.
    struct Local {
      CastSetUp s;
      PixelRect exact;
    };
    std::vector<Key> order;
    std::vector<Local> local;
    float bestWin[kTilePixels], bestVC[kTilePixels];
    std::uint32_t best[kTilePixels];
    glsl::vec3 bestGC[kTilePixels], bestGrad[kTilePixels];
    for (std::size_t t; (t = nextTile.fetch_add(1)) < bins.tiles();) {
      if (bins.start[t] == bins.start[t + 1]) continue;
      order.clear();
      for (std::uint32_t e = bins.start[t]; e < bins.start[t + 1]; ++e)
        order.push_back({nearVC[bins.items[e]], bins.items[e]});
      // Nearest first; of equal depths the lower record first, as drawn.
      std::sort(order.begin(), order.end(),
                [](const Key& a, const Key& b) { return a.nearVC < b.nearVC || (a.nearVC == b.nearVC && a.k < b.k); });
      const int tx = int(t % std::size_t(bins.tilesX)), ty = int(t / std::size_t(bins.tilesX));
      const int x0 = tx * kTilePx, y0 = ty * kTilePx;
      const int x1 = std::min(w, x0 + kTilePx) - 1, y1 = std::min(h, y0 + kTilePx) - 1;
      std::fill_n(bestWin, kTilePixels, 0.0f);
      std::fill_n(bestVC, kTilePixels, std::numeric_limits<float>::infinity());
      std::fill_n(best, kTilePixels, kNone);
      // Pixels of the tile (within the viewport) with no hit yet, and the
      // farthest hit once every one has one.
      int open = 0;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          if (!masked || out.only[std::size_t(y) * std::size_t(w) + std::size_t(x)]) ++open;
          else bestVC[(y - y0) * kTilePx + (x - x0)] = -1.0f;  // nearer than any glyph: cast nothing there
        }
      if (open == 0) continue;
      local.clear();
      float farVC = std::numeric_limits<float>::infinity();
      bool farStale = true;
      for (const Key& key : order) {
        if (open == 0) {
          if (farStale) {
            farVC = 0.0f;
            for (int y = y0; y <= y1; ++y)
              for (int x = x0; x <= x1; ++x) farVC = std::max(farVC, bestVC[(y - y0) * kTilePx + (x - x0)]);
            farStale = false;
          }
          if (key.nearVC > farVC) break;
        }
        const std::uint32_t k = key.k;
        const PixelRect& r = rects[k];
        std::uint32_t slot = kNone;  // in local, once a pixel casts it
        bool seen = true;            // false once the sprite shows no pixel centre can see it
        for (int y = std::max(int(r.y0), y0); seen && y <= std::min(int(r.y1), y1); ++y)
          for (int x = std::max(int(r.x0), x0); x <= std::min(int(r.x1), x1); ++x) {
            const int q = (y - y0) * kTilePx + (x - x0);
            if (key.nearVC > bestVC[q]) continue;
            if (slot == kNone) {
              Local l;
              if (kept) {
                l = {out.setUps[k], r};
              } else if (!sprite(k, l.s.c, l.s.shape, l.exact)) {
                seen = false;
                break;
              }
              slot = std::uint32_t(local.size());
              local.push_back(l);
            }
            const Local& l = local[slot];
            if (x < l.exact.x0 || x > l.exact.x1 || y < l.exact.y0 || y > l.exact.y1) continue;
            const Candidate& c = l.s.c;
            if (c.nearVC > bestVC[q]) continue;
            const std::uint8_t kind = l.s.shape.kind;
            const glsl::vec2 fragDC(float(x) + 0.5f, float(y) + 0.5f);
            float depthVC;
            glsl::vec3 pGC, grad(0.0f);
            if (kind == kCastEllipsoid) {
              if (!sh.castEllipsoid(fragDC, c.centreVC, c.gcFromVC, depthVC, pGC)) continue;
            } else if (kind >= kCastCylinder) {
              // grad holds the face's GC normal.
              if (!sh.castPrism(fragDC, c.centreVC, c.gcFromVC, kind == kCastCylinder, depthVC, pGC, grad)) continue;
            } else {
              const bool hit = withVariant(variantOfKind(kind), general, convex, mixed, [&](auto& sq) {
                const glsl::vec3 shape = l.s.shape.shape;
                const auto ray = sq.superquadricRay(fragDC, c.centreVC, c.gcFromVC, shape, eps);
                if (!ray.inReach) return false;
                const auto hitM = sq.marchSuperquadricRay(ray, shape, maxIter, eps);
                if (!sq.superquadricHitDepth(ray, hitM, depthVC)) return false;
                grad = hitM.gradGC;
                pGC = sq.superquadricHitGC(ray, hitM);
                return true;
              });
              if (!hit) continue;
            }
            const float win = sh.windowDepthFromViewDepth(depthVC);
            if (win > bestWin[q] || (best[q] != kNone && win == bestWin[q] && c.record < local[best[q]].s.c.record)) {
              open -= best[q] == kNone ? 1 : 0;
              farStale = true;
              bestWin[q] = win;
              bestVC[q] = depthVC;
              best[q] = slot;
              bestGC[q] = pGC;
              bestGrad[q] = grad;
            }
          }
      }
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const int q = (y - y0) * kTilePx + (x - x0);
          if (best[q] == kNone) continue;
          const Candidate& c = local[best[q]].s.c;
          const std::size_t px = std::size_t(y) * std::size_t(w) + std::size_t(x);
          out.windowDepth[px] = bestWin[q];
          out.record[px] = c.record + 1;
          const std::uint8_t kind = local[best[q]].s.shape.kind;
          const bool ellipsoid = kind == kCastEllipsoid;
          if (!out.normalWC.empty())
            out.normalWC[px] = ellipsoid               ? sh.ellipsoidNormalWC(c.gcFromVC, bestGC[q])
                               : kind >= kCastCylinder ? sh.prismNormalWC(c.gcFromVC, bestGrad[q])
                                                       : general.superquadricNormalWC(c.gcFromVC, bestGrad[q]);
          if (!out.hitGC.empty())
            out.hitGC[px] = glsl::vec4(ellipsoid ? bestGC[q] : ellipsoidOrderGC(bestGC[q], local[best[q]].s.shape.axis), 0.0f);
        }
    }
  });
  return count;
}

CpuGlyphs::CpuGlyphs(const gl::Api& gl, const gl::ShaderLibrary& lib)
    : gl_(gl), targets_(gl, lib, GL_RGB32F, true), threads_(cpuPathThreads()) {}

CpuGlyphs::~CpuGlyphs() {
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);
  if (scalars_) gl_.DeleteBuffers(1, &scalars_);
}

void CpuGlyphs::upload(const tensor::GlyphSet& set) {
  if (set.glyphs.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
    throw std::runtime_error("GlyphRenderer::upload: " + std::to_string(set.glyphs.size()) +
                             " glyphs; the cpu path numbers them in 32 bits");
  set_ = withoutRecords(set);
  records_ = {};
  if (buffer_) gl_.DeleteBuffers(1, &buffer_);  // unmaps it
  if (scalars_) gl_.DeleteBuffers(1, &scalars_);
  buffer_ = scalars_ = 0;
  if (!set.glyphs.empty()) {
    const auto bytes = GLsizeiptr(set.glyphs.size() * sizeof(tensor::GlyphRecord));
    gl_.CreateBuffers(1, &buffer_);
    const auto* renderer = reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER));
    // llvmpipe keeps a buffer in host memory and maps it in place, so the
    // casts read the one copy the shaders read (2 M records: 96 MB saved).
    // Elsewhere a GPU buffer read through a mapping may be uncached: the
    // casts keep their own copy.
    if (renderer && std::string_view(renderer).find("llvmpipe") != std::string_view::npos) {
      constexpr GLbitfield kFlags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT;
      gl_.NamedBufferStorage(buffer_, bytes, set.glyphs.data(), kFlags | GL_CLIENT_STORAGE_BIT);
      if (const void* p = gl_.MapNamedBufferRange(buffer_, 0, bytes, kFlags))
        records_ = {static_cast<const tensor::GlyphRecord*>(p), set.glyphs.size()};
    } else {
      gl_.NamedBufferStorage(buffer_, bytes, set.glyphs.data(), 0);
    }
    if (records_.empty()) {
      set_.glyphs = set.glyphs;
      records_ = {set_.glyphs.data(), set_.glyphs.size()};
    }
  }
  gl::checkError(gl_, "GlyphRenderer::upload");
}

void CpuGlyphs::setParams(const FrameParams& p, const FrameParams* old) { targets_.setGlyphParams(p, old); }

void CpuGlyphs::setColorWindow(glm::dvec2 window) { targets_.setColorWindow(window); }

void CpuGlyphs::uploadColorScalars(std::span<const float> byRecord) {
  if (byRecord.size() != records_.size())
    throw std::invalid_argument("GlyphRenderer::setColorScalars: " + std::to_string(byRecord.size()) +
                                " values for " + std::to_string(records_.size()) + " glyphs");
  if (scalars_) gl_.DeleteBuffers(1, &scalars_);
  scalars_ = 0;
  if (!byRecord.empty()) {
    gl_.CreateBuffers(1, &scalars_);
    gl_.NamedBufferStorage(scalars_, GLsizeiptr(byRecord.size_bytes()), byRecord.data(), 0);
  }
  gl::checkError(gl_, "GlyphRenderer::setColorScalars");
}

void CpuGlyphs::drawView(const Camera& cam, const FrameParams& p, const GBuffer& target) {
  if (p.tessellation > 0)
    throw std::invalid_argument("GlyphRenderer::render: the cpu glyph path casts rays; a tessellated frame needs the raster path");
  if (target.width() != cam.width || target.height() != cam.height)
    throw std::invalid_argument("GlyphRenderer::render: the target is not the camera's size");
  const bool sign = p.color == ColorMode::Sign;
  // An anti-aliasing sample of the last centre frame's view: only the
  // pixels by that frame's silhouettes (a record differs in the 3x3 block).
  const bool sample = cam.pixelOffsetDC != glm::dvec2(0.0);
  const int w = cam.width, h = cam.height;
  casts_.only.clear();
  if (sample && centreRecord_.size() == std::size_t(w) * std::size_t(h) && centreView_ == cam.viewWCVC) {
    casts_.only.assign(centreRecord_.size(), 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::uint32_t r = centreRecord_[std::size_t(y) * std::size_t(w) + std::size_t(x)];
        bool edge = false;
        for (int dy = -1; dy <= 1 && !edge; ++dy)
          for (int dx = -1; dx <= 1 && !edge; ++dx) {
            const int qx = std::clamp(x + dx, 0, w - 1), qy = std::clamp(y + dy, 0, h - 1);
            edge = centreRecord_[std::size_t(qy) * std::size_t(w) + std::size_t(qx)] != r;
          }
        casts_.only[std::size_t(y) * std::size_t(w) + std::size_t(x)] = edge;
      }
  }
  // Cast straight into the mapped targets, once GL has read the last frame's.
  targets_.allocateView(w, h, sign);
  targets_.waitForReads();
  casts_.into = CastStorage{static_cast<float*>(targets_.viewMapped(CastTargets::kDepth)),
                            static_cast<std::uint32_t*>(targets_.viewMapped(CastTargets::kRecord)),
                            static_cast<glm::vec3*>(targets_.viewMapped(CastTargets::kNormal)),
                            static_cast<glm::vec4*>(targets_.viewMapped(CastTargets::kHitGC))};
  drawn_ = glyphKind(p.glyph).draw == KindDraw::Blob ? castBlobs(records_, cam, p, sign, threads_, casts_, blobs_)
                                                     : castGlyphs(records_, cam, p, sign, threads_, casts_);
  if (!sample && p.samples > 1) {  // only a frame that samples again needs them
    centreRecord_.assign(casts_.record.begin(), casts_.record.end());
    centreView_ = cam.viewWCVC;
  }
  target.beginGeometry();
  if (drawn_ == 0) return;
  const RecordChunk all{buffer_, scalars_, 0, records_.size()};
  tileRuns(casts_.bins, w, h, runs_);
  targets_.writeView(cam, std::span(&all, 1), runs_);
}

std::pair<glm::dvec3, glm::dvec3> CpuGlyphs::castersBoxWC(const FrameParams& p) const {
  return render::castersBoxWC(set_.boundsMinWC, set_.boundsMaxWC, set_.maxAbsEigenvalue, p);
}

void CpuGlyphs::castShadowMap(const Camera& light, const FrameParams& p, ShadowPass& shadow) {
  // Into the light's mapped targets, with the view's per-glyph buffers
  // (keys, rectangles, tiles), which the view's casts refill after.
  casts_.only.clear();
  targets_.allocateLight(light.width);
  targets_.waitForReads();
  casts_.into = CastStorage{static_cast<float*>(targets_.lightMapped(0)),
                            static_cast<std::uint32_t*>(targets_.lightMapped(1)), nullptr, nullptr};
  if (glyphKind(p.glyph).draw == KindDraw::Blob) castBlobs(records_, light, p, false, threads_, casts_, blobs_);
  else castGlyphs(records_, light, p, false, threads_, casts_);
  tileRuns(casts_.bins, light.width, light.height, runs_);
  targets_.writeLight(light.width, shadow, runs_);
}

void CpuGlyphs::drawShadowCasters(const Camera& light, const FrameParams& p, ShadowPass& shadow) {
  castShadowMap(light, p, shadow);
}

std::size_t CpuGlyphs::gpuBytes() const {
  return records_.size() * (sizeof(tensor::GlyphRecord) + (scalars_ ? sizeof(float) : 0)) + targets_.bytes();
}

}  // namespace tg::render
