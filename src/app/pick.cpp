#include "app/pick.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include "render/pixel_probe.h"

namespace tg::app {

const char* signClassName(SignClass c) {
  switch (c) {
    case SignClass::PositiveDefinite: return "positive-definite";
    case SignClass::NegativeDefinite: return "negative-definite";
    case SignClass::PositiveSemidefinite: return "positive-semidefinite";
    case SignClass::NegativeSemidefinite: return "negative-semidefinite";
    case SignClass::Indefinite: return "indefinite";
    case SignClass::Zero: break;
  }
  return "zero";
}

const char* glyphGroupName(tensor::GlyphGroup g) {
  switch (g) {
    case tensor::GlyphGroup::Sphere: return "sphere";
    case tensor::GlyphGroup::Definite: return "definite";
    case tensor::GlyphGroup::Mixed: break;
  }
  return "mixed";
}

namespace {

// From eigenvalues sorted descending.
SignClass classify(const glm::dvec3& l) {
  if (l.z > 0.0) return SignClass::PositiveDefinite;
  if (l.x < 0.0) return SignClass::NegativeDefinite;
  if (l.x == 0.0 && l.z == 0.0) return SignClass::Zero;
  if (l.z == 0.0) return SignClass::PositiveSemidefinite;
  if (l.x == 0.0) return SignClass::NegativeSemidefinite;
  return SignClass::Indefinite;
}

}  // namespace

PickTable::PickTable(io::TensorField& field, const tensor::GlyphOptions& opt)
    : positions_(std::move(field.positions)),
      tensors_(std::move(field.tensors)),
      ids_(std::move(field.ids)),
      opt_(opt) {
  if (field.grid) dims_ = std::array<int, 3>{field.grid->dims[0], field.grid->dims[1], field.grid->dims[2]};
  // Only the clamp changes a kept glyph's record; the shape filters decided
  // which glyphs exist, and a picked id did.
  opt_.clMin = opt_.cpMin = 0.0;
  if (ids_.empty()) {
    // buildGlyphs numbers glyphs 0..N-1 when a field gives no ids.
    ids_.extend(positions_.size() / 3);
    std::iota(ids_.begin(), ids_.end(), 0u);
  }
  if (!std::is_sorted(ids_.begin(), ids_.end())) {
    byId_.resize(ids_.size());
    std::iota(byId_.begin(), byId_.end(), 0u);
    std::sort(byId_.begin(), byId_.end(), [&](std::uint32_t a, std::uint32_t b) { return ids_[a] < ids_[b]; });
  }
}

std::optional<GlyphPick> PickTable::glyph(std::uint32_t id) const {
  std::size_t row = 0;
  if (byId_.empty()) {
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), id);
    if (it == ids_.end() || *it != id) return std::nullopt;
    row = std::size_t(it - ids_.begin());
  } else {
    const auto it = std::lower_bound(byId_.begin(), byId_.end(), id,
                                     [&](std::uint32_t r, std::uint32_t v) { return ids_[r] < v; });
    if (it == byId_.end() || ids_[*it] != id) return std::nullopt;
    row = *it;
  }
  GlyphPick g;
  g.index = id;
  if (dims_) {
    const std::uint32_t nx = std::uint32_t((*dims_)[0]), ny = std::uint32_t((*dims_)[1]);
    g.voxel = std::array<int, 3>{int(id % nx), int(id / nx % ny), int(id / nx / ny)};
  }
  const float* p = &positions_[3 * row];
  const float* t = &tensors_[6 * row];
  g.positionWC = glm::dvec3(p[0], p[1], p[2]);
  g.tensorWC = {t[0], t[1], t[2], t[3], t[4], t[5]};
  g.eigen = tensor::eigensolve(g.tensorWC);
  g.shape = tensor::anisotropy(g.eigen.values);
  g.sign = classify(g.eigen.values);
  // The record the renderer drew, from the same builder: its group is the
  // dispatch's, the --min-eigenvalue clamp included.
  const tensor::GlyphSet one = tensor::buildGlyphs({p, 3}, {t, 6}, {&id, 1}, 1, opt_);
  if (one.glyphs.size() != 1) throw std::logic_error("PickTable::glyph: the builder dropped a drawn glyph");
  g.group = tensor::glyphGroup(one.glyphs[0]);
  return g;
}

