"""The Python module (issue 18), run by ctest with Debian's python3:
a DIPY pipeline, the module against the CLI, bad input, uploads, threads,
the type stubs."""
import ast
import gc
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import tensorglyph as tg

CLI = os.environ.get("TG_CLI", "")


def fit_small_64d():
    import nibabel as nib
    from dipy.core.gradients import gradient_table
    from dipy.data import get_fnames
    from dipy.io.gradients import read_bvals_bvecs
    from dipy.reconst.dti import TensorModel

    fdata, fbval, fbvec = get_fnames("small_64D")
    img = nib.load(fdata)
    bvals, bvecs = read_bvals_bvecs(fbval, fbvec)
    fit = TensorModel(gradient_table(bvals, bvecs)).fit(img.get_fdata())
    return img, fit


def view_basis(eye, look_at, up):
    fwd = np.asarray(look_at, float) - eye
    fwd /= np.linalg.norm(fwd)
    right = np.cross(fwd, up)
    right /= np.linalg.norm(right)
    return fwd, right, np.cross(right, fwd)


class DipyPipeline(unittest.TestCase):
    def test_long_axes_follow_dipys_principal_eigenvectors(self):
        """Frame convention: DIPY's tensors are in the image's voxel axes
        (i, j, k), so the module's default for a TensorFit is frame="voxel":
        a direction e in voxel axes points along normalize(A e) in world
        space, A the affine's 3x3 part. Each glyph's visible surface,
        unprojected from the id and depth channels, must be elongated along
        DIPY's own principal eigenvector taken to world space that way."""
        img, fit = fit_small_64d()
        A = img.affine[:3, :3]
        k = 5
        # Look at slice k along its normal (the affine's third column).
        normal = A[:, 2] / np.linalg.norm(A[:, 2])
        centre = img.affine @ np.array([4.5, 4.5, k, 1.0])
        eye = centre[:3] + 100.0 * normal
        up = A[:, 0] / np.linalg.norm(A[:, 0])
        W = H = 480
        ortho = 24.0
        fig = tg.render(fit, affine=img.affine, slice=f"z:{k}", size=(W, H), ortho=ortho, eye=eye,
                        look_at=centre[:3], up=up, channels=True)
        ids, depth = fig.channels["id"], fig.channels["depth"]
        fwd, right, up2 = view_basis(eye, centre[:3], up)
        jj, ii = np.mgrid[0:H, 0:W]
        u = ((ii + 0.5) / W - 0.5) * ortho * W / H
        v = (0.5 - (jj + 0.5) / H) * ortho
        hit = np.isfinite(depth)
        points = np.zeros((H, W, 3))
        points[hit] = (eye + u[hit][:, None] * right + v[hit][:, None] * up2 + depth[hit][:, None] * fwd)
        evecs, fa = fit.evecs, fit.fa
        checked = passed = 0
        for gid in np.unique(ids[ids != 0xFFFFFFFF]):
            i, j, kk = gid % 10, (gid // 10) % 10, gid // 100
            self.assertEqual(kk, k, "an id outside the slice")
            mask = ids == gid
            pts = points[mask]
            world = img.affine @ np.array([i, j, kk, 1.0])
            # The surface lies around the glyph's own voxel: ids and depth agree.
            self.assertLess(np.linalg.norm(pts.mean(axis=0) - world[:3]), 2.0, f"glyph {gid} drawn off its voxel")
            e1 = A @ evecs[i, j, kk, :, 0]
            e1 /= np.linalg.norm(e1)
            if fa[i, j, kk] < 0.4 or mask.sum() < 40 or abs(e1 @ normal) > 0.7:
                continue
            w, vecs = np.linalg.eigh(np.cov((pts - pts.mean(axis=0)).T))
            checked += 1
            passed += abs(vecs[:, 2] @ e1) > np.cos(np.radians(25))
        # Measured: 38 of 38 pass; taking the tensors as world-space (frame="world") passes 8 of 39.
        self.assertGreaterEqual(checked, 10)
        self.assertGreaterEqual(passed, 0.9 * checked, f"{passed} of {checked} long axes follow DIPY's")


    def test_lower_triangular_in_the_default_order_is_refused(self):
        """DIPY's fit.lower_triangular() is xx xy yy xz yz zz, the "nifti"
        order; arrays default to "fsl", so passing it bare swaps yy and xz.
        "nifti" is the one order that reads it as diffusion tensors: refused,
        naming it (test_layouts.py has the rest); in the right order, or as
        quadratic_form, it says nothing."""
        import warnings
        img, fit = fit_small_64d()
        opts = dict(size=(96, 72))
        with self.assertRaisesRegex(ValueError, 'indefinite .* as fsl .*only layout="nifti"'):
            tg.render(fit.lower_triangular(), affine=img.affine, **opts)
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            right = tg.render(fit.lower_triangular(), affine=img.affine, layout="nifti", frame="voxel", **opts)
            self.assertTrue(np.array_equal(right, tg.render(fit, affine=img.affine, **opts)))
            # Indefinite in any order (stress), in a named order: no order is evidence, no warning.
            rng = np.random.default_rng(2)
            tg.render(rng.normal(size=(50, 6)), positions=rng.uniform(0, 10, (50, 3)), layout="vtk", **opts)


@unittest.skipUnless(CLI, "TG_CLI names the tensorglyph binary")
class ModuleAgainstCli(unittest.TestCase):
    def test_same_nifti_same_pixels(self):
        import nibabel as nib
        rng = np.random.default_rng(7)
        X, Y, Z = 6, 5, 4
        L = rng.normal(size=(X, Y, Z, 3, 3)) * 0.3 + np.eye(3) * [1.0, 0.5, 0.25]
        D = L @ np.swapaxes(L, -1, -2)  # positive definite
        fsl = np.stack([D[..., 0, 0], D[..., 0, 1], D[..., 0, 2], D[..., 1, 1], D[..., 1, 2], D[..., 2, 2]], -1)
        # Axes permuted, voxels anisotropic, det > 0 (so the fsl frame mirrors i);
        # every entry exact in the file's float32 sform.
        affine = np.array([[0, -2.0, 0, 10], [1.5, 0, 0, -3], [0, 0, 2.5, 1], [0, 0, 0, 1]])
        opts = dict(size=(160, 120), glyph="superquadric", gamma=2.5, fa_min=0.05, color="fa")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "dt.nii.gz")
            nib.save(nib.Nifti1Image(fsl.astype(np.float32), affine), path)
            png = os.path.join(d, "cli.png")
            subprocess.run([CLI, "render", path, "-o", png, "--size", "160", "120", "--glyph", "superquadric",
                            "--gamma", "2.5", "--fa-min", "0.05", "--color", "fa"], check=True)
            from_cli = np.asarray(_read_png(png))
            from_path = tg.render(path, **opts).image
            from_nibabel = tg.render(nib.load(path), **opts).image
            from_array = tg.render(fsl.astype(np.float32), affine=affine, layout="fsl", **opts).image
            saved = os.path.join(d, "module.png")
            tg.save(tg.render(path, **opts), saved)
            self.assertTrue(np.array_equal(from_cli, from_path))
            self.assertTrue(np.array_equal(from_cli, from_nibabel))
            self.assertTrue(np.array_equal(from_cli, from_array))
            self.assertTrue(np.array_equal(from_cli, _read_png(saved)))
            self.assertGreater(np.count_nonzero(from_cli[..., 3]), 500, "nothing drawn")


    def test_nifti_without_sform_or_qform_same_pixels(self):
        # nibabel's affine for such a header is ANALYZE's (x reversed, centred);
        # NIfTI's method 1 and the CLI place by pixdim alone, tensors unrotated.
        import nibabel as nib
        rng = np.random.default_rng(3)
        L = rng.normal(size=(5, 4, 3, 3, 3)) * 0.3 + np.eye(3) * [1.0, 0.5, 0.25]
        D = L @ np.swapaxes(L, -1, -2)
        fsl = np.stack([D[..., 0, 0], D[..., 0, 1], D[..., 0, 2], D[..., 1, 1], D[..., 1, 2], D[..., 2, 2]], -1)
        hdr = nib.Nifti1Header()
        hdr.set_data_shape(fsl.shape)
        hdr.set_data_dtype(np.float32)
        hdr.set_zooms((2.0, 1.5, 2.5, 1.0))
        img = nib.Nifti1Image(fsl.astype(np.float32), None, hdr)
        img.header.set_sform(None, code=0)
        img.header.set_qform(None, code=0)
        opts = dict(size=(160, 120), glyph="superquadric", gamma=2.5, fa_min=0.05, color="fa")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "noaffine.nii")
            nib.save(img, path)
            png = os.path.join(d, "cli.png")
            subprocess.run([CLI, "render", path, "-o", png, "--size", "160", "120", "--glyph", "superquadric",
                            "--gamma", "2.5", "--fa-min", "0.05", "--color", "fa"], check=True, capture_output=True)
            from_cli = np.asarray(_read_png(png))
            loaded = nib.load(path)
            self.assertEqual(int(loaded.header["sform_code"]), 0)
            self.assertEqual(loaded.affine[0, 0], -2.0)  # nibabel's ANALYZE affine, which must not be used
            self.assertTrue(np.array_equal(from_cli, tg.render(loaded, **opts).image))
            self.assertGreater(np.count_nonzero(from_cli[..., 3]), 300, "nothing drawn")

    def test_points_from_arrays_draw_as_their_vtk_file(self):
        """Points from arrays are sized as the VTK reader sizes the same
        points (spacing mode, the default): once they had no sample spacing
        and drew at another size."""
        import vtk
        from vtk.util.numpy_support import numpy_to_vtk
        t, p = points(60)
        opts = dict(size=(120, 90), glyph="superquadric")
        with tempfile.TemporaryDirectory() as d:
            grid = vtk.vtkPolyData()
            pts = vtk.vtkPoints()
            pts.SetData(numpy_to_vtk(p.astype(np.float32), deep=1))
            grid.SetPoints(pts)
            arr = numpy_to_vtk(t.reshape(-1, 9).astype(np.float32), deep=1)
            arr.SetName("tensors")
            grid.GetPointData().SetTensors(arr)
            path = os.path.join(d, "points.vtp")
            w = vtk.vtkXMLPolyDataWriter()
            w.SetFileName(path)
            w.SetInputData(grid)
            self.assertEqual(w.Write(), 1)
            png = os.path.join(d, "cli.png")
            subprocess.run([CLI, "render", path, "-o", png, "--size", "120", "90", "--glyph", "superquadric"],
                           check=True)
            from_cli = _read_png(png)
        from_arrays = tg.render(t.astype(np.float32), positions=p.astype(np.float32), **opts).image
        self.assertGreater(np.count_nonzero(from_cli[..., 3]), 300, "nothing drawn")
        self.assertTrue(np.array_equal(from_cli, from_arrays))


