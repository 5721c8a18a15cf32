#include "app/pick_json.h"

#include <json/json.h>

namespace tg::app {
namespace {

Json::Value vec3(const glm::dvec3& v) {
  Json::Value a(Json::arrayValue);
  for (int k = 0; k < 3; ++k) a.append(v[k]);
  return a;
}

Json::Value glyphJson(const GlyphPick& g) {
  Json::Value o(Json::objectValue);
  o["index"] = Json::UInt(g.index);
  if (g.voxel) {
    Json::Value ijk(Json::arrayValue);
    for (int k : *g.voxel) ijk.append(k);
    o["voxel"] = ijk;
  }
  o["position"] = vec3(g.positionWC);
  const tensor::SymTensor& t = g.tensorWC;
  Json::Value m(Json::arrayValue);
  m.append(vec3({t.xx, t.xy, t.xz}));
  m.append(vec3({t.xy, t.yy, t.yz}));
  m.append(vec3({t.xz, t.yz, t.zz}));
  o["tensor"] = m;
  o["eigenvalues"] = vec3(g.eigen.values);
  Json::Value vs(Json::arrayValue);
  for (const glm::dvec3& v : g.eigen.vectors) vs.append(vec3(v));
  o["eigenvectors"] = vs;
  o["fa"] = g.shape.fa;
  o["md"] = g.shape.md;
  o["cl"] = g.shape.cl;
  o["cp"] = g.shape.cp;
  o["sign"] = signClassName(g.sign);
  o["glyph_group"] = glyphGroupName(g.group);
  return o;
}

}  // namespace

std::string pickJson(const Pick& p) {
  Json::Value o(Json::objectValue);
  Json::Value px(Json::arrayValue);
  px.append(p.pixel.i);
  px.append(p.pixel.j);
  o["pixel"] = px;
  o["hit"] = p.glyph ? "glyph" : p.context ? "context" : "background";
  if (!p.background()) o["id"] = Json::UInt(p.id);
  if (p.glyph) {
    const Json::Value g = glyphJson(*p.glyph);
    for (const auto& key : g.getMemberNames()) o[key] = g[key];
  }
  if (p.context) {
    o["label"] = p.context->label;
    o["value"] = p.context->value ? Json::Value(*p.context->value) : Json::Value(Json::nullValue);
  }
  if (p.surfaceWC) {
    o["surface"] = vec3(*p.surfaceWC);
    o["depth"] = p.viewDepth;
  }
  Json::StreamWriterBuilder w;
  w["indentation"] = "";
  // 17 significant digits: every double, the tensor's float components
  // among them, reads back to the same value.
  w["precision"] = 17;
  return Json::writeString(w, o);
}

}  // namespace tg::app