Pick resolvePick(const render::Camera& cam, PixelIJ pixel, std::uint32_t id, double viewDepth, const PickTable& table,
                 const render::GlyphRenderer& renderer) {
  Pick pick;
  pick.pixel = pixel;
  pick.id = id;
  if (id == 0xFFFFFFFFu) return pick;
  pick.viewDepth = viewDepth;
  // The ray's direction has unit length along the view axis, so the view
  // depth is its parameter (perspective and orthographic alike).
  const render::RayWC ray = cam.rayThroughPixel(pixel.i + 0.5, pixel.j + 0.5);
  pick.surfaceWC = ray.origin + viewDepth * ray.direction;
  if (render::isContextId(id)) {
    const render::ContextItem* item = renderer.contextItem(id);
    if (!item) throw std::logic_error("resolvePick: id " + std::to_string(id) + " names no context item");
    // A slice plane's depth is drawn moved behind the glyphs: report the
    // point on the plane itself, and its depth.
    if (const auto onItem = item->trueSurface(ray.origin, ray.direction)) {
      pick.surfaceWC = *onItem;
      pick.viewDepth = glm::dot(*onItem - ray.origin, ray.direction) / glm::dot(ray.direction, ray.direction);
    }
    pick.context = ContextPick{item->label(), item->valueAt(*pick.surfaceWC)};
    return pick;
  }
  pick.glyph = table.glyph(id);
  if (!pick.glyph) throw std::logic_error("resolvePick: id " + std::to_string(id) + " names no kept tensor");
  return pick;
}

Pick pickPixel(const gl::Api& gl, const render::GlyphRenderer& renderer, const render::Camera& cam,
               const render::GBuffer& target, const PickTable& table, PixelIJ pixel) {
  const render::PixelSample s = render::readPixel(gl, cam, target, pixel.i, pixel.j);
  return resolvePick(cam, pixel, s.id, s.viewDepth, table, renderer);
}

std::string describePick(const Pick& p) {
  char buf[1024];
  std::string out;
  auto line = [&](const char* fmt, auto... args) {
    std::snprintf(buf, sizeof buf, fmt, args...);
    out += buf;
    out += '\n';
  };
  line("pixel (%d, %d)", p.pixel.i, p.pixel.j);
  if (p.background()) {
    line("%s", "background");
    return out;
  }
  const glm::dvec3 s = *p.surfaceWC;
  if (p.context) {
    line("context: %s", p.context->label.c_str());
    if (p.context->value) line("value %.6g", *p.context->value);
  } else {
    const GlyphPick& g = *p.glyph;
    const tensor::SymTensor& t = g.tensorWC;
    line("glyph: input index %u at (%.6g, %.6g, %.6g)", g.index, g.positionWC.x, g.positionWC.y, g.positionWC.z);
    if (g.voxel) line("voxel (i, j, k) (%d, %d, %d)", (*g.voxel)[0], (*g.voxel)[1], (*g.voxel)[2]);
    line("tensor (WC): xx %.6g  xy %.6g  xz %.6g", t.xx, t.xy, t.xz);
    line("             yy %.6g  yz %.6g  zz %.6g", t.yy, t.yz, t.zz);
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3& v = g.eigen.vectors[std::size_t(k)];
      line("l%d %.6g  e%d (%.4f, %.4f, %.4f)", k + 1, g.eigen.values[k], k + 1, v.x, v.y, v.z);
    }
    line("FA %.4f  MD %.6g  cl %.4f  cp %.4f", g.shape.fa, g.shape.md, g.shape.cl, g.shape.cp);
    line("%s (glyph group: %s)", signClassName(g.sign), glyphGroupName(g.group));
  }
  line("surface (%.6g, %.6g, %.6g), view depth %.6g", s.x, s.y, s.z, p.viewDepth);
  return out;
}

}  // namespace tg::app