def _read_png(path):
    # matplotlib's PNG reader (Debian's python3-matplotlib comes with DIPY) as 8-bit.
    import matplotlib.image
    return np.round(matplotlib.image.imread(path) * 255).astype(np.uint8)


def points(n=5):
    rng = np.random.default_rng(1)
    m = rng.normal(size=(n, 3, 3))
    return m + np.swapaxes(m, 1, 2) + 6 * np.eye(3), rng.uniform(0, 10, size=(n, 3))


_TMP = tempfile.TemporaryDirectory()  # removed when the interpreter exits


def _nifti_file():
    """A small positive-definite fsl-order NIfTI (det > 0), written once."""
    path = os.path.join(_TMP.name, "dt.nii")
    if not os.path.exists(path):
        import nibabel as nib
        rng = np.random.default_rng(3)
        L = rng.normal(size=(4, 4, 3, 3, 3)) * 0.3 + np.eye(3) * [1.0, 0.5, 0.25]
        D = L @ np.swapaxes(L, -1, -2)
        fsl = np.stack([D[..., 0, 0], D[..., 0, 1], D[..., 0, 2], D[..., 1, 1], D[..., 1, 2], D[..., 2, 2]], -1)
        nib.save(nib.Nifti1Image(fsl.astype(np.float32), np.diag([2.0, 2.0, 2.0, 1.0])), path)
    return path


