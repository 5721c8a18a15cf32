"""Python inputs (issue 32 items 5 and 6): underlays and masks from NumPy
arrays, nibabel images and DIPY results, with their affines; the hint for a
volume cut down by an integer index; "did you mean" for keywords; the stubs'
Literal types; the default frame of (X, Y, Z, 3, 3) arrays; and the voxel
(i, j, k) of a pick, from the CLI's --pick and from Figure.voxel."""
import ast
import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import tensorglyph as tg
from test_module import fit_small_64d

CLI = os.environ.get("TG_CLI", "")
EMPTY = 0xFFFFFFFF
OPTS = dict(size=(160, 120), plane="z:5")


def nib():
    import nibabel
    return nibabel


class Underlays(unittest.TestCase):
    """An underlay in memory draws the picture its file draws."""

    @classmethod
    def setUpClass(cls):
        cls.img, cls.fit = fit_small_64d()
        cls.dir = tempfile.TemporaryDirectory()
        # The affine's entries rounded to float32, as a NIfTI file stores them.
        cls.affine = cls.img.affine.astype(np.float32).astype(np.float64)

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def saved(self, name, values, affine):
        path = os.path.join(self.dir.name, name)
        nib().save(nib().Nifti1Image(np.asarray(values, np.float32), affine), path)
        return path

    def draw(self, **opts):
        return tg.render(self.fit, affine=self.affine, **{**OPTS, **opts}).image

    def test_dipy_fa_array_draws_as_its_file(self):
        fa = self.fit.fa
        from_file = self.draw(underlay=self.saved("fa.nii", fa, self.affine))
        self.assertTrue(np.array_equal(self.draw(underlay=fa), from_file))
        self.assertFalse(np.array_equal(self.draw(plane=None), from_file), "the underlay draws nothing")
        # The field's own FA: the same values up to the float32 eigen-solve.
        own = self.draw(underlay="fa").astype(int)
        self.assertLessEqual(np.abs(own - from_file).max(), 3)

    def test_nibabel_image_with_its_own_affine_draws_as_its_file(self):
        # A grid of its own: twice as fine, shifted by half a voxel.
        fa = np.repeat(np.repeat(np.repeat(self.fit.fa, 2, 0), 2, 1), 2, 2)
        affine = self.affine.copy()
        affine[:3, :3] /= 2
        affine[:3, 3] -= affine[:3, :3] @ [0.5, 0.5, 0.5]
        path = self.saved("fine.nii", fa, affine)
        image = nib().load(path)
        opts = dict(plane_at=list(self.affine[:3, 3] + self.affine[:3, :3] @ [4.5, 4.5, 5]) +
                    list(self.affine[:3, 2]), plane=None)
        from_file = self.draw(underlay=path, **opts)
        self.assertTrue(np.array_equal(self.draw(underlay=image, **opts), from_file))
        self.assertTrue(np.array_equal(self.draw(underlay=fa, underlay_affine=affine, **opts), from_file))
        # Without its affine a grid of another shape has no place: refused,
        # naming the way to give one.
        with self.assertRaisesRegex(ValueError, r"underlay.*20x20x20 is not the tensor grid 10x10x10.*underlay_affine"):
            self.draw(underlay=fa, **opts)

    def test_file_tensors_take_an_array_underlay_on_their_grid(self):
        lower = self.fit.lower_triangular()
        fsl = lower[..., [0, 1, 3, 2, 4, 5]]  # nifti's xx xy yy xz yz zz as FSL's xx xy xz yy yz zz
        path = self.saved("dt.nii", fsl, self.affine)
        from_file = tg.render(path, frame="voxel", underlay=self.saved("fa2.nii", self.fit.fa, self.affine),
                              **OPTS).image
        self.assertTrue(np.array_equal(tg.render(path, frame="voxel", underlay=self.fit.fa, **OPTS).image, from_file))

    def test_a_changed_array_reloads(self):
        r = tg.Renderer(self.fit, affine=self.affine, underlay=self.fit.fa, **OPTS)
        first = r.render().image
        uploads = r.uploads
        self.assertTrue(np.array_equal(r.render(underlay=self.fit.fa.copy()).image, first))
        changed = r.render(underlay=1.0 - self.fit.fa).image
        self.assertFalse(np.array_equal(changed, first), "a new array was not drawn")
        self.assertGreater(r.uploads, uploads)
        # A refused one (off the grid, found once loading) leaves the last drawable.
        with self.assertRaisesRegex(ValueError, "3x3x3 is not the tensor grid"):
            r.render(underlay=np.zeros((3, 3, 3)))
        self.assertTrue(np.array_equal(r.render(underlay=1.0 - self.fit.fa).image, changed))
        self.assertFalse(any(kw == "underlay" for kw, _ in tg.render(self.fit, affine=self.affine,
                                                                     underlay=self.fit.fa, **OPTS).inputs))

    def test_bad_underlays_are_refused_with_their_keyword(self):
        t = np.tile(np.eye(3), (4, 1, 1))
        p = np.arange(12.0).reshape(4, 3)
        cases = [
            (ValueError, r"underlay: shape \(10, 10\) .*underlay\[:, :, 5:6\]", dict(underlay=self.fit.fa[:, :, 5])),
            (ValueError, r"underlay: shape \(10, 10, 12, 3\) is not a volume", dict(underlay=np.zeros((10, 10, 12, 3)))),
            (TypeError, r"underlay: an array of numbers", dict(underlay=np.array([[["a"]]]))),
            (ValueError, r"underlay_affine: applies to underlay= given as an array", dict(underlay="fa",
                                                                                       underlay_affine=np.eye(4))),
            (ValueError, r"underlay_affine: shape \(3, 3\)", dict(underlay=self.fit.fa, underlay_affine=np.eye(3))),
            (ValueError, r"mask_affine: the nibabel image", dict(mask=nib().Nifti1Image(self.fit.fa, self.affine),
                                                                 mask_affine=self.affine)),
            # Transposed (its translation in the last row), or no affine at
            # all: refused, not drawn with the last row ignored.
            (ValueError, r"underlay_affine: the last row must be 0 0 0 1",
             dict(underlay=self.fit.fa, underlay_affine=self.affine.T)),
            (ValueError, r"mask_affine: the last row must be 0 0 0 1",
             dict(mask=self.fit.fa > 0.3, mask_affine=np.diag([2.0, 2.0, 2.0, 0.0]))),
            (ValueError, r"underlay_affine: singular", dict(underlay=self.fit.fa, underlay_affine=np.diag([1.0, 0, 1, 1]))),
        ]
        for error, message, opts in cases:
            with self.subTest(message), self.assertRaisesRegex(error, message):
                self.draw(**opts)
        with self.assertRaisesRegex(ValueError, r"point set; give the array's affine \(underlay_affine=\)"):
            tg.render(t, positions=p, underlay=np.zeros((2, 2, 2)), size=(32, 24))


