#include "render/mesh_item.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "render/camera_uniforms.h"
#include "render/frame_params.h"
#include "shaders/lib/bindings.h"

namespace tg::render {
namespace {

// Edges as (lo, hi) vertex pairs with the triangle they came from; sorted,
// equal pairs are the faces that share an edge.
struct HalfEdge {
  std::uint32_t a, b, tri;
  bool operator<(const HalfEdge& o) const { return a != o.a ? a < o.a : b != o.b ? b < o.b : tri < o.tri; }
};

}  // namespace

const char* meshModeName(MeshMode m) {
  switch (m) {
    case MeshMode::Opaque: return "opaque";
    case MeshMode::SeeThrough: return "see-through";
    case MeshMode::Edges: return "edges";
  }
  return "?";
}

MeshItem::MeshItem(const gl::Api& gl, const gl::ShaderLibrary& lib, std::string label,
                   std::span<const float> positionsWC, std::span<const std::uint32_t> triangles,
                   const MeshParams& params)
    : gl_(gl), lib_(lib), label_(std::move(label)), params_(params) {
  if (positionsWC.size() % 3 || triangles.size() % 3 || triangles.empty())
    throw std::invalid_argument("MeshItem: " + label_ + ": no whole triangles");
  vertexCount_ = positionsWC.size() / 3;
  triangleCount_ = triangles.size() / 3;
  if (triangles.size() > std::size_t(INT32_MAX))
    throw std::invalid_argument("MeshItem: " + label_ + ": more indices than one draw takes");
  // The box of the vertices the triangles use: unused ones may be anything.
  loWC_ = glm::dvec3(INFINITY);
  hiWC_ = glm::dvec3(-INFINITY);
  for (std::uint32_t i : triangles) {
    if (i >= vertexCount_) throw std::invalid_argument("MeshItem: " + label_ + ": a triangle indexes past the vertices");
    const glm::dvec3 p(positionsWC[3 * std::size_t(i)], positionsWC[3 * std::size_t(i) + 1],
                       positionsWC[3 * std::size_t(i) + 2]);
    loWC_ = glm::min(loWC_, p);
    hiWC_ = glm::max(hiWC_, p);
  }
  gl.CreateVertexArrays(1, &vao_);
  gl.CreateBuffers(1, &vertices_);
  gl.NamedBufferStorage(vertices_, GLsizeiptr(positionsWC.size_bytes()), positionsWC.data(), 0);
  gl.CreateBuffers(1, &triangles_);
  gl.NamedBufferStorage(triangles_, GLsizeiptr(triangles.size_bytes()), triangles.data(), 0);
  gl::checkError(gl, "MeshItem");
}

MeshItem::~MeshItem() {
  const GLuint buffers[3] = {vertices_, triangles_, edges_};
  gl_.DeleteBuffers(3, buffers);
  gl_.DeleteVertexArrays(1, &vao_);
  const GLuint fbos[2] = {peelFbo_, blendFbo_};
  gl_.DeleteFramebuffers(2, fbos);
  if (peelDepth_) gl_.DeleteTextures(1, &peelDepth_);
}

std::size_t MeshItem::gpuBytes() const {
  return 12 * vertexCount_ + 12 * triangleCount_ + 8 * edgeCount_ + 4 * std::size_t(peelWidth_) * std::size_t(peelHeight_);
}

void MeshItem::setParams(const MeshParams& p) {
  params_ = p;
  // A mode switched away from releases what only it used.
  if (p.mode != MeshMode::SeeThrough) {
    forward_.reset();
    const GLuint fbos[2] = {peelFbo_, blendFbo_};
    gl_.DeleteFramebuffers(2, fbos);
    if (peelDepth_) gl_.DeleteTextures(1, &peelDepth_);
    peelFbo_ = blendFbo_ = peelDepth_ = peelColor_ = 0;
    peelWidth_ = peelHeight_ = 0;
  }
  if (p.mode != MeshMode::Edges && edges_) {
    gl_.DeleteBuffers(1, &edges_);
    edges_ = 0;
    edgeCount_ = 0;
    edgesAngleDeg_ = -1.0f;
  }
}

// Feature edges from the GPU's copy of the mesh: boundary and non-manifold
// edges (not two faces) and creases sharper than the feature angle.
void MeshItem::buildEdges() {
  std::vector<float> pos(3 * vertexCount_);
  std::vector<std::uint32_t> tri(3 * triangleCount_);
  gl_.GetNamedBufferSubData(vertices_, 0, GLsizeiptr(pos.size() * sizeof(float)), pos.data());
  gl_.GetNamedBufferSubData(triangles_, 0, GLsizeiptr(tri.size() * sizeof(std::uint32_t)), tri.data());
  auto vertex = [&](std::uint32_t i) { return glm::dvec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]); };
  std::vector<glm::dvec3> normal(triangleCount_);
  std::vector<HalfEdge> half;
  half.reserve(3 * triangleCount_);
  for (std::size_t t = 0; t < triangleCount_; ++t) {
    const std::uint32_t* v = &tri[3 * t];
    const glm::dvec3 n = glm::cross(vertex(v[1]) - vertex(v[0]), vertex(v[2]) - vertex(v[0]));
    const double len = glm::length(n);
    normal[t] = len > 0.0 ? n / len : glm::dvec3(0.0);
    for (int k = 0; k < 3; ++k)
      half.push_back({std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]), std::uint32_t(t)});
  }
  std::sort(half.begin(), half.end());
  // Orientation-blind: a mesh's faces need not wind alike (STL often does not).
  const double cosFeature = std::cos(glm::radians(double(params_.featureAngleDeg)));
  std::vector<std::uint32_t> lines;
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].a == half[i].a && half[j].b == half[i].b) ++j;
    if (half[i].a != half[i].b &&
        (j - i != 2 || std::abs(glm::dot(normal[half[i].tri], normal[half[i + 1].tri])) < cosFeature)) {
      lines.push_back(half[i].a);
      lines.push_back(half[i].b);
    }
    i = j;
  }
  if (edges_) gl_.DeleteBuffers(1, &edges_);
  edges_ = 0;
  edgeCount_ = lines.size() / 2;
  if (!lines.empty()) {
    gl_.CreateBuffers(1, &edges_);
    gl_.NamedBufferStorage(edges_, GLsizeiptr(lines.size() * sizeof(std::uint32_t)), lines.data(), 0);
  }
  edgesAngleDeg_ = params_.featureAngleDeg;
}