class BadInput(unittest.TestCase):
    def test_each_bad_argument_raises_and_names_it(self):
        t, p = points()
        cases = [
            (ValueError, "tensors", lambda: tg.render(np.zeros((5, 4)), positions=p)),
            (ValueError, "tensors", lambda: tg.render(np.zeros((5, 3, 2)), positions=p)),
            (TypeError, "tensors", lambda: tg.render(np.zeros((5, 3, 3), complex), positions=p)),
            (TypeError, "tensors", lambda: tg.render(np.array([["a"] * 6] * 5), positions=p)),
            # NaN tensors are skipped, as the readers skip them; all of them is nothing to draw.
            (ValueError, "5 skipped (NaN/Inf)", lambda: tg.render(np.where(np.eye(3) > 0, np.nan, 1.0)[None]
                                                                  .repeat(5, 0), positions=p)),
            (ValueError, "positions", lambda: tg.render(t, positions=p[:3])),
            (ValueError, "positions", lambda: tg.render(t)),
            (ValueError, "affine", lambda: tg.render(np.zeros((2, 2, 2, 6)), affine=np.eye(3))),
            (ValueError, "affine", lambda: tg.render(np.zeros((2, 2, 2, 6)), affine=np.full((4, 4), np.inf))),
            (TypeError, "unexpected keyword", lambda: tg.render(t, positions=p, gama=2)),
            (ValueError, "--gamma", lambda: tg.render(t, positions=p, gamma=-1)),
            (ValueError, "--gamma", lambda: tg.render(t, positions=p, gamma=float("nan"))),
            (TypeError, "gamma", lambda: tg.render(t, positions=p, gamma=True)),
            (TypeError, "ao", lambda: tg.render(t, positions=p, ao=1)),
            (ValueError, "--size", lambda: tg.render(t, positions=p, size=(0, 10))),
            (ValueError, "--size", lambda: tg.render(t, positions=p, size=(10,))),
            (ValueError, "--glyph", lambda: tg.render(t, positions=p, glyph="teapot")),
            (ValueError, "missing.vtk", lambda: tg.render("/nonexistent/missing.vtk")),
            (ValueError, "layout", lambda: tg.render(np.zeros((2, 2, 2, 6)) + 1, affine=np.eye(4), layout="xyz")),
            # Points' tensors are in world axes: a frame would be ignored.
            (ValueError, "frame", lambda: tg.render(t, positions=p, frame="voxel")),
            (ValueError, "--layout", lambda: tg.render(_nifti_file(), layout="xyz")),
            (TypeError, "layout", lambda: tg.Renderer(t, positions=p).set(layout="mrtrix")),
            # A float image in 0..1 cast to uint8 was saved black.
            (TypeError, "uint8", lambda: tg.save(np.full((8, 8, 4), 0.9), os.path.join(_TMP.name, "f.png"))),
            # The core itself refuses what it would misread.
            (TypeError, "byte order", lambda: tg._core.Renderer(t.astype(">f8"), p, None, "", "", "", [], None)),
        ]
        for exc, word, call in cases:
            with self.subTest(word=word):
                with self.assertRaises(exc) as cm:
                    call()
                self.assertIn(word, str(cm.exception))

    def test_big_endian_arrays_draw_as_native_ones(self):
        """'>f4' (a big-endian NIfTI's data through nibabel) read in place as
        little-endian is other, mostly finite numbers: once drawn without a word."""
        t, p = points(12)
        opts = dict(size=(64, 48), scale_mode="absolute", scale=0.6, eye=(5, 5, 40), look_at=(5, 5, 5))
        native = tg.render(t.astype(np.float32), positions=p.astype(np.float32), **opts).image
        self.assertGreater(np.count_nonzero(native[..., 3]), 200, "nothing drawn")
        for tt, pp in [(t.astype(">f4"), p.astype(np.float32)), (t.astype(np.float32), p.astype(">f4")),
                       (t.astype(">f8"), p.astype(">f8"))]:
            with self.subTest(tensors=tt.dtype.str, positions=pp.dtype.str):
                self.assertTrue(np.array_equal(native, tg.render(tt, positions=pp, **opts).image))

    def test_nan_tensors_are_skipped_as_the_file_reader_skips_them(self):
        """A NIfTI with a NaN voxel: read as a path it was drawn without that
        voxel and a warning; through nibabel (an array) it was refused."""
        import nibabel as nib
        path = os.path.join(_TMP.name, "nan.nii")
        img = nib.load(_nifti_file())
        data = np.asarray(img.dataobj).copy()
        data[1, 2, 0, 3] = np.nan
        nib.save(nib.Nifti1Image(data, img.affine), path)
        opts = dict(size=(64, 48), glyph="superquadric")
        with self.assertWarnsRegex(UserWarning, "skipped 1 tensors with NaN/Inf"):
            from_file = tg.render(path, **opts)
        with self.assertWarnsRegex(UserWarning, "skipped 1 tensors with NaN/Inf"):
            from_array = tg.render(nib.load(path), **opts)
        self.assertEqual(from_file.glyphs, 4 * 4 * 3 - 1)
        self.assertEqual(from_array.glyphs, from_file.glyphs)
        self.assertTrue(np.array_equal(from_file.image, from_array.image))
        t, p = points(6)
        t[4, 1, 1] = np.inf
        with self.assertWarnsRegex(UserWarning, "skipped 1 tensors"):
            self.assertEqual(tg.render(t, positions=p, size=(32, 24)).glyphs, 5)

    def test_overflowing_tensors_are_skipped_as_the_file_reader_skips_them(self):
        """A float64 NIfTI with a value beyond single precision: as a path it
        was drawn without that voxel and a warning; through nibabel it was
        refused, blaming "tensors" (as were points whose positions overflow,
        which are now refused by their own name)."""
        import nibabel as nib
        path = os.path.join(_TMP.name, "overflow.nii")
        img = nib.load(_nifti_file())
        data = np.asarray(img.dataobj).astype(np.float64)
        data[1, 2, 0, 0] = 1e39
        nib.save(nib.Nifti1Image(data, img.affine), path)
        opts = dict(size=(64, 48), glyph="superquadric")
        with self.assertWarnsRegex(UserWarning, "skipped 1 tensors whose values overflow"):
            from_file = tg.render(path, **opts)
        with self.assertWarnsRegex(UserWarning, "skipped 1 tensors whose values overflow"):
            from_array = tg.render(nib.load(path), **opts)
        self.assertEqual(from_file.glyphs, 4 * 4 * 3 - 1)
        self.assertEqual(from_array.glyphs, from_file.glyphs)
        self.assertTrue(np.array_equal(from_file.image, from_array.image))
        t, p = points(6)
        p[2, 0] = 1e39
        with self.assertRaisesRegex(ValueError, "positions: beyond single precision"):
            tg.render(t, positions=p, size=(32, 24))

    def test_a_files_layout_and_frame_are_used(self):
        """layout= and frame= with a path are the reader's --layout and
        --frame: once they were taken and silently ignored."""
        path = _nifti_file()
        opts = dict(size=(64, 48), glyph="superquadric", color="fa")
        as_fsl = tg.render(path, **opts).image
        with self.assertWarnsRegex(UserWarning, "indefinite .* try --layout fsl"):  # the reader's check
            as_mrtrix = tg.render(path, layout="mrtrix", frame="world", **opts).image
        self.assertFalse(np.array_equal(as_fsl, as_mrtrix), "layout= was ignored")
        self.assertTrue(np.array_equal(as_mrtrix, tg.Renderer(path, **opts).set(layout="mrtrix", frame="world")
                                       .render().image))
        self.assertTrue(np.array_equal(tg.render(path, frame="world", **opts).image,
                                       tg.Renderer(path, **opts).set(frame="world").render().image))

    def test_exr_needs_channels_and_png_bytes_are_a_png(self):
        t, p = points()
        fig = tg.render(t, positions=p, size=(32, 24))
        self.assertIsInstance(fig, np.ndarray)
        self.assertEqual(fig.shape, (24, 32, 4))
        self.assertEqual(fig.dtype, np.uint8)
        self.assertIsNone(fig[:, :, :3]._repr_png_())
        self.assertTrue(fig._repr_png_().startswith(b"\x89PNG"))
        with tempfile.TemporaryDirectory() as d:
            with self.assertRaises(ValueError):
                fig.save(os.path.join(d, "x.exr"))
            self.assertFalse(os.path.exists(os.path.join(d, "x.exr")))


