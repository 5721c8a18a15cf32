// The mapper behind "Tensor Glyphs (ray cast)": draws tensorglyph's exact
// ray-cast glyphs (src/render) into the host's framebuffer, with depth in the
// host's convention, so that they mix with ParaView's other geometry.
//
// Input: the points that glyph_input.h prepares (a vtkPolyData with float
// points, the "tg_tensor6" and "tg_ids" point arrays and the "tg_scale_sample"
// field array). Only VTK types appear here: the header is wrapped for
// ParaView's client-server layer.
#ifndef vtkTensorGlyphRayCastMapper_h
#define vtkTensorGlyphRayCastMapper_h

#include <memory>

#include "TensorGlyphRayCastRepresentationsModule.h"
#include "vtkMapper.h"

class TENSORGLYPHRAYCASTREPRESENTATIONS_EXPORT vtkTensorGlyphRayCastMapper : public vtkMapper
{
public:
  static vtkTensorGlyphRayCastMapper* New();
  vtkTypeMacro(vtkTensorGlyphRayCastMapper, vtkMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Glyph kind: 0 ellipsoid, 1 superquadric, 2 cylinder, 3 box.
  vtkSetClampMacro(GlyphKind, int, 0, 3);
  vtkGetMacro(GlyphKind, int);
  // The double setters clamp as vtkSetClampMacro would, but ignore a NaN
  // (keeping the old value), which the macro stores: every comparison with
  // NaN is false.
  void SetGamma(double v);
  vtkGetMacro(Gamma, double);
  // Scale mode: 0 absolute, 1 max, 2 spacing (tensor::ScaleMode).
  vtkSetClampMacro(ScaleMode, int, 0, 2);
  vtkGetMacro(ScaleMode, int);
  void SetScaleFactor(double v);
  vtkGetMacro(ScaleFactor, double);
  void SetFAThreshold(double v);
  vtkGetMacro(FAThreshold, double);
  // Colour mode: 0 DEC, 1 FA, 2 MD, 3 cl, 4 cp, 5 sign (render::ColorMode).
  vtkSetClampMacro(ColorMode, int, 0, 5);
  vtkGetMacro(ColorMode, int);
  vtkSetClampMacro(MarchIterations, int, 1, 1000);
  vtkGetMacro(MarchIterations, int);
  void SetMarchEpsilon(double v);
  vtkGetMacro(MarchEpsilon, double);
  // The renderer's deferred depth cues (render/ao_pass.h, outline_pass.h,
  // shadow_pass.h), off by default as in the CLI.
  vtkSetMacro(AmbientOcclusion, bool);
  vtkGetMacro(AmbientOcclusion, bool);
  vtkSetMacro(Outlines, bool);
  vtkGetMacro(Outlines, bool);
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);

  void Render(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;
  // The glyph centres' bounds grown by the largest glyph's reach.
  double* GetBounds() override;
  using vtkMapper::GetBounds;
  bool HasOpaqueGeometry() override { return true; }
  bool HasTranslucentPolygonalGeometry() override { return false; }

  // World units per eigenvalue unit of the last resolved scale (for tests).
  double GetResolvedScale();
  // Milliseconds the last glyph build (eigen-decomposition) took.
  vtkGetMacro(LastBuildMilliseconds, double);

protected:
  vtkTensorGlyphRayCastMapper();
  ~vtkTensorGlyphRayCastMapper() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  int GlyphKind = 0;
  double Gamma = 3.0;
  int ScaleMode = 2;
  double ScaleFactor = 1.0;
  double FAThreshold = 0.0;
  int ColorMode = 0;
  int MarchIterations = 10;
  double MarchEpsilon = 1e-4;
  bool AmbientOcclusion = false;
  bool Outlines = false;
  bool Shadows = false;
  double LastBuildMilliseconds = 0.0;

private:
  vtkTensorGlyphRayCastMapper(const vtkTensorGlyphRayCastMapper&) = delete;
  void operator=(const vtkTensorGlyphRayCastMapper&) = delete;
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