class Masks(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.img, cls.fit = fit_small_64d()
        cls.affine = cls.img.affine.astype(np.float32).astype(np.float64)

    def test_masks_from_arrays_images_and_files_keep_the_same_voxels(self):
        keep = self.fit.fa > 0.3
        opts = dict(size=(160, 120), channels=True)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "mask.nii")
            nib().save(nib().Nifti1Image(keep.astype(np.uint8), self.affine), path)
            from_file = tg.render(self.fit, affine=self.affine, mask=path, **opts)
            image = nib().load(path)
            kinds = {"bool array": dict(mask=keep), "float array": dict(mask=keep * 1.0),
                     "nibabel image": dict(mask=image), "array and affine": dict(mask=keep, mask_affine=self.affine)}
            for name, mask in kinds.items():
                with self.subTest(name):
                    fig = tg.render(self.fit, affine=self.affine, **mask, **opts)
                    self.assertEqual(fig.glyphs, from_file.glyphs)
                    self.assertTrue(np.array_equal(fig.image, from_file.image))
        # Each drawn voxel is one the mask keeps, and every kept one is drawn.
        self.assertEqual(from_file.glyphs, int(keep.sum()))
        drawn = from_file.voxel(np.unique(from_file.channels["id"][from_file.channels["id"] != EMPTY]))
        self.assertTrue(keep[tuple(drawn.T)].all())

    def test_bad_masks_are_refused(self):
        with self.assertRaisesRegex(ValueError, r"<mask array>: mask grid 10x10x11 differs from the tensor grid 10x10x10"):
            tg.render(self.fit, affine=self.affine, mask=np.ones((10, 10, 11)), size=(32, 24))
        moved = self.affine.copy()
        moved[0, 3] += 5
        with self.assertRaisesRegex(ValueError, r"<mask array>: mask lies elsewhere"):
            tg.render(self.fit, affine=self.affine, mask=np.ones((10, 10, 10)), mask_affine=moved, size=(32, 24))


