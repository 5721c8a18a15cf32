"""Component orders of (N, 6) and (X, Y, Z, 6) arrays (issue 31): the CLI's
--layout names, and refusal over guessing where the default order is
implausible."""
import unittest
import warnings

import numpy as np

import tensorglyph as tg

from test_module import fit_small_64d

OPTS = dict(size=(64, 48))
ORDERS = {  # stored index of xx xy xz yy yz zz, as the CLI's table
    "abaqus": (0, 3, 4, 1, 5, 2),  # S11 S22 S33 S12 S13 S23
    "voigt": (0, 5, 4, 1, 3, 2),   # xx yy zz yz xz xy
    "vtk": (0, 3, 5, 1, 4, 2),     # xx yy zz xy yz xz
}


def stored(full, layout):
    """(N, 3, 3) tensors as six values in `layout`'s order."""
    sym = np.stack([full[:, 0, 0], full[:, 0, 1], full[:, 0, 2], full[:, 1, 1], full[:, 1, 2], full[:, 2, 2]], 1)
    out = np.empty_like(sym)
    out[:, list(ORDERS[layout])] = sym
    return out


def stress_states(n, rng):
    """Indefinite symmetric tensors (stress), none of them diffusion-like."""
    a = rng.normal(size=(n, 3, 3))
    s = a + a.transpose(0, 2, 1)
    return s - 2 * np.abs(s).max() * np.eye(3) * (np.arange(3) == 1)


def quiet(f):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return f()


class Layouts(unittest.TestCase):
    def test_lower_triangular_is_refused_naming_its_order(self):
        """DIPY's fit.lower_triangular() is xx xy yy xz yz zz ("nifti"):
        read in the default "fsl" most tensors are indefinite and "nifti" is
        the one order that reads them as diffusion tensors. Once warned and
        drawn wrong; now refused, naming the keyword and the order."""
        img, fit = fit_small_64d()
        with self.assertRaisesRegex(ValueError, r'^layout: .*indefinite.* as fsl .*only layout="nifti" reads them'):
            tg.render(fit.lower_triangular(), affine=img.affine, **OPTS)
        right = quiet(lambda: tg.render(fit.lower_triangular(), affine=img.affine, layout="nifti", **OPTS))
        self.assertTrue(np.array_equal(right, tg.render(fit, affine=img.affine, **OPTS)))
        # Named, the implausible order is drawn; its warning names "nifti" only.
        with self.assertWarnsRegex(UserWarning, r'try layout="nifti"$'):
            tg.render(fit.lower_triangular(), affine=img.affine, layout="fsl", **OPTS)

    def test_a_nibabel_image_is_refused_as_its_file_is(self):
        """lower_triangular() saved as a plain 4-D NIfTI: the CLI refuses the
        file, naming --layout nifti; the same image through nibabel once drew
        it in FSL's order with a warning."""
        import os
        import tempfile
        import nibabel as nib
        img, fit = fit_small_64d()
        saved = nib.Nifti1Image(fit.lower_triangular().astype(np.float32), img.affine)
        with self.assertRaisesRegex(ValueError, r'only layout="nifti" reads them plausibly'):
            tg.render(saved, **OPTS)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "lower.nii")
            nib.save(saved, path)
            with self.assertRaisesRegex(ValueError, r"only --layout nifti --frame voxel reads them plausibly"):
                tg.render(path, **OPTS)
        quiet(lambda: tg.render(saved, layout="nifti", **OPTS))

    def test_abaqus_vectors_need_their_order(self):
        """(N, 6) stress in Abaqus order with no layout: once read as FSL's
        order without a word. No order reads stress as diffusion tensors, and
        off a plane nothing else tells: refused, asking for the order. Named,
        each FEM order draws what the 3x3 tensors draw, without a warning."""
        rng = np.random.default_rng(4)
        full = stress_states(40, rng)
        pos = rng.uniform(0, 10, (40, 3))
        with self.assertRaisesRegex(ValueError, r"^layout: .*no order reads them plausibly: name theirs \(.*abaqus"):
            tg.render(stored(full, "abaqus"), positions=pos, **OPTS)
        expected = tg.render(full, positions=pos, **OPTS)
        for name in ORDERS:
            with self.subTest(layout=name):
                drawn = quiet(lambda: tg.render(stored(full, name), positions=pos, layout=name, **OPTS))
                self.assertTrue(np.array_equal(drawn, expected))
        # paraview is VTK's order under ParaView's name.
        self.assertTrue(np.array_equal(tg.render(stored(full, "vtk"), positions=pos, layout="paraview", **OPTS),
                                       expected))

    def test_one_stress_state_in_its_order_draws_no_warning(self):
        """Once layout="mrtrix", the right order, warned and pointed to an
        order that reads the tensor as indefinite as well."""
        s = np.array([[100.0, -20.0, -20.0, 5.0, 0.0, 0.0]])  # xx yy zz xy xz yz
        quiet(lambda: tg.render(s, positions=np.zeros((1, 3)), layout="mrtrix", **OPTS))

    def test_a_plate_in_the_wrong_order_warns_naming_only_a_plausible_one(self):
        """Points in the x-z plane: a plate's out-of-plane shears (xy, yz)
        are zero. Abaqus values read as VTK's order put S13 there: the
        warning names abaqus (and voigt, which reads the same tensors here),
        both of which read the plate plausibly."""
        u, v = np.meshgrid(np.linspace(1, 3, 6), np.linspace(-2, 2, 6))
        u, v = u.ravel(), v.ravel()
        full = np.zeros((u.size, 3, 3))
        full[:, 0, 0], full[:, 2, 2] = 50 + 10 * u, -30 + 5 * v
        full[:, 0, 2] = full[:, 2, 0] = 20 + u * v
        pos = np.stack([u, np.zeros_like(u), v], 1)
        with self.assertWarnsRegex(UserWarning, r'out-of-plane shear .* as vtk .*; try layout="abaqus" \(or voigt'):
            tg.render(stored(full, "abaqus"), positions=pos, layout="vtk", **OPTS)
        drawn = quiet(lambda: tg.render(stored(full, "abaqus"), positions=pos, layout="abaqus", **OPTS))
        self.assertTrue(np.array_equal(drawn, tg.render(full, positions=pos, **OPTS)))

    def test_unknown_names_list_every_order(self):
        with self.assertRaisesRegex(ValueError, r"layout: unknown order \"S\"; choose fsl, nifti, mrtrix, vtk, "
                                                r"paraview, abaqus or voigt"):
            tg.render(np.ones((2, 6)), positions=np.zeros((2, 3)), layout="S", **OPTS)


if __name__ == "__main__":
    unittest.main()
