"""Every keyword of the option table against every kind of input the module
takes (issue 30): a file path, a volume array, an array of points. Each is
applied as the CLI applies it to the same data, or refused naming it; none
is taken and dropped. Run by ctest with Debian's python3 (TG_CLI: the CLI)."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

import tensorglyph as tg

CLI = os.environ.get("TG_CLI", "")
SIZE = (96, 72)

# keyword -> (value, the keywords it needs to show: its companions)
SQ = {"glyph": "superquadric"}
UNDERLAY = {"underlay": "@underlay"}
MESH = {"mesh": "@mesh"}
TRACTS = {"tracts": "@tracts"}
CASES = {
    "size": ((64, 48), {}),
    "glyph": ("superquadric", {}),
    "iterations": (1, SQ),
    "epsilon": (0.4, SQ),
    "stats": (True, SQ),
    "gamma": (0.5, SQ),
    "blob_threshold": (0.7, {"glyph": "blob"}),
    "blobbiness": (-1.0, {"glyph": "blob"}),
    "blob_cutoff": (0.1, {"glyph": "blob"}),
    "blob_steps": (1, {"glyph": "blob"}),
    "samples": (4, {}),
    "fa_min": (0.85, {}),
    "eye": ((30.0, -20.0, 25.0), {}),
    "look_at": ((0.0, 0.0, 0.0), {"eye": (30.0, -20.0, 25.0)}),
    "up": ((1.0, 0.0, 0.0), {"eye": (30.0, -20.0, 25.0)}),
    "fov": (10.0, {}),
    "ortho": (3.0, {}),
    "view": ("left", {}),
    "radiological": (True, {}),
    "neurological": (True, {"view": "coronal"}),
    "orientation_letters": ("on", {}),
    "color": ("fa", {}),
    "colormap": ("gray", {"color": "md"}),
    "color_range": ((0.2, 0.4), {"color": "fa"}),
    "color_array": ("@mask", {}),  # a scalar volume on the volumes' grid
    "background": ((1.0, 0.0, 0.0, 1.0), {}),
    "array": ("other", {}),
    "layout": ("mrtrix", {}),
    "frame": ("world", {}),
    "tensor_axes": ("-x,y,z", {}),
    "mask": ("@mask", {}),
    "mask_min": (0.8, {"mask": "@mask"}),
    "confidence_min": (0.3, {}),
    "slice": ("z:1", {}),
    "stride": (2, {}),
    "roi": ((0.0, 0.0, 0.0, 3.0, 3.0, 3.0), {}),
    "cl_min": (0.2, {}),
    "cp_min": (0.2, {}),
    "min_eigenvalue": (1.5, {}),
    "scale": (0.2, {}),
    "scale_mode": ("max", {}),
    "magnitude": ("shape", {}),
    "lambda0": (3.0, {"magnitude": "log"}),
    "clamp": (0.3, {}),
    "underlay": ("@underlay", {}),
    "plane": ("x:1", UNDERLAY),
    "plane_at": ((2.0, 2.0, 2.0, 1.0, 0.0, 0.0), UNDERLAY),
    "underlay_colormap": ("viridis", UNDERLAY),
    "underlay_window": ((0.2, 0.3), UNDERLAY),
    "underlay_percentiles": ((40.0, 60.0), UNDERLAY),
    "underlay_nearest": (True, UNDERLAY),
    "plane_offset": (0.0, UNDERLAY),
    "mesh": ("@mesh", {}),
    "mesh_from_input": (True, {}),
    "mesh_mode": ("edges", MESH),
    "mesh_color": ((1.0, 0.0, 0.0), MESH),
    "mesh_opacity": (0.1, {"mesh": "@mesh", "mesh_mode": "see-through"}),
    "mesh_feature_angle": (120.0, {"mesh": "@mesh", "mesh_mode": "edges"}),
    "tracts": ("@tracts", {}),
    "tract_color": ((1.0, 0.0, 0.0), TRACTS),
    "tract_width": (1.5, TRACTS),
    "legend": (True, {}),
    "legend_corner": ("top-left", {"legend": True}),
    "units": ("MPa", {"legend": True, "color": "md", "size": (320, 240)}),
    "length_units": ("mm", {"legend": True, "size": (320, 240)}),
    "legend_text_scale": (3, {"legend": True, "size": (320, 240)}),
    "ao": (True, {}),
    "ao_radius": (8.0, {"ao": True}),
    "ao_strength": (4.0, {"ao": True}),
    "ao_samples": (4, {"ao": True}),
    "outlines": (True, {}),
    "outline_width": (6.0, {"outlines": True}),
    "outline_color": ((1.0, 0.0, 0.0, 1.0), {"outlines": True}),
    "outline_crease": (2.0, {"outlines": True}),
    "shadows": (True, {}),
    "shadow_penumbra": (0.05, {"shadows": True}),
    "shadow_map_size": (64, {"shadows": True}),
    "shadow_strength": (0.05, {"shadows": True}),
    "shadow_bias": (64.0, {"shadows": True}),
    "no_shadows": (True, {}),
    "no_ao": (True, {}),
    "no_legend": (True, {}),
    "no_outlines": (True, {}),
    "tessellate": (6, SQ),
    "backend": ("egl", {}),
    "pipeline": ("cpu", {"glyph": "ellipsoid"}),
    "sizes_from": ("selection", {"roi": (0.0, 0.0, 0.0, 3.0, 3.0, 3.0)}),
}
# Applied without a visible change, by design: statistics on stderr, the
# built-in scene's look switched off (these inputs have none), the default
# stated, another GL back end drawing the same pixels.
# neurological is the default convention; orientation_letters="on" is the
# default for the anatomical inputs (NIfTI, a volume with its affine) and
# changes the others: test_views checks where letters are drawn. The cpu
# pipeline draws the raster path's pixels (tests/gl/test_cpu_glyphs.cpp);
# blob_steps samples the same surface more or less densely, which finds the
# same pixels where the coarser sampling finds them.
NO_VISIBLE_CHANGE = {"stats", "no_shadows", "no_ao", "no_legend", "no_outlines", "backend", "neurological",
                     "orientation_letters", "pipeline", "blob_steps"}
# Where an array of points and a .vtu of the same points differ by design:
# the file names its arrays and holds the cells of a mesh; arrays do neither.
POINTS_DIFFER_FROM_VTU = {"array", "mesh_from_input"}


def _flag_args(kw, value):
    flag, names, _, _ = tg.options()[kw]
    if not names:
        return [flag] if value else []
    values = value if isinstance(value, (tuple, list)) else (value,)
    return [flag] + [str(v) for v in values]


class Data:
    """One field as a NIfTI volume (and its array), one point set as a .vtu
    (and its arrays), a mask and an underlay on the volume's grid, a mesh, tracts."""

    def __init__(self, d):
        import nibabel as nib
        import vtk
        from vtk.util.numpy_support import numpy_to_vtk
        rng = np.random.default_rng(11)
        self.dir = d
        L = rng.normal(size=(4, 4, 3, 3, 3)) * 0.5 + np.eye(3) * [1.5, 0.8, 0.3]
        D = (L @ np.swapaxes(L, -1, -2)).astype(np.float32)
        self.volume = np.stack([D[..., 0, 0], D[..., 0, 1], D[..., 0, 2], D[..., 1, 1], D[..., 1, 2], D[..., 2, 2]],
                               -1).astype(np.float32)
        self.affine = np.diag([2.0, 2.0, 2.0, 1.0])
        self.nifti = os.path.join(d, "dt.nii")
        nib.save(nib.Nifti1Image(self.volume, self.affine), self.nifti)
        grid = np.indices((4, 4, 3)).transpose(1, 2, 3, 0).astype(np.float32)
        self.files = {"@mask": os.path.join(d, "mask.nii"), "@underlay": os.path.join(d, "underlay.nii"),
                      "@mesh": os.path.join(d, "mesh.obj"), "@tracts": os.path.join(d, "tracts.tck")}
        nib.save(nib.Nifti1Image((grid[..., 0] + grid[..., 1]) / 6.0, self.affine), self.files["@mask"])
        nib.save(nib.Nifti1Image(grid[..., 0] * 0.1 + grid[..., 2] * 0.05 + grid[..., 1] * 0.02, self.affine),
                 self.files["@underlay"])
        self._write_mesh(self.files["@mesh"])
        # Two streamlines across the field, in its world (RAS+ mm).
        t = np.linspace(0.0, 1.0, 20)[:, None]
        lines = [(np.array([0.0, 1.0, 2.0]) + t * [6.0, 4.0, 0.0]).astype(np.float32),
                 (np.array([3.0, 0.0, 1.0]) + t * [0.0, 6.0, 3.0]).astype(np.float32)]
        nib.streamlines.save(nib.streamlines.Tractogram(lines, affine_to_rasmm=np.eye(4)), self.files["@tracts"])
        n = 40
        M = rng.normal(size=(n, 3, 3)) * 0.5 + np.eye(3) * [1.5, 0.8, 0.3]
        self.tensors = (M @ np.swapaxes(M, 1, 2)).astype(np.float32)
        self.positions = rng.uniform(0, 6, (n, 3)).astype(np.float32)
        ug = vtk.vtkUnstructuredGrid()
        pts = vtk.vtkPoints()
        pts.SetData(numpy_to_vtk(self.positions, deep=1))
        ug.SetPoints(pts)
        for c in range(0, n - 3, 4):
            ug.InsertNextCell(vtk.VTK_TETRA, 4, [c, c + 1, c + 2, c + 3])
        arr = numpy_to_vtk(self.tensors.reshape(-1, 9), deep=1)
        arr.SetName("tensors")
        ug.GetPointData().SetTensors(arr)
        squeeze = np.outer([1.0, 0.5, 0.2], [1.0, 0.5, 0.2])
        other = numpy_to_vtk((self.tensors * squeeze).reshape(-1, 9).astype(np.float32), deep=1)
        other.SetName("other")
        ug.GetPointData().AddArray(other)
        self.vtu = os.path.join(d, "points.vtu")
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetFileName(self.vtu)
        w.SetInputData(ug)
        assert w.Write() == 1

    @staticmethod
    def _write_mesh(path):
        # A coarse sphere of radius 2 about (3, 3, 2): faces meet at 45-90 degrees.
        rows = []
        for i in range(5):
            th = np.pi * i / 4
            rows.append([(3 + 2 * np.sin(th) * np.cos(ph), 3 + 2 * np.sin(th) * np.sin(ph), 2 + 2 * np.cos(th))
                         for ph in np.linspace(0, 2 * np.pi, 6, endpoint=False)])
        with open(path, "w") as f:
            for row in rows:
                for x, y, z in row:
                    f.write(f"v {x:.6f} {y:.6f} {z:.6f}\n")
            for i in range(4):
                for j in range(6):
                    a, b = 1 + 6 * i + j, 1 + 6 * i + (j + 1) % 6
                    f.write(f"f {a} {b} {b + 6}\nf {a} {b + 6} {a + 6}\n")

    def resolve(self, opts):
        return {k: self.files.get(v, v) if isinstance(v, str) else v for k, v in opts.items()}

    def python(self, kind, opts):
        """('image', pixels) or ('refused', message)."""
        opts = {"size": SIZE, **self.resolve(opts)}
        sources = {
            "nifti": lambda: tg.render(self.nifti, **opts),
            "volume": lambda: tg.render(self.volume, affine=self.affine, **opts),
            "vtu": lambda: tg.render(self.vtu, **opts),
            "points": lambda: tg.render(self.tensors, positions=self.positions, **opts),
        }
        try:
            import warnings
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return "image", sources[kind]().image
        except (ValueError, TypeError) as e:
            return "refused", str(e)

    def cli(self, kind, opts):
        path = {"nifti": self.nifti, "vtu": self.vtu}[kind]
        png = os.path.join(self.dir, "cli.png")
        if os.path.exists(png):
            os.remove(png)
        args = [CLI, "render", path, "-o", png, "--quiet"]
        for kw, v in {"size": SIZE, **self.resolve(opts)}.items():
            args += _flag_args(kw, v)
        r = subprocess.run(args, capture_output=True, text=True)
        if r.returncode != 0:
            return "refused", r.stderr.strip()
        import matplotlib.image
        return "image", np.round(matplotlib.image.imread(png) * 255).astype(np.uint8)


