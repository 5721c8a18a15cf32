"""VTK's own tensor glyphs for tests/bench/peers.sh: vtkTensorGlyph with the
tessellated source ParaView's TensorGlyph draws, on a VTK XML image, through a
VTK render window (run it under Xvfb), with the camera and glyph size given
explicitly so that tensorglyph can draw the same.

usage: peer_vtk_glyph.py IN.vti W H EYE(3) LOOKAT(3) UP(3) FOV SCALE CLAMP RES SOURCE OUT_MASK.png
  SCALE: world size per unit eigenvalue of a glyph's semi-axis (tensorglyph's
  --scale in absolute mode); CLAMP: largest glyph diameter, world units (0: off);
  SOURCE: sphere (vtkSphereSource, RES x RES: an ellipsoid per glyph, the shape
  of tensorglyph's --glyph ellipsoid) or superquadric (vtkSuperquadricSource,
  RES x RES, as ParaView's TensorGlyph sets it up: toroidal, roundness 1, so one
  torus shape for every glyph; not Kindlmann's superquadric, whose shape
  follows each tensor's anisotropy).
Prints "build_s first_frame_s frame_s" on stdout; writes the
coverage mask (255 where the depth buffer holds a glyph) as an upright PNG.
Run with Debian's /usr/bin/python3 (python3-vtk9).
"""
import sys
import time

from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkFiltersCore import vtkTensorGlyph
from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkSuperquadricSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkImagingCore import vtkImageShiftScale
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer, vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory overrides)

a = sys.argv[1:]
if len(a) != 18 or a[16] not in ("sphere", "superquadric"):
    sys.exit(__doc__)
path, w, h = a[0], int(a[1]), int(a[2])
eye, look, up = [float(x) for x in a[3:6]], [float(x) for x in a[6:9]], [float(x) for x in a[9:12]]
fov, scale, clamp, res, kind, out = float(a[12]), float(a[13]), float(a[14]), int(a[15]), a[16], a[17]

t0 = time.perf_counter()
reader = vtkXMLImageDataReader()
reader.SetFileName(path)
# Both sources have radius 0.5.
if kind == "sphere":
    source = vtkSphereSource()
else:
    source = vtkSuperquadricSource()
    # ParaView's proxy (and so its TensorGlyph) defaults to a toroidal source;
    # VTK's own class does not.
    source.ToroidalOn()
    source.SetThetaRoundness(1.0)
    source.SetPhiRoundness(1.0)
    source.SetThickness(0.3333)
source.SetThetaResolution(res)
source.SetPhiResolution(res)
glyph = vtkTensorGlyph()
glyph.SetInputConnection(reader.GetOutputPort())
glyph.SetSourceConnection(source.GetOutputPort())
glyph.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "tensors")
glyph.ExtractEigenvaluesOn()
glyph.ColorGlyphsOn()
glyph.SetColorModeToEigenvalues()
# The source's radius is 0.5: a semi-axis of SCALE * |eigenvalue| needs twice that factor.
glyph.SetScaleFactor(2.0 * scale)
glyph.SetClampScaling(clamp > 0)
glyph.SetMaxScaleFactor(clamp)
glyph.Update()
t1 = time.perf_counter()

mapper = vtkPolyDataMapper()
mapper.SetInputConnection(glyph.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
ren = vtkRenderer()
ren.AddActor(actor)
ren.SetBackground(0, 0, 0)
win = vtkRenderWindow()
win.SetOffScreenRendering(1)
win.AddRenderer(ren)
win.SetSize(w, h)
cam = ren.GetActiveCamera()
cam.SetPosition(*eye)
cam.SetFocalPoint(*look)
cam.SetViewUp(*up)
cam.SetViewAngle(fov)  # vertical, as tensorglyph's --fov
ren.ResetCameraClippingRange()
win.Render()
t2 = time.perf_counter()
win.Render()  # the same frame again: the per-frame cost, without building the buffers
t3 = time.perf_counter()

grab = vtkWindowToImageFilter()
grab.SetInput(win)
grab.SetInputBufferTypeToZBuffer()
grab.ReadFrontBufferOff()
grab.Update()
# Depth 1 is empty: mask = 255 * (depth < 1), as (1 - depth) scaled up and clamped.
mask = vtkImageShiftScale()
mask.SetInputConnection(grab.GetOutputPort())
mask.SetShift(-1.0)
mask.SetScale(-1e9)
mask.SetOutputScalarTypeToUnsignedChar()
mask.ClampOverflowOn()
mask.Update()
img = mask.GetOutput()
png = vtkPNGWriter()
png.SetInputData(img)
png.SetFileName(out)
png.Write()
print(f"{t1 - t0:.3f} {t2 - t1:.3f} {t3 - t2:.3f}")