class Hints(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.img, cls.fit = fit_small_64d()

    def test_an_integer_index_is_refused_with_the_range_that_keeps_its_axis(self):
        A = self.img.affine
        q = self.fit.quadratic_form
        cut = {"fit[:, :, 5]": self.fit[:, :, 5], "fit[5, 5, 5]": self.fit[5, 5, 5],
               "quadratic_form[:, :, 5]": q[:, :, 5], "lower_triangular()[:, 5]": self.fit.lower_triangular()[:, 5]}
        for name, tensors in cut.items():
            with self.subTest(name), self.assertRaisesRegex(ValueError, r"integer index drops its axis.*5:6.*slice="):
                tg.render(tensors, affine=A, size=(32, 24))
        # The range keeps it: the same glyphs as slice="z:5" of the whole.
        whole = tg.render(self.fit, affine=A, slice="z:5", size=(96, 72), view="superior")
        shift = A.copy()
        shift[:3, 3] += A[:3, 2] * 5  # voxel (i, j, 0) of the slab is (i, j, 5) of the volume
        part = tg.render(self.fit[:, :, 5:6], affine=shift, size=(96, 72), view="superior")
        self.assertEqual(part.glyphs, whole.glyphs)

    def test_misspelt_keywords_get_the_nearest(self):
        t = np.tile(np.eye(3), (2, 1, 1))
        p = np.zeros((2, 3))
        cases = {"glpyh": "glyph", "fa_mni": "fa_min", "afine": "affine", "underlay_afine": "underlay_affine",
                 "colour": "color"}
        for wrong, right in cases.items():
            with self.subTest(wrong), self.assertRaisesRegex(TypeError, f"'{wrong}'; did you mean '{right}'\\?"):
                tg.render(t, positions=p, **{wrong: "1"})
            with self.subTest(wrong + " in set"), self.assertRaisesRegex(TypeError, f"did you mean '{right}'"):
                tg.Renderer(t, positions=p, size=(16, 16)).set(**{wrong: "1"})
        with self.assertRaises(TypeError) as cm:
            tg.render(t, positions=p, zzzzzzzz=1)
        self.assertNotIn("did you mean", str(cm.exception))
        # The core's own check, as the CLI's: the same suggestion.
        with self.assertRaisesRegex(TypeError, "did you mean 'glyph'"):
            tg._core.Renderer(t, p, None, "", "", "", [("glpyh", ["box"])], None)


class Frames(unittest.TestCase):
    def test_quadratic_form_arrays_are_in_dipys_voxel_axes_by_default(self):
        img, fit = fit_small_64d()
        opts = dict(size=(96, 72), glyph="superquadric")
        q = fit.quadratic_form
        as_fit = tg.render(fit, affine=img.affine, **opts)
        self.assertTrue(np.array_equal(tg.render(q, affine=img.affine, **opts), as_fit))
        self.assertTrue(np.array_equal(tg.render(q, affine=img.affine, frame="voxel", **opts), as_fit))
        # Under small_64D's oblique affine the other frames draw otherwise.
        self.assertFalse(np.array_equal(tg.render(q, affine=img.affine, frame="world", **opts), as_fit))


class StubLiterals(unittest.TestCase):
    """The stubs type each option with a fixed list of names as a Literal of
    exactly the names the option takes: each is accepted, and a name outside
    it is refused with a message listing the same names."""

    def annotations(self):
        stub = os.path.join(os.path.dirname(tg.__file__), "__init__.pyi")
        with open(stub) as f:
            tree = ast.parse(f.read())
        render = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "render")
        return {a.arg: a.annotation for a in render.args.kwonlyargs}

    @staticmethod
    def literal(annotation):
        for node in ast.walk(annotation):
            if isinstance(node, ast.Subscript) and ast.unparse(node.value) == "Literal":
                elts = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
                return [e.value for e in elts]
        return None

    def test_named_values_are_literals_of_what_each_option_takes(self):
        kinds = self.annotations()
        for kw in ("glyph", "color", "colormap", "underlay_colormap", "magnitude", "legend_corner", "mesh_mode",
                   "pipeline", "layout", "frame", "scale_mode", "sizes_from", "backend", "view", "orientation_letters"):
            self.assertIsNotNone(self.literal(kinds[kw]), f"{kw}: {ast.unparse(kinds[kw])}")
        self.assertIn("ArrayLike", ast.unparse(kinds["color"]), "color= also takes one value per tensor")
        for name in ("underlay", "mask"):
            self.assertIn("ArrayLike", ast.unparse(kinds[name]))
        t = np.tile(np.eye(3), (2, 1, 1))
        p = np.zeros((2, 3))
        r = tg.Renderer(t, positions=p, size=(16, 16))
        for kw, annotation in kinds.items():
            names = self.literal(annotation)
            if names is None or kw in ("layout", "frame"):
                continue
            with self.subTest(kw):
                with self.assertRaises(ValueError) as cm:
                    r.set(**{kw: "no-such-name"})
                listed = str(cm.exception).split("choose ", 1)[1]
                self.assertEqual(sorted(n for n in names if n in listed), sorted(names), str(cm.exception))
                for n in names:
                    try:
                        r.set(**{kw: n})
                    except ValueError as e:  # a name that needs another option names that one, not itself
                        self.assertNotIn("unknown", str(e), f"{kw}={n!r}")
                    r.set(**{kw: None})
        # The volume's own layout= and frame=: those the readers take.
        q = np.tile(np.eye(3), (2, 2, 2, 1, 1))
        for n in self.literal(kinds["frame"]):
            tg.render(q, affine=np.eye(4), frame=n, size=(16, 16))
        self.assertEqual(self.literal(kinds["glyph"]), tg._core.choices()["glyph"])


