#include "vtkTensorGlyphRayCastMapper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkHardwareSelector.h>
#include <vtkInformation.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkScalarsToColors.h>

#include "glyph_input.h"
#include "host_gl.h"
#include "lookup_colors.h"
#include "property_check.h"
#include "app/scale/pipeline_calibration.h"
#include "render/glyph_kind.h"
#include "render/glyph_path.h"
#include "render/renderer.h"

namespace {

using namespace tg;

// GL objects of one host context: made on the first frame in it, dropped in
// ReleaseGraphicsResources (while that context is current).
struct GLState {
  vtkOpenGLRenderWindow* window = nullptr;
  paraview::HostGL host;
  gl::ShaderLibrary lib;
  std::unique_ptr<render::GlyphRenderer> renderer;
  std::unique_ptr<render::GBuffer> target;
  std::unique_ptr<paraview::HostComposite> composite;
  vtkMTimeType uploaded = 0;  // input time of the records on the GPU
  int pipeline = -1;          // the Pipeline `renderer` was made for
  GLuint blocks = 0;          // the composite input's block table (blockTable), or none
  // What the colour scalars and table on the GPU were made from.
  std::string scalarsArray;
  vtkMTimeType scalarsInput = 0, tableTime = 0;
  paraview::LookupReading scalarsReading, tableReading;
  vtkScalarsToColors* tableOf = nullptr;
  glm::dvec2 tableWindow{0.0, 1.0};
  ~GLState() {
    if (blocks) host.api.DeleteBuffers(1, &blocks);
  }
  GLState() = default;
  GLState(const GLState&) = delete;
  GLState& operator=(const GLState&) = delete;
};

// Pipeline's path: raster, cpu or compute as named, or for auto the calibrated
// choice (app/scale/pipeline_calibration.h), measured in this context the
// first time this renderer, driver and core count is seen.
std::string glyphPathFor(GLState& g, int pipeline, render::GlyphKind kind, double gamma, double glyphs,
                         double pixels) {
  if (pipeline < int(std::size(render::kGlyphPathNames))) return std::string(render::kGlyphPathNames[pipeline]);
  app::CachedCalibration cached;
  const app::PathCalibration* cal = nullptr;
  if (app::choiceNeedsCalibration(kind, {})) {
    cached = app::calibrationFor(g.host.api, g.lib, app::currentCalibrationKey(g.host.api));
    if (!cached.said.empty()) vtkGenericWarningMacro("TensorGlyphPipeline auto: " << cached.said);
    cal = &cached.cal;
  }
  return app::choosePath(cal, kind, gamma, glyphs, pixels).path;
}

}  // namespace

struct vtkTensorGlyphRayCastMapper::Internals {
  std::optional<GLState> gl;
  tensor::GlyphSet glyphs;  // the CPU copy: dropped once uploaded
  paraview::SizingInfo sizing;
  glm::dvec3 centresLo{0.0}, centresHi{0.0};
  double maxAbsEigenvalue = 0;
  std::size_t count = 0;
  vtkIdType maxId = -1;  // the largest glyph id
  std::vector<std::uint32_t> blocks;  // composite input: (first id, flat index) pairs
  std::vector<std::uint32_t> pointOfRecord;  // each record's point of the prepared input
  vtkMTimeType built = 0;  // input time of `glyphs`
  vtkPolyData* builtFrom = nullptr;

