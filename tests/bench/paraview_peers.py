"""ParaView's TensorGlyph filter against the plugin's "Tensor Glyphs (ray
cast)", in one pvbatch run per shape, on the same data and camera. A
benchmark, not a test. Each run compares like with like (--shape):

  ellipsoid     the plugin's exact ellipsoids against the filter's Sphere
                source, 16 x 16: an ellipsoid per glyph, the same shape;
  superquadric  the plugin's Kindlmann superquadrics (gamma 3, each glyph's
                shape from its anisotropy) against the filter's Superquadric
                source as ParaView sets it up (toroidal, roundness 1: one
                torus shape for every glyph). ParaView has no Kindlmann
                glyph; this is what its "Superquadric" option draws, a
                different shape, so its coverage error measures the shape.

  PYTHONPATH=/opt/tg-paraview-python/usr/lib/python3/dist-packages \\
  xvfb-run -a pvbatch tests/bench/paraview_peers.py --plugin SO --cli build/tensorglyph \\
      --shape ellipsoid|superquadric [--input FILE] [--frames N] [--size W H] [--out DIR]

Per renderer: build time and first frames together (from creating the
filter or representation to the first picture at the benchmark's camera: the
plugin builds its glyphs inside its update and first frame), median frame of N (the camera turns
a degree between frames), resident memory it added (VmRSS; llvmpipe keeps
GPU buffers in host memory), and coverage error: the share of the reference's
glyph pixels whose coverage (glyph or background) differs, plus those covered
only by the renderer. The reference is the CLI's picture of the same glyphs
in the plugin's shape (tensorglyph render, exact ray casts: the project's
tests hold it to src/ref). Prints a table naming each side's shape, with
ratios filter / plugin. One shape per process: a second filter's memory
would hide in the first one's freed pages.
"""
import argparse
import os
import statistics
import subprocess
import time

from paraview import simple
from vtkmodules.vtkIOImage import vtkPNGReader

EYE, AT, UP, FOV = [40, 70, 170], [-1.5, 41.8, 5.6], [0, 1, 0], 30.0
BG = [0.08, 0.08, 0.10]
# Per shape: the CLI's glyph options, the plugin's kind (its TensorGlyphKind
# enumeration), ParaView's glyph type and how each side's shape is named.
SHAPES = {
    "ellipsoid": (["--glyph", "ellipsoid"], 0, "Sphere",
                  "plugin: exact ellipsoids", "ParaView TensorGlyph: Sphere source 16x16 (ellipsoids)"),
    "superquadric": (["--glyph", "superquadric", "--gamma", "3"], 1, "Superquadric",
                     "plugin: Kindlmann superquadrics (gamma 3)",
                     "ParaView TensorGlyph: Superquadric source 16x16 (one torus shape, not Kindlmann's)"),
}


def rss_mib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return 0.0


def coverage(path):
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    s = r.GetOutput().GetPointData().GetScalars()
    bg = [round(255 * c) for c in BG]
    return [any(abs(s.GetComponent(i, c) - bg[c]) > 1.5 for c in range(3)) for i in range(s.GetNumberOfTuples())]


def coverage_error(ref, got):
    wrong = sum(1 for a, b in zip(ref, got) if a != b)
    return wrong / max(1, sum(ref))


def make_view(size):
    view = simple.CreateRenderView()
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = BG
    return view


def place_camera(view):
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp, view.CameraViewAngle = EYE, AT, UP, FOV


