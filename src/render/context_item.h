#pragma once
// Scene context, after Polyscope's structures: slice planes and meshes that
// draw themselves into the glyphs' G-buffer. Context and glyphs then hide
// each other by depth, as Taylor mixes ray-cast objects with polygons through
// the z-buffer, and lighting, the depth cues and picking read them alike.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include <glm/vec3.hpp>

#include "view/camera.h"
#include "render/gbuffer.h"
#include "render/legend_key.h"

namespace tg::render {

struct FrameParams;

// The id channel holds a glyph's input index, or kContextIdBase + the item's
// slot for context, or 0xFFFFFFFF where nothing was drawn. Input indices stay
// below kContextIdBase (TensorField refuses more tensors than that).
inline constexpr std::uint32_t kContextIdBase = 0xFFFFFF00u;
inline constexpr std::size_t kMaxContextItems = 0xFF;
inline bool isContextId(std::uint32_t id) { return id >= kContextIdBase && id != 0xFFFFFFFFu; }

// Which target an item draws into: the view's G-buffer (albedo, normalWC, id,
// depth), or the key light's shadow map (depth only; outputs are discarded).
enum class ContextTarget { View, ShadowMap };

class ContextItem {
 public:
  virtual ~ContextItem() = default;
  // What the viewer's panel and picking call it, e.g. "plane z:40".
  virtual std::string label() const = 0;
  // Opaque surfaces into the bound framebuffer. The caller has enabled the
  // reversed-Z depth test (GL_GREATER) with depth writes; `id` is what the
  // item writes to the id channel.
  virtual void drawOpaque(const Camera& cam, const FrameParams& p, std::uint32_t id, ContextTarget target) = 0;
  // See-through surfaces, blended over the lit colour after lighting and
  // before the outlines and overlays; `target`'s depth holds the opaque scene.
  virtual bool translucent() const { return false; }
  virtual void drawTranslucent(const Camera& /*cam*/, const FrameParams& /*p*/, const GBuffer& /*target*/) {}
  // The item's box in world coordinates, so that framing and the shadow
  // map's extent can include it.
  virtual std::pair<glm::dvec3, glm::dvec3> boundsWC() const = 0;
  // What picking reports of a surface point, beyond the label: the scalar a
  // slice shows there (its underlay's value), or nothing.
  virtual std::optional<double> valueAt(const glm::dvec3& /*pointWC*/) const { return std::nullopt; }
  // Where the ray origin + t dir (t > 0) meets the item's true surface, for an
  // item that draws its depth moved (a slice plane's offset); nothing when
  // the drawn depth is the surface.
  virtual std::optional<glm::dvec3> trueSurface(const glm::dvec3& /*originWC*/, const glm::dvec3& /*dirWC*/) const {
    return std::nullopt;
  }
  // The colour key the legend shows for the item (a slice plane's underlay), or nothing.
  virtual std::optional<UnderlayKey> legendKey() const { return std::nullopt; }
  // GPU memory the item holds.
  virtual std::size_t gpuBytes() const = 0;

  bool visible() const { return visible_; }
  void setVisible(bool v) { visible_ = v; }

 private:
  bool visible_ = true;
};

// The visible items' opaque surfaces into the bound target, under the
// reversed-Z depth test with depth writes; nothing (no GL call) with none.
void drawContextOpaque(const gl::Api& gl, std::span<const std::unique_ptr<ContextItem>> items, const Camera& cam,
                       const FrameParams& p, ContextTarget target);

}  // namespace tg::render