  // Rebuilds the glyphs when the input changed since the last build.
  bool refresh(vtkPolyData* input, double& buildMs) {
    const vtkMTimeType t = input ? input->GetMTime() : 0;
    if (input == builtFrom && t == built) return false;
    const auto t0 = std::chrono::steady_clock::now();
    glyphs = paraview::buildGlyphSet(input);
    buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    sizing = paraview::sizingInfo(input);
    // Colours map the whole dataset's ranges (all ranks), not this piece's.
    if (sizing.mdMin <= sizing.mdMax) {
      glyphs.mdMin = sizing.mdMin;
      glyphs.mdMax = sizing.mdMax;
      glyphs.eigenvalueMin = sizing.eigenMin;
      glyphs.eigenvalueMax = sizing.eigenMax;
    }
    centresLo = glyphs.boundsMinWC;
    centresHi = glyphs.boundsMaxWC;
    maxAbsEigenvalue = glyphs.maxAbsEigenvalue;
    count = glyphs.glyphs.size();
    maxId = paraview::largestId(input);
    blocks = paraview::blockTable(input);
    pointOfRecord = paraview::pointOfRecord(input, glyphs);
    builtFrom = input;
    built = t;
    return true;
  }

  // ParaView's ColorBy into `p`: the array's values on the records and the
  // lookup table's colours and range, each sent again only when what it was
  // made from changed. False (p as it was) without an array or table, or
  // with a categorical table (IndexedLookup), which maps no range.
  bool colorByArray(GLState& g, vtkScalarsToColors* lut, const std::string& name, vtkPolyData* input,
                    render::FrameParams& p) const {
    vtkDataArray* array = name.empty() ? nullptr : input->GetPointData()->GetArray(name.c_str());
    if (!array || !lut || lut->GetIndexedLookup()) return false;
    const paraview::LookupReading reading = paraview::lookupReading(lut);
    if (g.scalarsArray != name || g.scalarsInput != built || !(g.scalarsReading == reading)) {
      g.renderer->setColorScalars(paraview::lookupScalars(array, pointOfRecord, reading), name);
      g.scalarsArray = name;
      g.scalarsInput = built;
      g.scalarsReading = reading;
    }
    if (g.tableOf != lut || g.tableTime != lut->GetMTime() || !(g.tableReading == reading)) {
      const paraview::LookupTable table = paraview::sampleLookupTable(lut, reading);
      g.renderer->setColorTable(table.colors);
      g.tableWindow = table.window;
      g.tableOf = lut;
      g.tableTime = lut->GetMTime();  // after MapValue, which may build the table
      g.tableReading = reading;
    }
    p.color = render::ColorMode::Array;
    p.colorTable = true;
    p.colorWindow = g.tableWindow;
    return true;
  }
};

vtkStandardNewMacro(vtkTensorGlyphRayCastMapper);

vtkTensorGlyphRayCastMapper::vtkTensorGlyphRayCastMapper() : Impl(std::make_unique<Internals>()) {}

vtkTensorGlyphRayCastMapper::~vtkTensorGlyphRayCastMapper() = default;

namespace {

// --lambda0's range, with 0 for its default (the median magnitude).
constexpr app::NumberRange kLambda0{app::ranges::kPositiveFloat.lo, app::ranges::kPositiveFloat.hi, false, true};

}  // namespace