def frames(view, n):
    times = []
    for _ in range(n):
        view.GetActiveCamera().Azimuth(1.0)
        t = time.perf_counter()
        simple.Render(view)
        times.append(1000 * (time.perf_counter() - t))
    return statistics.median(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--shape", required=True, choices=sorted(SHAPES))
    ap.add_argument("--input", default=os.path.join(os.path.dirname(__file__),
                                                   "../../../shared/data/real/tsv-kitten-stress/kitten-stress.vtu"))
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--size", type=int, nargs=2, default=[400, 300])
    ap.add_argument("--out", default="/tmp/tg_paraview_peers")
    a = ap.parse_args()
    cli_glyph, plugin_kind, pv_type, plugin_name, filter_name = SHAPES[a.shape]
    os.makedirs(a.out, exist_ok=True)
    simple.LoadPlugin(a.plugin, remote=False, ns=globals())
    reader = simple.OpenDataFile(a.input)
    reader.UpdatePipeline()
    cam = ["--eye"] + [str(v) for v in EYE] + ["--look-at"] + [str(v) for v in AT] + ["--fov", str(FOV)]
    size = ["--size", str(a.size[0]), str(a.size[1])]
    ref_png = os.path.join(a.out, a.shape + "-reference.png")
    # Absolute scale, no clamp: vtkTensorGlyph's own sizing (eigenvalues times
    # ScaleFactor, the diameter per eigenvalue unit, as --scale-mode absolute
    # and the plugin's absolute mode take it).
    scale = 0.0178
    subprocess.run([a.cli, "render", a.input, "-o", ref_png] + cli_glyph +
                   ["--scale-mode", "absolute", "--scale", str(scale)] + size + cam, check=True)
    ref = coverage(ref_png)

    # The plugin first, so that the filter's freed memory does not hide its own.
    # The plugin: its glyph build happens in the first frame.
    view = make_view(a.size)
    rss0 = rss_mib()
    t = time.perf_counter()
    disp = simple.Show(reader, view)
    disp.SetRepresentationType("Tensor Glyphs (ray cast)")
    disp.TensorGlyphKind = plugin_kind
    disp.TensorGlyphGamma = 3.0
    disp.TensorGlyphScaleMode = 0
    disp.TensorGlyphScaleFactor = scale
    simple.Render(view)
    place_camera(view)
    simple.Render(view)
    first = 1000 * (time.perf_counter() - t)
    png = os.path.join(a.out, a.shape + "-plugin.png")
    simple.SaveScreenshot(png, view, ImageResolution=a.size)
    # The plugin's classes have no Python wrapping: its glyph build (the
    # representation's input preparation and the mapper's eigen-decomposition)
    # is inside its update and first frame, reported together.
    median = frames(view, a.frames)
    plugin_row = (first, median, rss_mib() - rss0, coverage_error(ref, coverage(png)))
    simple.Delete(disp)
    simple.Delete(view)

    # ParaView's own filter: one copy of the source per point, on the CPU.
    view = make_view(a.size)
    rss0 = rss_mib()
    t = time.perf_counter()
    glyphs = simple.TensorGlyph(Input=reader, GlyphType=pv_type)
    glyphs.Tensors = ["POINTS", "stress"]
    glyphs.GlyphType.ThetaResolution = 16
    glyphs.GlyphType.PhiResolution = 16
    # Both sources have radius 0.5: ScaleFactor is the diameter per
    # eigenvalue unit, the factor the CLI and the plugin were given. The
    # superquadric source keeps ParaView's settings (Toroidal 1, roundness 1,
    # thickness 0.3333): what a user choosing "Superquadric" gets.
    glyphs.ScaleFactor = scale
    glyphs.UpdatePipeline()
    build = 1000 * (time.perf_counter() - t)
    disp = simple.Show(glyphs, view)
    simple.ColorBy(disp, None)
    t = time.perf_counter()
    simple.Render(view)
    place_camera(view)
    simple.Render(view)
    first = 1000 * (time.perf_counter() - t)
    png = os.path.join(a.out, a.shape + "-filter.png")
    simple.SaveScreenshot(png, view, ImageResolution=a.size)
    median = frames(view, a.frames)
    filter_row = (build + first, median, rss_mib() - rss0, coverage_error(ref, coverage(png)))

    print("reference: tensorglyph render %s (%d glyph pixels); load average %s" %
          (" ".join(cli_glyph), sum(ref), " ".join(open("/proc/loadavg").read().split()[:3])))
    print("%-84s %16s %10s %10s %9s" % ("renderer (shape it draws)", "build+first ms", "frame ms", "RSS MiB", "cov err"))
    for name, (f, m, r, c) in [(filter_name, filter_row), (plugin_name, plugin_row)]:
        print("%-84s %16.1f %10.1f %10.1f %8.2f%%" % (name, f, m, r, 100 * c))
    ratio = lambda x, y: x / y if y > 0 else float("inf")
    print("%-84s %15.1fx %9.1fx %9.1fx" % ("ratio filter / plugin", ratio(filter_row[0], plugin_row[0]),
                                         ratio(filter_row[1], plugin_row[1]), ratio(filter_row[2], plugin_row[2])))


if __name__ == "__main__":
    main()