class ColorBy(unittest.TestCase):
    """color= a derived scalar's name, or a NumPy array of one value per tensor."""

    @staticmethod
    def _von_mises(t):
        lam = np.linalg.eigvalsh(t)
        a, b, c = lam[..., 2], lam[..., 1], lam[..., 0]
        return np.sqrt(0.5 * ((a - b) ** 2 + (b - c) ** 2 + (c - a) ** 2))

    def test_an_array_draws_what_the_derived_scalar_draws(self):
        t, p = points(300)
        opts = dict(size=(160, 120), scale_mode="absolute", scale=0.4)
        by_mode = tg.render(t, positions=p, color="vonmises", **opts).image.astype(int)
        r = tg.Renderer(t, positions=p, color=self._von_mises(t), **opts)
        by_array = r.render().image.astype(int)
        self.assertGreater(np.count_nonzero(by_mode[..., 3]), 300, "nothing drawn")
        self.assertLessEqual(np.abs(by_mode - by_array).max(), 1)
        # New values, a window, a map: no upload of the glyphs.
        other = r.render(color=np.sin(np.arange(300.0)), color_range=(-0.5, 0.5), colormap="gray").image
        self.assertFalse(np.array_equal(other, by_array.astype(np.uint8)))
        self.assertEqual(r.uploads, 1)

    def test_a_volume_array_is_in_the_tensors_voxel_order(self):
        rng = np.random.default_rng(3)
        L = rng.normal(size=(5, 4, 3, 3, 3)) * 0.3 + np.eye(3) * [1.0, 0.5, 0.25]
        D = L @ np.swapaxes(L, -1, -2)
        lam = np.linalg.eigvalsh(D)
        md = lam.mean(-1, keepdims=True)
        fa = np.sqrt(1.5 * ((lam - md) ** 2).sum(-1) / (lam ** 2).sum(-1))
        opts = dict(affine=np.diag([2.0, 1.5, 2.5, 1.0]), frame="world", size=(160, 120), color_range=(0.0, 1.0))
        by_mode = tg.render(D, color="fa", **opts).image.astype(int)
        by_array = tg.render(D, color=fa, **opts).image.astype(int)
        self.assertGreater(np.count_nonzero(by_mode[..., 3]), 300, "nothing drawn")
        self.assertLessEqual(np.abs(by_mode - by_array).max(), 1)

    def test_bad_arrays_and_windows_are_refused(self):
        t, p = points(50)
        with self.assertRaises(ValueError) as cm:
            tg.render(t, positions=p, color=np.zeros(49))
        self.assertIn("49 values for 50 tensors", str(cm.exception))
        with self.assertRaises(ValueError) as cm:
            tg.render(t, positions=p, color="vonmises", color_range=(float("nan"), 1.0))
        self.assertIn("--color-range", str(cm.exception))
        with self.assertRaises(ValueError) as cm:
            tg.render(t, positions=p, color="vonmises", color_range=(2.0, 1.0))
        self.assertIn("must be below", str(cm.exception))
        with self.assertRaises(TypeError):
            tg.render(t, positions=p, color=np.array(["a"] * 50))