#define TG_CHECKED_SETTER(Name, Type, Property, Range)              \
  void vtkTensorGlyphRayCastMapper::Set##Name(Type v) {             \
    if (paraview::acceptValue(this, "Set" #Name, "TensorGlyph" Property, this->Name, v, Range)) this->Modified(); \
  }
// The plugin draws through the raster path in ParaView's context: the kinds
// it draws lead the table (blobs, cast on the CPU, are the CLI's and Python's).
std::size_t rasterKinds() {
  std::size_t n = 0;
  while (n < render::kGlyphKindCount && render::pathDraws("raster", render::GlyphKind(n))) ++n;
  return n;
}
TG_CHECKED_SETTER(GlyphKind, int, "Kind", paraview::choices(rasterKinds()))
// render::kGlyphPathNames, then auto.
TG_CHECKED_SETTER(Pipeline, int, "Pipeline", paraview::choices(std::size(render::kGlyphPathNames) + 1))
TG_CHECKED_SETTER(Gamma, double, "Gamma", app::ranges::kGamma)
TG_CHECKED_SETTER(ScaleMode, int, "ScaleMode", paraview::choices(3))
TG_CHECKED_SETTER(ScaleFactor, double, "ScaleFactor", app::ranges::kPositiveFloat)
TG_CHECKED_SETTER(Magnitude, int, "Magnitude", paraview::choices(3))
TG_CHECKED_SETTER(Lambda0, double, "Lambda0", kLambda0)
TG_CHECKED_SETTER(Clamp, double, "Clamp", app::ranges::kClampSpacings)
TG_CHECKED_SETTER(FAThreshold, double, "FAThreshold", app::ranges::kUnit)
TG_CHECKED_SETTER(ColorMode, int, "ColorMode", paraview::choices(6))  // render::ColorMode's six
TG_CHECKED_SETTER(MarchIterations, int, "MarchIterations", app::ranges::kIterations)
TG_CHECKED_SETTER(MarchEpsilon, double, "MarchEpsilon", app::ranges::kEpsilon)
#undef TG_CHECKED_SETTER

int vtkTensorGlyphRayCastMapper::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace {

// The CLI's sizing (app::FieldFlags::scaleParams) from the properties.
tensor::ScaleParams scaleParams(vtkTensorGlyphRayCastMapper& m) {
  tensor::ScaleParams p;
  p.mode = tensor::ScaleMode(m.GetScaleMode());
  p.factor = m.GetScaleFactor();
  p.magnitude = tensor::Magnitude(m.GetMagnitude());
  if (m.GetLambda0() > 0.0) p.lambda0 = m.GetLambda0();
  if (!m.GetClampDefault()) p.clampSpacings = m.GetClamp();
  return p;
}

tensor::ResolvedScale resolve(vtkTensorGlyphRayCastMapper& m, const paraview::SizingInfo& s) {
  return tensor::resolveScale(scaleParams(m), s.sample);
}

// One prop's render inside one of VTK's hardware selection passes
// (vtkHardwareSelector: the renderer draws the scene once per pass and reads
// the colours back). Begun and ended around the draw as VTK's own mappers
// do; says what the composite writes in this pass.
class SelectionPass {
 public:
  SelectionPass(vtkHardwareSelector* sel, vtkIdType maxId, bool composite) : sel_(sel) {
    if (!sel_) return;
    sel_->BeginRenderProp();
    const int pass = sel_->GetCurrentPass();
    if (pass == vtkHardwareSelector::COMPOSITE_INDEX_PASS) sel_->RenderCompositeIndex(1);
    // Ids of 2^24 and more need the high pass.
    sel_->UpdateMaximumPointId(maxId);
    using Kind = paraview::CompositeOutput::Kind;
    out_.kind = Kind::Constant;
    if (sel_->GetFieldAssociation() != vtkDataObject::FIELD_ASSOCIATION_POINTS) {
      // Glyphs stand for points and have no cells: in a cell selection they
      // hide what is behind them (black with depth: no prop) but are never
      // selected themselves.
      return;
    }
    if (pass == vtkHardwareSelector::COMPOSITE_INDEX_PASS && composite) {
      out_.kind = Kind::CompositeIndex;  // each glyph's block (host_composite.frag)
    } else if (pass == vtkHardwareSelector::POINT_ID_LOW24) {
      out_.kind = Kind::IdLow24;
    } else if (pass == vtkHardwareSelector::POINT_ID_HIGH24) {
      out_.kind = Kind::IdHigh8;
    } else {  // actor, composite and process passes: the selector's colour
      const float* c = sel_->GetPropColorValue();
      out_.constant = glm::vec3(c[0], c[1], c[2]);
    }
  }
  ~SelectionPass() {
    if (sel_) sel_->EndRenderProp();
  }
  SelectionPass(const SelectionPass&) = delete;
  SelectionPass& operator=(const SelectionPass&) = delete;
  paraview::CompositeOutput& output() { return out_; }

 private:
  vtkHardwareSelector* sel_;
  paraview::CompositeOutput out_;
};

// The view's light kit (its UseLight and KeyLightIntensity) as a factor on
// the CLI's key light: the kit's key is its brightest camera light, and
// ParaView's default key intensity, 0.75, gives the CLI's picture; with the
// kit off (no camera light on) the key light is off, the head light and the
// ambient term stay. The key's direction stays the CLI's.
double keyLightFactor(vtkRenderer* ren) {
  constexpr double kParaViewKeyIntensity = 0.75;
  double key = 0.0;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
    if (light->GetSwitch() && light->LightTypeIsCameraLight()) key = std::max(key, light->GetIntensity());
  return key / kParaViewKeyIntensity;
}

}  // namespace

void vtkTensorGlyphRayCastMapper::SetColorArray(const char* name) {
  const std::string n = name ? name : "";
  if (n == this->ColorArray) return;
  this->ColorArray = n;
  this->Modified();
}

int vtkTensorGlyphRayCastMapper::GetRecordUploads() {
  const auto& g = this->Impl->gl;
  return g && g->renderer ? int(g->renderer->uploadCount()) : 0;
}

double vtkTensorGlyphRayCastMapper::GetResolvedScale() {
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  return resolve(*this, paraview::sizingInfo(input)).scale;
}

double* vtkTensorGlyphRayCastMapper::GetBounds() {
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!paraview::glyphBounds(input, scaleParams(*this), this->Bounds)) vtkMath::UninitializeBounds(this->Bounds);
  return this->Bounds;
}