void MeshItem::drawOpaque(const Camera& cam, const FrameParams& /*p*/, std::uint32_t id, ContextTarget target) {
  const bool edges = params_.mode == MeshMode::Edges;
  // See-through surfaces come after lighting; edges are too thin to cast a shadow worth a pass.
  if (params_.mode == MeshMode::SeeThrough || (edges && target == ContextTarget::ShadowMap)) return;
  if (edges && edgesAngleDeg_ != params_.featureAngleDeg) buildEdges();
  if (edges && edgeCount_ == 0) return;
  if (!gbuffer_)
    gbuffer_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}});
  setCameraUniforms(*gbuffer_, cam);
  gbuffer_->set("uColor", params_.color);
  gbuffer_->set("uEdges", edges ? 1 : 0);
  gbuffer_->set("uId", std::bit_cast<int>(id));
  gl_.UseProgram(gbuffer_->id());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_MESH_VERTICES, vertices_);
  gl_.VertexArrayElementBuffer(vao_, edges ? edges_ : triangles_);
  gl_.BindVertexArray(vao_);
  const std::size_t count = edges ? 2 * edgeCount_ : 3 * triangleCount_;
  gl_.DrawElementsInstanced(edges ? GL_LINES : GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, nullptr, 1);
  gl::checkError(gl_, "MeshItem::drawOpaque");
}

