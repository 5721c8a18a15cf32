#include "vtkTensorGlyphRayCastRepresentation.h"

#include <exception>
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkOpenGLActor.h>
#include <vtkProperty.h>
#include <vtkAlgorithmOutput.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPVRenderView.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkScalarsToColors.h>

#include "color_legend.h"
#include "glyph_input.h"
#include "property_check.h"
#include "io/field/tensor_field.h"
#include "vtkTensorGlyphRayCastMapper.h"

vtkStandardNewMacro(vtkTensorGlyphRayCastRepresentation);

namespace {

// The glyphs' actor. Opaque, it draws in the opaque pass as any actor. Below
// an Opacity of 1 it is drawn last, over the frame (the overlay stage, before
// ParaView's 2-D annotations, which a renderer of their own draws), blended
// over the opaque and translucent geometry drawn before it: ParaView's
// translucent pass peels depth layers with shaders of VTK's own mappers,
// which the ray-cast glyphs are not, so the actor keeps out of it. The
// mapper draws the nearest glyph surface only (a glyph behind a glyph is
// hidden), and keeps its depth, for the view's depth compositing.
class GlyphActor : public vtkOpenGLActor {
 public:
  static GlyphActor* New();
  vtkTypeMacro(GlyphActor, vtkOpenGLActor);
  vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }
  int RenderTranslucentPolygonalGeometry(vtkViewport*) override { return 0; }
  int RenderOverlay(vtkViewport* viewport) override {
    auto* ren = vtkRenderer::SafeDownCast(viewport);
    if (!ren || ren->GetSelector() || !this->Mapper || this->GetIsOpaque() || !(this->Property->GetOpacity() > 0.0))
      return 0;
    this->Render(ren, this->Mapper);
    return 1;
  }
};
vtkStandardNewMacro(GlyphActor);

}  // namespace

vtkTensorGlyphRayCastRepresentation::vtkTensorGlyphRayCastRepresentation() : Actor(vtkSmartPointer<GlyphActor>::New()) {
  this->Actor->SetMapper(this->Mapper);
  // The active tensors unless the user picks another point array; the mask
  // (used only with UseMask) the active scalars unless another is picked.
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::TENSORS);
  this->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkTensorGlyphRayCastRepresentation::~vtkTensorGlyphRayCastRepresentation() = default;

vtkTensorGlyphRayCastMapper* vtkTensorGlyphRayCastRepresentation::GetMapper() { return this->Mapper; }

int vtkTensorGlyphRayCastRepresentation::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  // Every leaf block is drawn (RequestData).
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

namespace {

// The CLI's load warnings (app::reportLoad), in its words, with the array in
// place of the file. RequestData runs once per update, not once per render.
void reportLoad(vtkObject* self, const tg::paraview::LoadReport& report,
                const std::vector<tg::paraview::Piece>& pieces, const tg::paraview::SelectionParams& select) {
  std::string name;
  for (const auto& piece : pieces)
    if (piece.tensors && piece.tensors->GetName()) name = piece.tensors->GetName();
  const std::string array = "prepareGlyphInput: array '" + name + "': ";
  if (const std::string w = tg::io::asymmetryWarning("9-component tensors", report.maxAsymmetry); !w.empty())
    vtkWarningWithObjectMacro(self, << array << w);
  if (report.skippedNonFinite)
    vtkWarningWithObjectMacro(self, << array << "skipped " << report.skippedNonFinite << " tensors with NaN/Inf components");
  if (report.skippedOverflow)
    vtkWarningWithObjectMacro(self, << array << "skipped " << report.skippedOverflow
                    << " tensors whose values overflow single precision (beyond 3.4e38)");
  // As the CLI's checkLoaded: the options that left nothing, named.
  if (report.kept == 0 && report.masked + report.unselected > 0)
    vtkErrorWithObjectMacro(self, << "prepareGlyphInput: array '" << name << "': no tensor to draw: "
                                  << report.masked << " masked (TensorGlyphMaskMin " << select.maskMin << "), "
                                  << report.unselected << " left out by TensorGlyphStride " << select.stride);
  if (report.piecesWithTensors == 0 && report.piecesWithout > 0)
    vtkErrorWithObjectMacro(self, << "prepareGlyphInput: none of the " << report.piecesWithout
                  << " blocks with points has a point array of tensors (9 or 6 components)");
}

}  // namespace

int vtkTensorGlyphRayCastRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) {
  this->Prepared->Initialize();
  const bool one = inputVector[0]->GetNumberOfInformationObjects() == 1;
  vtkDataSet* input = one ? vtkDataSet::GetData(inputVector[0], 0) : nullptr;
  vtkCompositeDataSet* blocks = one && !input ? vtkCompositeDataSet::GetData(inputVector[0], 0) : nullptr;
  // Every leaf block, each with its own tensor array (the same name or
  // attribute), as ParaView's Tensor Glyph draws a composite input.
  std::vector<tg::paraview::Piece> pieces;
  if (blocks) {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(blocks->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      if (auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
        pieces.push_back({leaf, this->GetInputArrayToProcess(0, leaf), it->GetCurrentFlatIndex(), this->MaskOf(leaf)});
  } else {
    pieces.push_back({input, input ? this->GetInputArrayToProcess(0, input) : nullptr, 0, this->MaskOf(input)});
  }
  const tg::paraview::SelectionParams select{this->Stride, this->MaskMin};
  auto* controller = vtkMultiProcessController::GetGlobalController();
  try {
    // Collective over the ranks: every rank runs this, with or without points.
    tg::paraview::LoadReport report;
    this->Prepared->ShallowCopy(tg::paraview::prepareGlyphInput(pieces, blocks != nullptr, controller, &report, select));
    // The counts are the whole dataset's: said once, by the first rank.
    if (!controller || controller->GetLocalProcessId() == 0) reportLoad(this, report, pieces, select);
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
    this->Prepared->Initialize();
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

vtkDataArray* vtkTensorGlyphRayCastRepresentation::MaskOf(vtkDataSet* piece) {
  return this->UseMask && piece ? this->GetInputArrayToProcess(1, piece) : nullptr;
}

int vtkTensorGlyphRayCastRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo) {
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo)) return 0;
  if (request_type == vtkPVView::REQUEST_UPDATE()) {
    vtkPVView::SetPiece(inInfo, this, this->Prepared);
    // The view's bounds (camera reset, clipping range, IceT's per-rank
    // extents) hold the glyphs, not only their centres.
    this->Mapper->SetInputDataObject(this->Prepared);
    double bounds[6];
    this->Mapper->GetBounds(bounds);
    if (vtkMath::AreBoundsInitialized(bounds)) vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds);
  } else if (request_type == vtkPVView::REQUEST_RENDER()) {
    this->Mapper->SetInputConnection(vtkPVRenderView::GetPieceProducer(inInfo, this));
    // Only the representation in use renders: said when the glyphs are drawn.
    auto* controller = vtkMultiProcessController::GetGlobalController();
    const bool cells = this->ColorAssociation != vtkDataObject::FIELD_ASSOCIATION_POINTS;
    // GetLookupTable makes a default table where ParaView set none: asked only with an array chosen.
    const bool categorical = !this->ColorArray.empty() && this->Mapper->GetLookupTable()->GetIndexedLookup();
    if (!this->ColorArray.empty() && (cells || categorical) && this->ColorArray != this->ColorArraySaid &&
        (!controller || controller->GetLocalProcessId() == 0)) {
      vtkWarningMacro(<< "ColorBy: '" << this->ColorArray << "' "
                      << (cells ? "is not a point array; the glyphs stand for points"
                                : "is coloured by categories (Interpret Values As Categories); the glyphs map a range")
                      << ", and keep the colours of TensorGlyphColorMode");
      this->ColorArraySaid = this->ColorArray;
    }
  }
  return 1;
}

void vtkTensorGlyphRayCastRepresentation::SetVisibility(bool val) {
  this->Superclass::SetVisibility(val);
  this->Actor->SetVisibility(val);
}

bool vtkTensorGlyphRayCastRepresentation::AddToView(vtkView* view) {
  auto* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview) return false;
  rview->GetRenderer()->AddActor(this->Actor);
  // Picking and selections find this representation through its actor.
  rview->RegisterPropForHardwareSelection(this, this->Actor);
  return this->Superclass::AddToView(view);
}

bool vtkTensorGlyphRayCastRepresentation::RemoveFromView(vtkView* view) {
  auto* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview) return false;
  rview->GetRenderer()->RemoveActor(this->Actor);
  rview->UnRegisterPropForHardwareSelection(this, this->Actor);
  return this->Superclass::RemoveFromView(view);
}

// The legend follows the colour mode and the data: recomputed on each ask.
const char* vtkTensorGlyphRayCastRepresentation::GetColorLegendTitle() {
  this->LegendTitle = tg::paraview::colorLegend(this->Mapper->GetColorMode(),
                                                tg::paraview::sizingInfo(this->Prepared)).title;
  return this->LegendTitle.c_str();
}