class Interactive(unittest.TestCase):
    def test_parameter_changes_upload_nothing(self):
        t, p = points(200)
        r = tg.Renderer(t, positions=p, size=(128, 96), glyph="superquadric")
        first = r.render().image
        self.assertEqual(r.uploads, 1)
        times = {}
        for change in [dict(gamma=1.5), dict(fa_min=0.1), dict(scale=0.5), dict(color="fa"),
                       dict(eye=(30, 20, 40)), dict(ao=True), dict(outlines=True), dict(shadows=True)]:
            t0 = time.perf_counter()
            img = r.render(**change).image
            times[next(iter(change))] = 1000 * (time.perf_counter() - t0)
            self.assertEqual(r.uploads, 1, f"{change} uploaded again")
        self.assertFalse(np.array_equal(first, img), "the changes changed nothing")
        r.set(stride=2)
        r.render()
        self.assertEqual(r.uploads, 2, "a new selection must load and upload")
        print("ms per change from Python: " + ", ".join(f"{k} {v:.1f}" for k, v in times.items()), file=sys.stderr)

    def test_a_failed_reload_leaves_the_renderer_usable(self):
        """A reload that fails after the old session is freed (here the
        underlay file) once left no session: going back to the old options
        drew with none and crashed the interpreter."""
        t, p = points(20)
        r = tg.Renderer(t, positions=p, size=(48, 32))
        first = r.render().image
        with self.assertRaises(ValueError) as cm:
            r.render(plane="z:0", underlay="/nonexistent/underlay.nii")
        self.assertIn("underlay.nii", str(cm.exception))
        again = r.set(plane=None, underlay=None).render().image
        self.assertTrue(np.array_equal(first, again))
        self.assertEqual(r.uploads, 2)

    def test_one_renderer_shared_by_two_threads(self):
        """The core's lock was waited for with the GIL held while the holder
        needed the GIL to finish: two threads on one Renderer deadlocked.
        Each call draws with its own options."""
        t, p = points(50)
        opts = dict(size=(96, 64), glyph="superquadric")
        alone = {g: tg.render(t, positions=p, gamma=g, **opts).image for g in (1.0, 4.0)}
        r = tg.Renderer(t, positions=p, **opts)
        wrong, errors = [], []

        def work(g):
            try:
                for _ in range(4):
                    if not np.array_equal(r.render(gamma=g).image, alone[g]):
                        wrong.append(g)
            except Exception as e:  # reported below, not lost in the thread
                errors.append(e)

        threads = [threading.Thread(target=work, args=(g,), daemon=True) for g in (1.0, 4.0)]
        for th in threads:
            th.start()
        for th in threads:
            th.join(timeout=120)
        self.assertFalse(any(th.is_alive() for th in threads), "deadlocked")
        self.assertEqual(errors, [])
        self.assertEqual(wrong, [])

    def test_one_renderer_handed_between_threads(self):
        """A Renderer made on one thread, reloaded on others and collected on
        yet another: the old session's GL objects were deleted with no context
        current there, and the interpreter crashed (segfault in Mesa). Each
        call makes the context current and releases it, which EGL needs too."""
        t, p = points(20)
        for backend in ("osmesa", "egl"):
            with self.subTest(backend=backend):
                opts = dict(positions=p, backend=backend, glyph="superquadric")
                alone = {w: tg.render(t, size=(w, 32), **opts).image for w in (48, 56, 64)}
                box, wrong, errors = {}, [], []

                def on_thread(f):
                    def run():
                        try:
                            f()
                        except Exception as e:  # reported below, not lost in the thread
                            errors.append(e)
                    th = threading.Thread(target=run)
                    th.start()
                    th.join(timeout=120)
                    self.assertFalse(th.is_alive())

                on_thread(lambda: box.setdefault("r", tg.Renderer(t, size=(48, 32), **opts)))
                for w in (56, 64, 48, 56):  # each a reload: the size changes the session
                    def draw(w=w):
                        if not np.array_equal(box["r"].render(size=(w, 32)).image, alone[w]):
                            wrong.append(w)
                    on_thread(draw)
                    draw(64 if w != 64 else 48)  # and on this thread in turn
                on_thread(lambda: (box.clear(), gc.collect()))
                self.assertEqual(errors, [])
                self.assertEqual(wrong, [])

    def test_a_refused_option_does_not_stay_behind(self):
        t, p = points(10)
        r = tg.Renderer(t, positions=p, size=(32, 24))
        with self.assertRaises(ValueError):
            r.set(gamma=-1)
        self.assertNotIn("gamma", r.options)
        self.assertEqual(r.render().shape, (24, 32, 4))

    def test_progress_reaches_a_python_callback(self):
        import nibabel as nib
        n = (40, 40, 50)  # 80,000 tensors: more than one 65,536-tensor block
        fsl = np.zeros(n + (6,), np.float32)
        fsl[..., 0], fsl[..., 3], fsl[..., 5] = 3.0, 1.0, 0.5
        calls = []
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "dt.nii")
            nib.save(nib.Nifti1Image(fsl, np.eye(4)), path)
            tg.render(path, size=(32, 24), progress=lambda *a: calls.append(a))
            self.assertIn(("eigen", 80000.0, 80000.0, "tensors"), calls)
            # Then the frame, pass by pass: counted up to its total, after the load.
            drawn = [c for c in calls if c[0] == "rendering"]
            self.assertGreater(calls.index(drawn[0]), calls.index(("eigen", 80000.0, 80000.0, "tensors")))
            self.assertEqual({c[3] for c in drawn}, {"passes"})
            self.assertEqual([c[1] for c in drawn], list(range(len(drawn))))
            self.assertGreaterEqual(drawn[-1][2], 2)
            self.assertEqual(drawn[-1][1], drawn[-1][2])
            # A Renderer's later frame, with no reload, reports its passes too.
            calls.clear()
            r = tg.Renderer(path, size=(32, 24), progress=lambda *a: calls.append(a))
            r.render()
            calls.clear()
            r.render(gamma=2.0)
            self.assertTrue(calls)
            self.assertEqual({c[0] for c in calls}, {"rendering"})

            def fail(*a):
                raise KeyError("from the callback")
            with self.assertRaises(KeyError):
                tg.render(path, size=(32, 24), progress=fail)
            with self.assertRaises(TypeError):
                tg.render(path, progress=3)

    def test_two_renderers_in_two_threads(self):
        t, p = points(50)
        alone = [tg.render(t, positions=p, size=(96, 64), gamma=g, glyph="superquadric").image for g in (1.0, 4.0)]
        out = [None, None]
        errors = []

        def work(k, g):
            try:
                r = tg.Renderer(t, positions=p, size=(96, 64), gamma=g, glyph="superquadric")
                for _ in range(3):
                    out[k] = r.render().image
            except Exception as e:  # reported below, not lost in the thread
                errors.append(e)

        threads = [threading.Thread(target=work, args=(k, g)) for k, g in enumerate((1.0, 4.0))]
        for th in threads:
            th.start()
        for th in threads:
            th.join()
        self.assertEqual(errors, [])
        self.assertTrue(np.array_equal(out[0], alone[0]))
        self.assertTrue(np.array_equal(out[1], alone[1]))

    def test_render_from_its_own_progress_callback_raises(self):
        # It waited for the very render that called it: a hang. A reload (a
        # new size) reports progress. All in one thread, which may hang.
        t, p = points(10)
        errors, shapes = [], []

        def work():
            holder = {}

            def again(*a):
                if "r" in holder:
                    holder["r"].render()
            r = tg.Renderer(t, positions=p, size=(32, 24), progress=again)
            holder["r"] = r
            try:
                r.render(size=(40, 30))
            except Exception as e:  # reported below
                errors.append(e)
            del holder["r"]
            shapes.append(r.render(size=(48, 36)).shape)  # the Renderer still works
        th = threading.Thread(target=work, daemon=True)
        th.start()
        th.join(60)
        self.assertFalse(th.is_alive(), "render() from its own progress callback hung")
        self.assertEqual(len(errors), 1)
        self.assertIsInstance(errors[0], RuntimeError)
        self.assertIn("re-entrant", str(errors[0]))
        self.assertEqual(shapes, [(36, 48, 4)])


