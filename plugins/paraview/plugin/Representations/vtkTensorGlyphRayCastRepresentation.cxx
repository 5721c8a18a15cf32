#include "vtkTensorGlyphRayCastRepresentation.h"

#include <exception>

#include <vtkActor.h>
#include <vtkAlgorithmOutput.h>
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

#include "color_legend.h"
#include "glyph_input.h"
#include "vtkTensorGlyphRayCastMapper.h"

vtkStandardNewMacro(vtkTensorGlyphRayCastRepresentation);

vtkTensorGlyphRayCastRepresentation::vtkTensorGlyphRayCastRepresentation() {
  this->Actor->SetMapper(this->Mapper);
  // The active tensors unless the user picks another point array.
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::TENSORS);
}

vtkTensorGlyphRayCastRepresentation::~vtkTensorGlyphRayCastRepresentation() = default;

vtkTensorGlyphRayCastMapper* vtkTensorGlyphRayCastRepresentation::GetMapper() { return this->Mapper; }

int vtkTensorGlyphRayCastRepresentation::FillInputPortInformation(int, vtkInformation* info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  // Accepted so that RequestData can say what to do: refused by the
  // pipeline, a multiblock input drew nothing with an error about ports.
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkTensorGlyphRayCastRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector) {
  this->Prepared->Initialize();
  vtkDataSet* input =
    inputVector[0]->GetNumberOfInformationObjects() == 1 ? vtkDataSet::GetData(inputVector[0], 0) : nullptr;
  vtkDataArray* tensors = input ? this->GetInputArrayToProcess(0, input) : nullptr;
  if (!input && vtkCompositeDataSet::GetData(inputVector[0], 0)) {
    // One id per point of one dataset (picking, the spreadsheet): blocks
    // would need a block index as well.
    vtkErrorMacro(<< "RequestData: a composite (multiblock) dataset; apply Merge Blocks and show its output");
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  try {
    // Collective over the ranks: every rank runs this, with or without points.
    std::size_t skipped = 0;
    this->Prepared->ShallowCopy(tg::paraview::prepareGlyphInput(
      input, tensors, vtkMultiProcessController::GetGlobalController(), &skipped));
    // As the CLI says it: points left out are not drawn without a word.
    if (skipped > 0)
      vtkWarningMacro(<< "prepareGlyphInput: array '" << (tensors && tensors->GetName() ? tensors->GetName() : "")
                      << "': skipped " << skipped
                      << " points whose tensors have NaN/Inf components or overflow single precision");
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
    this->Prepared->Initialize();
  }
  return this->Superclass::RequestData(request, inputVector, outputVector);
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
void vtkTensorGlyphRayCastRepresentation::SetScaleMode(int v) {
  this->Mapper->SetScaleMode(v);
  this->MarkModified();
}

void vtkTensorGlyphRayCastRepresentation::SetScaleFactor(double v) {
  this->Mapper->SetScaleFactor(v);
  this->MarkModified();
}

void vtkTensorGlyphRayCastRepresentation::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
