// "Tensor Glyphs (ray cast)": a representation for any dataset with point
// tensors. Each rank turns its own piece into the mapper's input
// (glyph_input.h) and draws it; in a distributed view IceT composites the
// ranks' images by depth.
#ifndef vtkTensorGlyphRayCastRepresentation_h
#define vtkTensorGlyphRayCastRepresentation_h

#include <string>

#include "TensorGlyphRayCastRepresentationsModule.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkPVDataRepresentation.h"

class vtkActor;
class vtkDataArray;
class vtkDataSet;
class vtkPolyData;
class vtkScalarsToColors;
class vtkTensorGlyphRayCastMapper;

class TENSORGLYPHRAYCASTREPRESENTATIONS_EXPORT vtkTensorGlyphRayCastRepresentation
  : public vtkPVDataRepresentation
{
public:
  static vtkTensorGlyphRayCastRepresentation* New();
  vtkTypeMacro(vtkTensorGlyphRayCastRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;
  void SetVisibility(bool val) override;

  // The mapper's settings (vtkTensorGlyphRayCastMapper.h), forwarded.
  void SetGlyphKind(int v);
  void SetPipeline(int v);
  const char* GetGlyphPath();
  void SetGamma(double v);
  void SetScaleMode(int v);
  void SetScaleFactor(double v);
  void SetMagnitude(int v);
  void SetLambda0(double v);
  void SetClampDefault(bool v);
  void SetClamp(double v);
  // The CLI's --stride, and --mask/--mask-min with a point array of the
  // input as the mask (input array 1; glyph_input.h's SelectionParams).
  void SetStride(int v);
  void SetUseMask(bool v);
  void SetMaskMin(double v);
  void SetFAThreshold(double v);
  void SetColorMode(int v);
  void SetMarchIterations(int v);
  void SetMarchEpsilon(double v);
  void SetAmbientOcclusion(bool v);
  void SetOutlines(bool v);
  void SetShadows(bool v);
  // The GeometryRepresentation's Opacity, forwarded to every subproxy: below
  // 1 the glyphs' nearest surface is blended over what ParaView drew behind
  // it, after its opaque and translucent passes (GlyphActor in the .cxx).
  void SetOpacity(double v);
  // The GeometryRepresentation's ColorArrayName (ParaView's ColorBy) and
  // LookupTable, shared likewise: a point array colours the glyphs through
  // that table (vtkTensorGlyphRayCastMapper::SetColorArray); none ("Solid
  // Color") leaves them ColorMode's colours. A cell array or a categorical
  // table is said not to apply.
  void SetColorArrayName(int idx, int port, int connection, int association, const char* name);
  void SetLookupTable(vtkScalarsToColors* lut);
  // Glyph record uploads of the mapper (for tests).
  int GetRecordUploads();

  vtkTensorGlyphRayCastMapper* GetMapper();

  // The colour legend of the current colour mode over the whole dataset, as
  // the glyphs are drawn (color_legend.h), for ParaView's lookup table and
  // scalar bar: the mapped quantity's name (empty for DEC), its range, and
  // the colormap as RGBPoints (value r g b per control point).
  const char* GetColorLegendTitle();
  double* GetColorLegendRange() VTK_SIZEHINT(2);
  vtkDoubleArray* GetColorLegendRGBPoints();

protected:
  vtkTensorGlyphRayCastRepresentation();
  ~vtkTensorGlyphRayCastRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;
  // The mask array of a piece when UseMask is on, else null.
  vtkDataArray* MaskOf(vtkDataSet* piece);

  vtkNew<vtkTensorGlyphRayCastMapper> Mapper;
  vtkSmartPointer<vtkActor> Actor;
  vtkNew<vtkPolyData> Prepared;
  std::string LegendTitle;
  double LegendRange[2] = {0.0, 1.0};
  vtkNew<vtkDoubleArray> LegendPoints;
  int Stride = 1;
  bool UseMask = false;
  double MaskMin = 0.5;
  std::string ColorArray;  // ParaView's ColorBy array, or empty
  int ColorAssociation = 0;  // vtkDataObject::FIELD_ASSOCIATION_*
  std::string ColorArraySaid;  // the one last said not to apply

private:
  vtkTensorGlyphRayCastRepresentation(const vtkTensorGlyphRayCastRepresentation&) = delete;
  void operator=(const vtkTensorGlyphRayCastRepresentation&) = delete;
};

#endif