if __name__ == "__main__":
    unittest.main()


class Stubs(unittest.TestCase):
    """The type stubs generated from the option table (python/make_stubs.py)."""

    def test_stubs_compile_and_type_every_option(self):
        stub = os.path.join(os.path.dirname(tg.__file__), "__init__.pyi")
        with open(stub) as f:
            text = f.read()
        # Valid Python: a keyword taken twice (the module's own `layout` and
        # the table's --layout) was once a SyntaxError for every type checker.
        compile(text, stub, "exec")
        tree = ast.parse(text)
        render = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "render")
        kwargs = {a.arg: ast.unparse(a.annotation) for a in render.args.kwonlyargs}
        for kw in tg.options():
            self.assertIn(kw, kwargs, kw)
        # Typed by what the value is, not every type at once.
        self.assertEqual(kwargs["iterations"], "int | None")
        self.assertEqual(kwargs["gamma"], "float | None")
        self.assertTrue(kwargs["glyph"].startswith("Literal["), kwargs["glyph"])
        self.assertEqual(kwargs["size"], "Sequence[int] | None")
        self.assertEqual(kwargs["eye"], "Sequence[float] | None")
        self.assertEqual(kwargs["mesh"], "str | os.PathLike[str] | Sequence[str | os.PathLike[str]] | None")
        self.assertEqual(kwargs["ao"], "bool | None")
