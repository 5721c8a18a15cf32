#pragma once
// Picking: what a pixel of a rendered frame shows, read from the G-buffer's
// id and depth channels (no CPU ray cast), shared by `render --pick`, the
// viewer's click and its script's `pick` (and later Python).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "io/field/tensor_field.h"
#include "view/camera.h"
#include "render/gbuffer.h"
#include "render/renderer.h"
#include "tensor/anisotropy.h"
#include "tensor/eigen.h"
#include "tensor/glyph.h"

namespace tg::app {

// A pixel: column I from the left, row J from the top, as in the image.
struct PixelIJ {
  int i = 0, j = 0;
};

// The sign of a tensor's eigenvalues: finer than tensor::GlyphGroup, which
// puts semidefinite tensors with the mixed ones (they take its shapes).
enum class SignClass { PositiveDefinite, NegativeDefinite, PositiveSemidefinite, NegativeSemidefinite, Indefinite, Zero };
const char* signClassName(SignClass c);     // "positive-definite", ...
const char* glyphGroupName(tensor::GlyphGroup g);  // "sphere", "definite", "mixed"

struct GlyphPick {
  std::uint32_t index = 0;  // input index (the id channel)
  // On a gridded input, the voxel (i, j, k) the index names: index =
  // i + X (j + Y k), i fastest.
  std::optional<std::array<int, 3>> voxel;
  glm::dvec3 positionWC{0.0};
  // As stored for drawing: read, carried into WC (measurement frame, voxel
  // axes), rounded to float once; before --scale, the size mapping and
  // --min-eigenvalue.
  tensor::SymTensor tensorWC;
  tensor::Eigensystem eigen;  // of tensorWC, in double
  tensor::Anisotropy shape;   // FA, MD, cl, cp (cs) of those eigenvalues
  SignClass sign = SignClass::Zero;
  tensor::GlyphGroup group = tensor::GlyphGroup::Sphere;  // the renderer's dispatch (tensor::glyphGroup)
};

struct ContextPick {
  std::string label;            // render::ContextItem::label()
  std::optional<double> value;  // ContextItem::valueAt the surface point
};

struct Pick {
  PixelIJ pixel;
  std::uint32_t id = 0xFFFFFFFFu;  // the id channel
  // The surface point on the pixel centre's ray, at the depth the frame
  // stored (glyph or context; unset for background).
  std::optional<glm::dvec3> surfaceWC;
  double viewDepth = INFINITY;
  std::optional<GlyphPick> glyph;
  std::optional<ContextPick> context;
  bool background() const { return !glyph && !context; }
};

// The samples a field was drawn from, kept for picking after its glyph
// records are freed: input positions and tensors in float, exactly as the
// glyphs were built from them (40 bytes a tensor). Reconstructing a tensor
// from a record's float eigenvalues and quaternion instead would add ~1e-7
// relative error to every component, and much more to small off-diagonal
// terms of a nearly isotropic tensor.
class PickTable {
 public:
  // Moves the field's samples out (no copy); `opt` as the glyphs were built.
  PickTable(io::TensorField& field, const tensor::GlyphOptions& opt);
  std::size_t size() const { return ids_.size(); }
  // The glyph with input index `id`, or nothing when no kept tensor has it.
  std::optional<GlyphPick> glyph(std::uint32_t id) const;

 private:
  util::MappedArray<float> positions_, tensors_;
  util::MappedArray<std::uint32_t> ids_;
  std::vector<std::uint32_t> byId_;  // rows in ascending id order; empty when ids_ already ascend
  tensor::GlyphOptions opt_;
  std::optional<std::array<int, 3>> dims_;  // the field's grid, when it has one
};

// The GL-free half: what id `id` at view depth `viewDepth` means at `pixel`.
Pick resolvePick(const render::Camera& cam, PixelIJ pixel, std::uint32_t id, double viewDepth, const PickTable& table,
                 const render::GlyphRenderer& renderer);

// One pixel of the frame `renderer` last drew into `target` with `cam`.
// Throws std::out_of_range outside the target.
Pick pickPixel(const gl::Api& gl, const render::GlyphRenderer& renderer, const render::Camera& cam,
               const render::GBuffer& target, const PickTable& table, PixelIJ pixel);

// For the viewer's panel: a few lines of text.
std::string describePick(const Pick& p);

}  // namespace tg::app