void vtkTensorGlyphRayCastMapper::Render(vtkRenderer* ren, vtkActor* actor) {
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  auto* input = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!window || !input) return;
  Internals& in = *this->Impl;
  if (in.gl && in.gl->window != window) {
    // Another context: its records went with the old one's objects.
    in.gl.reset();
    in.builtFrom = nullptr;
  }
  // Another glyph path takes the records again: they are built anew.
  if (in.gl && in.gl->pipeline != this->Pipeline) in.builtFrom = nullptr;
  double ms = 0;
  if (in.refresh(input, ms)) this->LastBuildMilliseconds = ms;
  if (in.count == 0) return;
  SelectionPass selection(ren->GetSelector(), in.maxId, !in.blocks.empty());
  try {
    if (!in.gl) {
      in.gl.emplace();
      in.gl->window = window;
      in.gl->host = paraview::loadHostGL();
    }
    GLState& g = *in.gl;
    const paraview::HostState saved(g.host);
    saved.neutral();
    int width = 0, height = 0, x0 = 0, y0 = 0;
    ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
    if (width <= 0 || height <= 0) return;
    if (g.renderer && g.pipeline != this->Pipeline) g.renderer.reset();
    if (!g.renderer) {
      const std::string path = glyphPathFor(g, this->Pipeline, render::GlyphKind(this->GlyphKind), this->Gamma,
                                            double(in.glyphs.glyphs.size()), double(width) * double(height));
      g.renderer = std::make_unique<render::GlyphRenderer>(g.host.api, g.lib, render::OverlayFactories{}, path);
      g.pipeline = this->Pipeline;
      g.uploaded = 0;
    }
    this->GlyphPath = std::string(g.renderer->glyphPath().name());
    if (!g.composite) g.composite = std::make_unique<paraview::HostComposite>(g.host.api, g.lib);
    if (g.uploaded != in.built) {
      g.renderer->upload(in.glyphs);
      g.uploaded = in.built;
      g.scalarsArray.clear();  // an upload drops the renderer's colour scalars
      in.glyphs.glyphs = {};  // on the GPU now
      if (g.blocks) g.host.api.DeleteBuffers(1, &g.blocks);
      g.blocks = 0;
      if (!in.blocks.empty()) {
        g.host.api.CreateBuffers(1, &g.blocks);
        g.host.api.NamedBufferStorage(g.blocks, GLsizeiptr(in.blocks.size() * sizeof(std::uint32_t)),
                                      in.blocks.data(), 0);
      }
    }
    if (!ren->GetSelector() && actor) selection.output().opacity = float(actor->GetProperty()->GetOpacity());
    selection.output().blocks = g.blocks;
    selection.output().blockCount = int(in.blocks.size() / 2);
    if (!g.target || g.target->width() != width || g.target->height() != height)
      g.target = std::make_unique<render::GBuffer>(g.host.api, width, height);

    // The host's camera, as the CLI's --eye/--look-at/--up/--fov (or --ortho).
    vtkCamera* vc = ren->GetActiveCamera();
    render::CameraDesc desc;
    vc->GetPosition(&desc.eyeWC.x);
    vc->GetFocalPoint(&desc.lookAtWC.x);
    vc->GetViewUp(&desc.upWC.x);
    desc.projection = vc->GetParallelProjection() ? render::Projection::Orthographic : render::Projection::Perspective;
    desc.fovYDeg = vc->GetViewAngle();
    desc.orthoHeight = 2.0 * vc->GetParallelScale();
    const tensor::ResolvedScale sized = resolve(*this, in.sizing);
    render::FrameParams p;
    p.scale = sized.scale;
    p.sizing = sized.mapping;
    p.faMin = this->FAThreshold;
    p.glyph = render::GlyphKind(this->GlyphKind);
    p.gamma = this->Gamma;
    p.march = {this->MarchIterations, this->MarchEpsilon};
    p.color = render::ColorMode(this->ColorMode);
    this->ColoredByArray = in.colorByArray(g, this->LookupTable, this->ColorArray, input, p);
    p.ao.enabled = this->AmbientOcclusion;
    p.outline.enabled = this->Outlines;
    p.shadow.enabled = this->Shadows;
    p.light.key = float(double(p.light.key) * keyLightFactor(ren));
    tensor::GlyphSet box;  // the depth range: what glyphBoxWC needs of the uploaded set
    box.boundsMinWC = in.centresLo;
    box.boundsMaxWC = in.centresHi;
    box.maxAbsEigenvalue = in.maxAbsEigenvalue;
    const auto [lo, hi] = tensor::glyphBoxWC(box, p.scale, p.sizing);
    const render::Camera cam = render::makeCamera(desc, width, height, lo, hi);
    g.renderer->render(cam, p, *g.target);

    // Back into the host's framebuffer, depth in the host's convention.
    g.host.api.BindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(saved.drawFramebuffer()));
    g.host.api.ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    vtkMatrix4x4* proj = vc->GetProjectionTransformMatrix(double(width) / double(height), -1, 1);
    g.composite->draw(cam, *g.target, proj->GetData(), x0, y0, selection.output());
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
  }
}

void vtkTensorGlyphRayCastMapper::ReleaseGraphicsResources(vtkWindow* win) {
  auto& g = this->Impl->gl;
  if (g && g->window == win) {
    // The host makes its context current before releasing resources.
    g->composite.reset();
    g->target.reset();
    g->renderer.reset();
    g.reset();
  }
  this->Impl->builtFrom = nullptr;  // the records must be uploaded again
}

void vtkTensorGlyphRayCastMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GlyphKind: " << this->GlyphKind << "\n" << indent << "Gamma: " << this->Gamma << "\n";
  os << indent << "ScaleMode: " << this->ScaleMode << "\n" << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "Magnitude: " << this->Magnitude << "\n" << indent << "Lambda0: " << this->Lambda0 << "\n";
  os << indent << "ClampDefault: " << this->ClampDefault << "\n" << indent << "Clamp: " << this->Clamp << "\n";
  os << indent << "ColorMode: " << this->ColorMode << "\n" << indent << "FAThreshold: " << this->FAThreshold << "\n";
}