double* vtkTensorGlyphRayCastRepresentation::GetColorLegendRange() {
  const auto legend = tg::paraview::colorLegend(this->Mapper->GetColorMode(), tg::paraview::sizingInfo(this->Prepared));
  this->LegendRange[0] = legend.lo;
  this->LegendRange[1] = legend.hi;
  return this->LegendRange;
}

vtkDoubleArray* vtkTensorGlyphRayCastRepresentation::GetColorLegendRGBPoints() {
  const auto legend = tg::paraview::colorLegend(this->Mapper->GetColorMode(), tg::paraview::sizingInfo(this->Prepared));
  this->LegendPoints->Initialize();
  this->LegendPoints->SetNumberOfTuples(vtkIdType(4 * legend.points.size()));
  for (std::size_t i = 0; i < legend.points.size(); ++i)
    for (std::size_t k = 0; k < 4; ++k) this->LegendPoints->SetValue(vtkIdType(4 * i + k), legend.points[i][k]);
  return this->LegendPoints;
}

// Setters: changing a look needs a render only, never new data.
#define TG_FORWARD(Name, Type)                                                   \
  void vtkTensorGlyphRayCastRepresentation::Set##Name(Type v) {                  \
    this->Mapper->Set##Name(v);                                                  \
  }
TG_FORWARD(GlyphKind, int)
TG_FORWARD(Pipeline, int)
TG_FORWARD(Gamma, double)
TG_FORWARD(FAThreshold, double)
TG_FORWARD(ColorMode, int)
TG_FORWARD(MarchIterations, int)
TG_FORWARD(MarchEpsilon, double)
TG_FORWARD(AmbientOcclusion, bool)
TG_FORWARD(Outlines, bool)
TG_FORWARD(Shadows, bool)
#undef TG_FORWARD

// The view's bounds follow the glyphs' size: a new REQUEST_UPDATE.
#define TG_FORWARD_SIZE(Name, Type)                                              \
  void vtkTensorGlyphRayCastRepresentation::Set##Name(Type v) {                  \
    this->Mapper->Set##Name(v);                                                  \
    this->MarkModified();                                                        \
  }
TG_FORWARD_SIZE(ScaleMode, int)
TG_FORWARD_SIZE(ScaleFactor, double)
TG_FORWARD_SIZE(Magnitude, int)
TG_FORWARD_SIZE(Lambda0, double)
TG_FORWARD_SIZE(ClampDefault, bool)
TG_FORWARD_SIZE(Clamp, double)
#undef TG_FORWARD_SIZE

void vtkTensorGlyphRayCastRepresentation::SetOpacity(double v) {
  if (!(v >= 0.0 && v <= 1.0)) {
    vtkErrorMacro(<< "SetOpacity: Opacity must be within [0, 1]; kept " << this->Actor->GetProperty()->GetOpacity());
    return;
  }
  this->Actor->GetProperty()->SetOpacity(v);
}

void vtkTensorGlyphRayCastRepresentation::SetColorArrayName(int, int, int, int association, const char* name) {
  this->ColorArray = name ? name : "";
  this->ColorAssociation = association;
  this->ColorArraySaid.clear();
  const bool points = association == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  this->Mapper->SetColorArray(points ? this->ColorArray.c_str() : "");
}

void vtkTensorGlyphRayCastRepresentation::SetLookupTable(vtkScalarsToColors* lut) { this->Mapper->SetLookupTable(lut); }

int vtkTensorGlyphRayCastRepresentation::GetRecordUploads() { return this->Mapper->GetRecordUploads(); }
const char* vtkTensorGlyphRayCastRepresentation::GetGlyphPath() { return this->Mapper->GetGlyphPath(); }

// What is selected is new data: RequestData again.
void vtkTensorGlyphRayCastRepresentation::SetStride(int v) {
  if (tg::paraview::acceptValue(this, "SetStride", "TensorGlyphStride", this->Stride, v, tg::app::ranges::kStride))
    this->MarkModified();
}

void vtkTensorGlyphRayCastRepresentation::SetUseMask(bool v) {
  if (this->UseMask == v) return;
  this->UseMask = v;
  this->MarkModified();
}

void vtkTensorGlyphRayCastRepresentation::SetMaskMin(double v) {
  if (tg::paraview::acceptValue(this, "SetMaskMin", "TensorGlyphMaskMin", this->MaskMin, v, tg::app::ranges::kAnyFloat))
    this->MarkModified();
}

void vtkTensorGlyphRayCastRepresentation::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
