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
#include <string>

#include "TensorGlyphRayCastRepresentationsModule.h"
#include "vtkMapper.h"

class TENSORGLYPHRAYCASTREPRESENTATIONS_EXPORT vtkTensorGlyphRayCastMapper : public vtkMapper
{
public:
  static vtkTensorGlyphRayCastMapper* New();
  vtkTypeMacro(vtkTensorGlyphRayCastMapper, vtkMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Every setter refuses a value the command line refuses (the ranges of
  // src/app/scale/option_ranges.h, the kinds of render/glyph_kind.h): it says so
  // in the command line's words (vtkErrorMacro: ParaView's output messages)
  // and keeps the value held. A NaN is refused too.
  // Glyph kind: the row of render::glyphKinds() (0 ellipsoid, 1 superquadric,
  // 2 cylinder, 3 box).
  void SetGlyphKind(int v);
  vtkGetMacro(GlyphKind, int);
  void SetGamma(double v);
  vtkGetMacro(Gamma, double);
  // Scale mode: 0 absolute, 1 max, 2 spacing (tensor::ScaleMode).
  void SetScaleMode(int v);
  vtkGetMacro(ScaleMode, int);
  void SetScaleFactor(double v);
  vtkGetMacro(ScaleFactor, double);
  // The CLI's --magnitude (0 linear, 1 log, 2 shape: tensor::Magnitude) and
  // --lambda0 (0: the median magnitude, the CLI's default).
  void SetMagnitude(int v);
  vtkGetMacro(Magnitude, int);
  void SetLambda0(double v);
  vtkGetMacro(Lambda0, double);
  // The CLI's --clamp in sample spacings, 0 off; with ClampDefault on (the
  // default) the CLI's default instead: 2 in the spacing and max modes, off
  // in absolute mode.
  vtkSetMacro(ClampDefault, bool);
  vtkGetMacro(ClampDefault, bool);
  void SetClamp(double v);
  vtkGetMacro(Clamp, double);
  void SetFAThreshold(double v);
  vtkGetMacro(FAThreshold, double);
  // Colour mode: 0 DEC, 1 FA, 2 MD, 3 cl, 4 cp, 5 sign (render::ColorMode).
  void SetColorMode(int v);
  vtkGetMacro(ColorMode, int);
  void SetMarchIterations(int v);
  vtkGetMacro(MarchIterations, int);
  void SetMarchEpsilon(double v);
  vtkGetMacro(MarchEpsilon, double);
  // The glyph path (the CLI's --pipeline): 0 raster, 1 cpu (tiles cast on
  // every core), 2 auto (the path a calibration of this machine predicts
  // faster, app/scale/pipeline_choice.h). A change draws the next frame on
  // the new path, its records uploaded again.
  void SetPipeline(int v);
  vtkGetMacro(Pipeline, int);
  // The path the last frame drew on ("raster", "cpu", "compute"; "" before a frame).
  const char* GetGlyphPath() { return this->GlyphPath.c_str(); }
  // The renderer's deferred depth cues (render/ao_pass.h, outline_pass.h,
  // shadow_pass.h), off by default as in the CLI.
  vtkSetMacro(AmbientOcclusion, bool);
  vtkGetMacro(AmbientOcclusion, bool);
  vtkSetMacro(Outlines, bool);
  vtkGetMacro(Outlines, bool);
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);

  // ParaView's ColorBy: the point array (of the input's, by name; empty:
  // none) coloured through the mapper's LookupTable (vtkMapper's, the
  // display's), in place of ColorMode's colours: the table's own colours
  // and range, so that the glyphs show the scalar bar's colours. A new
  // array, range or preset uploads no glyph records.
  void SetColorArray(const char* name);
  const char* GetColorArray() { return this->ColorArray.c_str(); }
  // Whether the last frame coloured by ColorArray through the lookup table.
  vtkGetMacro(ColoredByArray, bool);
  // Glyph record uploads since construction (for tests: a colour change must not add one).
  int GetRecordUploads();

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
  int Pipeline = 0;
  std::string GlyphPath;
  double Gamma = 3.0;
  int ScaleMode = 2;
  double ScaleFactor = 1.0;
  int Magnitude = 0;
  double Lambda0 = 0.0;
  bool ClampDefault = true;
  double Clamp = 2.0;
  double FAThreshold = 0.0;
  int ColorMode = 0;
  int MarchIterations = 10;
  double MarchEpsilon = 1e-4;
  bool AmbientOcclusion = false;
  bool Outlines = false;
  bool Shadows = false;
  double LastBuildMilliseconds = 0.0;
  std::string ColorArray;
  bool ColoredByArray = false;

private:
  vtkTensorGlyphRayCastMapper(const vtkTensorGlyphRayCastMapper&) = delete;
  void operator=(const vtkTensorGlyphRayCastMapper&) = delete;
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
