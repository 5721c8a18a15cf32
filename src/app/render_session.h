#pragma once
// A scene on a GL context with its glyphs uploaded once: `render` draws it a
// frame at a time, and the Python module's Renderer redraws it for new frame
// parameters (γ, FA threshold, scale, colour, camera, depth cues) with no
// second upload. Options that change what is loaded (OptionTable::reloads)
// need a new session.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "app/render_options.h"
#include "app/scene.h"
#include "gl/context.h"
#include "gl/shader_library.h"
#include "io/core/mesh_reader.h"
#include "view/frame_image.h"
#include "render/gbuffer.h"
#include "render/legend/legend_room.h"
#include "render/renderer.h"
#include "render/slice_plane.h"
#include "tensor/glyph.h"
#include "util/progress.h"

namespace tg::app {

// Whether a frame's camera leaves the legend room: a legend is shown and
// the camera was chosen (no --eye, no --ortho, which are kept as given).
bool leavesLegendRoom(const RenderOptions& o, const render::FrameParams& p);
// `desc` moved so that the legend's panel covers none of the glyphs
// (render/legend/legend_room.h): `cells` of `set` (whose statistics the legend
// shows), the underlays' keys from `r`, and the scene box [lo, hi] for depth.
// render, Python (RenderSession::frame) and view call it alike.
render::CameraDesc withLegendRoom(const RenderOptions& o, const render::FrameParams& p, const render::CameraDesc& desc,
                                  const std::vector<render::GlyphCell>& cells, const tensor::GlyphSet& set,
                                  const render::GlyphRenderer& r, const glm::dvec3& lo, const glm::dvec3& hi);

// What `view` changes in a session: the context it draws in (its window),
// and a look at the underlay before that context exists, so that whatever
// the window's script asks of the planes is checked before a window opens.
struct SessionHooks {
  // Called once the underlay is loaded and checked (not without one).
  std::function<void(const render::UnderlayVolume&)> underlayLoaded;
  // Default: an offscreen context of o.backend at o.width x o.height.
  std::function<std::unique_ptr<gl::Context>(const RenderOptions&)> makeContext;
  // Kinds the session must draw besides its own (a viewer script's): what
  // --pipeline auto chooses among.
  std::vector<render::GlyphKind> alsoDraws;
};

class RenderSession {
 public:
  // Builds the glyphs from `scene` (checkDrawable), reads the underlay and
  // uploads everything. The colour ranges are the scene's whole field's where
  // it has them (attachWholeField), else the loaded glyphs'. `keepGlyphs`: keep the records on the CPU, which a
  // change of scale needs to refit the camera's depth range; `render` drops
  // them to hold peak memory down. `beforeUpload` may take the field's
  // samples (a pick table) or free them before the GPU copy is made.
  // `command` prefixes warnings on stderr; `progress` hears the eigen stage.
  RenderSession(const RenderOptions& o, Scene scene, std::vector<io::MeshData> meshes, bool keepGlyphs,
                const char* command, const std::function<void(io::TensorField&)>& beforeUpload = {},
                const util::ProgressSink& progress = {}, const SessionHooks& hooks = {});
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // The frame parameters and camera `o` asks for. Throws io::InputError when
  // the glyphs at this scale leave single precision's range, and
  // std::logic_error for a new scale once the glyphs were dropped.
  struct Frame {
    render::FrameParams params;
    render::Camera camera;
    tensor::ResolvedScale sized;
    tensor::FramingBox framing;
  };
  Frame frame(const RenderOptions& o) const;
  // `progress`: told as each pass finishes (render::PassProgress).
  void draw(const Frame& f, const render::PassProgress& progress = {});
  render::FrameImage readback(const Frame& f, render::Channels channels);

  const Scene& scene() const { return scene_; }
  Scene& scene() { return scene_; }
  render::GlyphRenderer& renderer() { return *renderer_; }
  render::GBuffer& target() { return *target_; }
  // The target at width x height, made again when the size changes (a window's framebuffer).
  render::GBuffer& target(int width, int height);
  // The records' set: its counts, ranges and box always, the records only with keepGlyphs.
  const tensor::GlyphSet& glyphs() const { return glyphs_; }
  // Colour values given one per input tensor (Python's color=array) for
  // ColorMode::Array: a buffer beside the records, which stay uploaded.
  // Needs the records (keepGlyphs); std::invalid_argument naming `option`
  // for another count.
  void setColorValues(std::span<const float> byInput, const std::string& option);
  const tensor::MagnitudeSample& magnitudes() const { return magnitudes_; }
  // The underlay's planes, in the order of the flags (none without one).
  std::span<render::SlicePlane* const> slicePlanes() const { return planes_; }
  // The camera's depth range for p's scale and sizing: the glyphs' box grown
  // by the underlay's and the meshes' (growDepthRange), as frame() makes it.
  std::pair<glm::dvec3, glm::dvec3> depthBoxWC(const render::FrameParams& p) const;
  gl::Context& context() { return *ctx_; }
  std::size_t glyphCount() const { return glyphCount_; }
  double buildMs() const { return buildMs_; }
  double uploadMs() const { return uploadMs_; }
  // Why --pipeline auto took the session's path ("" when it was not asked).
  const std::string& pipelineWhy() const { return pipelineWhy_; }

 private:
  struct Boxes {  // what the glyphs' records give for one scale
    double scale = 0.0;
    tensor::SizeMapping mapping;
    tensor::BoxWC glyphsWC;
    tensor::FramingBox framing;
  };
  Boxes boxes(const tensor::ResolvedScale& sized) const;
  // --pipeline auto's path for frames like `p` (app/scale/pipeline_choice.h),
  // on the context just made: calibrated first where the cache lacks it.
  std::string autoPipeline(const RenderOptions& o, const render::FrameParams& p,
                           const std::vector<render::GlyphKind>& alsoDraws);
  // [lo, hi] grown by how much farther a blob reaches than a glyph (render::kindReach).
  void growForBlobs(glm::dvec3& lo, glm::dvec3& hi, const render::FrameParams& p) const;
  // Where the glyphs lie, for the legend's room: made from the records on
  // first need, so a session that never shows a legend never pays for it.
  const std::vector<render::GlyphCell>& cells() const;

  Scene scene_;
  tensor::GlyphSet glyphs_;  // the records, kept only with keepGlyphs
  tensor::MagnitudeSample magnitudes_;
  std::size_t glyphCount_ = 0;
  glm::dvec3 underlayLoWC_{INFINITY}, underlayHiWC_{-INFINITY};
  glm::dvec3 meshLoWC_{INFINITY}, meshHiWC_{-INFINITY};  // the meshes and tracts
  mutable std::optional<Boxes> last_;  // for the last scale asked; all that is left once the records go
  mutable std::optional<std::vector<render::GlyphCell>> cells_;
  // The last room left for the legend and what it was worked out from: a
  // redraw that changes none of it (gamma, lighting, effects) reuses it.
  struct Room {
    render::CameraDesc chosen, moved;
    int width = 0, height = 0;
    render::FrameParams params;  // only the fields withLegendRoom reads are compared
    std::vector<render::UnderlayKey> keys;
  };
  mutable std::optional<Room> room_;
  std::unique_ptr<gl::Context> ctx_;
  std::unique_ptr<gl::ShaderLibrary> lib_;
  std::unique_ptr<render::GlyphRenderer> renderer_;
  std::unique_ptr<render::GBuffer> target_;
  std::vector<render::SlicePlane*> planes_;
  double buildMs_ = 0.0, uploadMs_ = 0.0;
  std::string pipelineWhy_;
  const char* command_;
};

}  // namespace tg::app