void MeshItem::drawTranslucent(const Camera& cam, const FrameParams& p, const GBuffer& target) {
  if (params_.mode != MeshMode::SeeThrough) return;
  const int w = target.width(), h = target.height();
  if (!peelDepth_ || peelWidth_ != w || peelHeight_ != h || peelColor_ != target.color()) {
    const GLuint fbos[2] = {peelFbo_, blendFbo_};
    gl_.DeleteFramebuffers(2, fbos);
    if (peelDepth_) gl_.DeleteTextures(1, &peelDepth_);
    gl_.CreateTextures(GL_TEXTURE_2D, 1, &peelDepth_);
    gl_.TextureStorage2D(peelDepth_, 1, GL_DEPTH_COMPONENT32F, w, h);
    gl_.CreateFramebuffers(1, &peelFbo_);
    gl_.NamedFramebufferTexture(peelFbo_, GL_DEPTH_ATTACHMENT, peelDepth_, 0);
    const GLenum none = GL_NONE, color0 = GL_COLOR_ATTACHMENT0;
    gl_.NamedFramebufferDrawBuffers(peelFbo_, 1, &none);
    gl_.CreateFramebuffers(1, &blendFbo_);
    gl_.NamedFramebufferTexture(blendFbo_, GL_COLOR_ATTACHMENT0, target.color(), 0);
    gl_.NamedFramebufferTexture(blendFbo_, GL_DEPTH_ATTACHMENT, peelDepth_, 0);
    gl_.NamedFramebufferDrawBuffers(blendFbo_, 1, &color0);
    for (GLuint f : {peelFbo_, blendFbo_})
      if (gl_.CheckNamedFramebufferStatus(f, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("MeshItem: see-through framebuffer incomplete");
    peelWidth_ = w;
    peelHeight_ = h;
    peelColor_ = target.color();
  }
  if (!forward_) {
    forward_ = std::make_unique<gl::Program>(
        gl_, lib_, std::initializer_list<gl::StageSource>{{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}},
        std::vector<std::string_view>{"TG_MESH_FORWARD"});
  }
  const gl::Program& prog = *forward_;
  setCameraUniforms(prog, cam);
  prog.set("uColor", params_.color);
  prog.set("uEdges", 0);
  prog.set("uOpacity", params_.opacity);
  prog.set("uKeyDirVC", p.light.keyDirVC);
  prog.set("uLightMix", glm::vec4(p.light.ambient, p.light.head, p.light.key, p.light.specular));
  prog.set("uShininess", p.light.shininess);
  gl_.UseProgram(prog.id());
  gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TG_SSBO_MESH_VERTICES, vertices_);
  gl_.VertexArrayElementBuffer(vao_, triangles_);
  gl_.BindVertexArray(vao_);
  gl_.BindTextureUnit(TG_UNIT_MESH_SCENE_DEPTH, target.depth());
  const auto n = GLsizei(3 * triangleCount_);
  // Pass 1: the mesh's nearest surface, depth only (the shader's colour goes nowhere).
  gl_.BindFramebuffer(GL_FRAMEBUFFER, peelFbo_);
  gl_.Viewport(0, 0, w, h);
  const float farDepth = 0.0f;  // reversed Z
  gl_.ClearNamedFramebufferfv(peelFbo_, GL_DEPTH, 0, &farDepth);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthMask(GL_TRUE);
  gl_.DepthFunc(GL_GREATER);
  gl_.DrawElementsInstanced(GL_TRIANGLES, n, GL_UNSIGNED_INT, nullptr, 1);
  // Pass 2: that layer alone, blended over the lit colour.
  gl_.BindFramebuffer(GL_FRAMEBUFFER, blendFbo_);
  gl_.DepthMask(GL_FALSE);
  gl_.DepthFunc(GL_EQUAL);
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl_.DrawElementsInstanced(GL_TRIANGLES, n, GL_UNSIGNED_INT, nullptr, 1);
  gl_.Disable(GL_BLEND);
  gl_.DepthMask(GL_TRUE);
  gl_.Disable(GL_DEPTH_TEST);
  gl_.BindFramebuffer(GL_FRAMEBUFFER, target.colorFramebuffer());
  gl::checkError(gl_, "MeshItem::drawTranslucent");
}

}  // namespace tg::render