class PickVoxels(unittest.TestCase):
    """The voxel (i, j, k) of a picked glyph: ids run i fastest, and the
    voxel's world position (the affine's) is where the glyph is drawn."""

    @classmethod
    def setUpClass(cls):
        cls.img, cls.fit = fit_small_64d()
        cls.affine = cls.img.affine.astype(np.float32).astype(np.float64)

    def test_figure_voxel_is_the_id_in_fortran_order(self):
        fig = tg.render(self.fit, affine=self.affine, size=(160, 120), slice="x:3", channels=True)
        self.assertEqual(fig.grid, self.fit.fa.shape)
        ids = fig.channels["id"]
        ijk = fig.voxel(ids)
        self.assertEqual(ijk.shape, ids.shape + (3,))
        hit = ids != EMPTY
        self.assertTrue((ijk[~hit] == -1).all())
        self.assertTrue((ijk[hit][:, 0] == 3).all(), "a voxel outside the slice x:3")
        expected = np.stack(np.unravel_index(ids[hit].astype(np.int64), fig.grid, order="F"), axis=-1)
        self.assertTrue(np.array_equal(ijk[hit], expected))
        self.assertEqual(tuple(fig.voxel(int(ids[hit][0]))), tuple(expected[0]))
        points = tg.render(np.tile(np.eye(3), (2, 1, 1)), positions=np.zeros((2, 3)), size=(16, 16))
        self.assertIsNone(points.grid)
        with self.assertRaisesRegex(ValueError, "no voxel grid"):
            points.voxel(0)

    @unittest.skipUnless(CLI, "TG_CLI names the tensorglyph binary")
    def test_cli_pick_gives_the_voxel_at_the_glyphs_position(self):
        lower = self.fit.lower_triangular()[..., [0, 1, 3, 2, 4, 5]]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "dt.nii")
            nib().save(nib().Nifti1Image(lower.astype(np.float32), self.affine), path)
            pixels = [(i, j) for i in range(0, 160, 5) for j in range(0, 120, 5)]
            args = [CLI, "render", path, "-o", os.path.join(d, "p.png"), "--size", "160", "120", "--slice", "z:5"]
            for i, j in pixels:
                args += ["--pick", str(i), str(j)]
            out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
        picks = [json.loads(line) for line in out.splitlines()]
        glyphs = [p for p in picks if p["hit"] == "glyph"]
        self.assertGreaterEqual(len(glyphs), 10)
        X, Y, _ = self.fit.fa.shape
        for p in glyphs:
            i, j, k = p["voxel"]
            self.assertEqual(k, 5)
            self.assertEqual(p["index"], i + X * (j + Y * k))
            world = self.affine @ [i, j, k, 1.0]
            np.testing.assert_allclose(p["position"], world[:3], atol=1e-4)
        self.assertTrue(all("voxel" not in p for p in picks if p["hit"] == "background"))


if __name__ == "__main__":
    unittest.main()