def _said(outcome):
    return outcome[1] if outcome[0] == "refused" else ""


def _same(a, b):
    return a[0] == b[0] and (a[0] == "refused" or np.array_equal(a[1], b[1]))


@unittest.skipUnless(CLI, "TG_CLI names the tensorglyph binary")
class OptionsApply(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls._tmp = tempfile.TemporaryDirectory()
        cls.data = Data(cls._tmp.name)

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def test_every_keyword_has_a_case(self):
        self.assertEqual(sorted(tg.options()), sorted(CASES), "a keyword without a case here is not checked")

    def test_no_keyword_is_dropped_for_any_input(self):
        """For each keyword and each input: the Python path does what the CLI
        does with that file (refuses, or the same pixels); a volume array
        what its NIfTI does, an array of points what its .vtu does; what is
        applied changes the picture; what is refused is named."""
        d = self.data
        baselines, applied = {}, set()
        for kw, (value, companions) in CASES.items():
            opts = dict(companions, **{kw: value})
            key = tuple(sorted(companions.items()))
            for kind in ("nifti", "volume", "vtu", "points"):
                with self.subTest(keyword=kw, input=kind):
                    if (kind, key) not in baselines:
                        baselines[kind, key] = d.python(kind, companions)
                    base = baselines[kind, key]
                    got = d.python(kind, opts)
                    if kind in ("nifti", "vtu"):
                        twin, what = d.cli(kind, opts), "the CLI with this file"
                    elif kind == "volume":
                        twin, what = d.python("nifti", opts), "its NIfTI file"
                    else:
                        twin, what = d.python("vtu", opts), "its .vtu file"
                    if kind != "points" or kw not in POINTS_DIFFER_FROM_VTU:
                        self.assertTrue(_same(got, twin),
                                        f"{got[0]} here, {twin[0]} by {what}: {_said(got)} {_said(twin)}")
                    else:
                        self.assertEqual(got[0], "refused", f"{kw} has nothing to apply to in arrays")
                    if base[0] == "refused":  # a companion that does not apply here (a mask for points)
                        self.assertEqual(got[0], "refused")
                    elif got[0] == "refused":
                        flag = tg.options()[kw][0]
                        self.assertTrue(flag in got[1] or kw in got[1], f"refused without naming {kw}: {got[1]}")
                    else:
                        applied.add(kw)
                        if kw not in NO_VISIBLE_CHANGE:
                            self.assertFalse(np.array_equal(got[1], base[1]), f"{kw}={value!r} changed nothing")
        # A case refused everywhere would test no application: each value
        # here applies to one input at least (confidence values: NRRD only).
        self.assertEqual(sorted(set(CASES) - applied), ["confidence_min"])

    def test_a_renderer_switched_to_blobs_takes_the_cpu_path(self):
        """A Renderer made for ellipsoids (the raster path) switched to
        glyph="blob" raised the raster path's refusal; it now loads again on
        the cpu path, and draws what a fresh blob render draws."""
        d = self.data
        r = tg.Renderer(d.nifti, size=(48, 36))
        r.render()
        blob = np.asarray(r.set(glyph="blob").render())
        fresh = np.asarray(tg.render(d.nifti, size=(48, 36), glyph="blob"))
        self.assertTrue(np.array_equal(blob, fresh))
        self.assertFalse(np.array_equal(blob, np.asarray(r.set(glyph="ellipsoid").render())))

    def test_march_options_on_glyphs_that_do_not_march_are_named(self):
        """gamma, iterations and epsilon on ellipsoids: `render` refuses them;
        a Renderer keeps them for a later glyph="superquadric" and drew
        without a word. Each now warns, naming the keyword; superquadrics
        take them without one."""
        import warnings
        d = self.data
        for kw, value in (("gamma", 2.0), ("iterations", 3), ("epsilon", 0.01)):
            with self.subTest(keyword=kw):
                both = ' and "blob"' if kw == "gamma" else ""
                with self.assertWarnsRegex(UserWarning, f'{kw} applies to glyph="superquadric"{both} only; this frame '
                                                        "draws ellipsoid glyphs"):
                    tg.render(d.nifti, size=(32, 24), **{kw: value})
                with warnings.catch_warnings():
                    warnings.simplefilter("error")
                    tg.render(d.nifti, size=(32, 24), glyph="superquadric", **{kw: value})

    def test_source_arguments_apply_or_are_refused(self):
        """layout=, frame= and affine= beside a file or the built-in scene:
        once taken and dropped without a word. The file's reader takes layout
        and frame (its --layout and --frame); the built-in scene refuses them,
        as the CLI does; no file or scene takes an affine."""
        d = self.data
        cases = [
            ("--layout", lambda: tg.render(layout="mrtrix", size=(32, 24))),
            ("--frame", lambda: tg.render(frame="world", size=(32, 24))),
            ("affine", lambda: tg.render(affine=np.eye(4), size=(32, 24))),
            ("affine", lambda: tg.render(d.nifti, affine=np.eye(4), size=(32, 24))),
            ("--layout", lambda: tg.render(d.vtu, layout="mrtrix", size=(32, 24))),
            ("positions", lambda: tg.render(d.nifti, positions=d.positions, size=(32, 24))),
        ]
        for word, call in cases:
            with self.subTest(word=word):
                with self.assertRaises(ValueError) as cm:
                    call()
                self.assertIn(word, str(cm.exception))


if __name__ == "__main__":
    unittest.main()
