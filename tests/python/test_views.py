"""Anatomical views, orientation letters and slices in anatomical terms
(issue 32 items 1 and 2), checked from the id channel against the voxels'
world positions: DIPY's small_64D fitted here (an oblique PLS affine), and
the published helices of ../shared/data/real (Slicer's in RAS, Kindlmann's
without a space)."""
import os
import unittest

import numpy as np

import tensorglyph as tg
from test_module import fit_small_64d

REAL = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "real")
SLICER_HELIX = os.path.join(REAL, "slicer-helix-dti-masked", "helix-DTI.nhdr")
KINDLMANN_HELIX = os.path.join(REAL, "kindlmann-dt-helix", "dt-helix.nhdr")
KITTEN = os.path.join(REAL, "tsv-kitten-stress", "kitten-stress.vtu")
EMPTY = 0xFFFFFFFF
W, H = 320, 240

# What the image's columns (left to right) and rows (top to bottom) run
# towards, as (world axis, sign): R = +x, A = +y, S = +z.
EXPECTED = {
    ("axial", "neurological"): ((0, +1), (1, -1)),   # R on the right, A at the top
    ("axial", "radiological"): ((0, -1), (1, -1)),   # R on the left
    ("coronal", "neurological"): ((0, +1), (2, -1)),  # seen from behind, S at the top
    ("coronal", "radiological"): ((0, -1), (2, -1)),  # facing the patient
    ("sagittal", "neurological"): ((1, -1), (2, -1)),  # the nose on the left
    ("sagittal", "radiological"): ((1, -1), (2, -1)),
}


def convention(name):
    return {"radiological": True} if name == "radiological" else {"neurological": True}


def world_of_hits(ids, shape, affine):
    """Per drawn pixel: its column, row and its voxel's world position."""
    rows, cols = np.nonzero(ids != EMPTY)
    i, j, k = np.unravel_index(ids[rows, cols].astype(np.int64), shape, order="F")  # the id runs i fastest
    ijk1 = np.stack([i, j, k, np.ones_like(i)]).astype(float)
    return cols, rows, (affine @ ijk1)[:3].T, np.stack([i, j, k], axis=1)


class Views(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.img, cls.fit = fit_small_64d()

    def check_axes(self, cols, rows, world, view, conv):
        (ca, cs), (ra, rs) = EXPECTED[(view, conv)]
        c = np.corrcoef(cols, world[:, ca])[0, 1]
        r = np.corrcoef(rows, world[:, ra])[0, 1]
        self.assertGreater(cs * c, 0.8, f"{view} {conv}: columns against world axis {ca}: r = {c:.3f}")
        self.assertGreater(rs * r, 0.8, f"{view} {conv}: rows against world axis {ra}: r = {r:.3f}")

    def test_dipy_views_follow_world_axes_in_both_conventions(self):
        for (view, conv) in EXPECTED:
            fig = tg.render(self.fit, affine=self.img.affine, view=view, size=(W, H), channels=True,
                            **convention(conv))
            cols, rows, world, _ = world_of_hits(fig.channels["id"], self.fit.shape, self.img.affine)
            self.assertGreater(cols.size, 1000)
            self.check_axes(cols, rows, world, view, conv)

    def test_default_dti_camera_is_axial_neurological(self):
        default = tg.render(self.fit, affine=self.img.affine, size=(W, H), channels=True)
        axial = tg.render(self.fit, affine=self.img.affine, size=(W, H), channels=True, view="axial",
                          neurological=True)
        np.testing.assert_array_equal(default.channels["id"], axial.channels["id"])

    @unittest.skipUnless(os.path.isdir(REAL), "no published datasets at " + REAL)
    def test_helix_views_follow_world_axes(self):
        # Both helices have positive axis spacings along x, y, z: a voxel's
        # index runs with its world coordinate.
        for path, dims in ((SLICER_HELIX, (64, 32, 16)), (KINDLMANN_HELIX, (38, 39, 40))):
            for (view, conv) in EXPECTED:
                fig = tg.render(path, view=view, size=(W, H), channels=True, **convention(conv))
                cols, rows, _, ijk = world_of_hits(fig.channels["id"], dims, np.eye(4))
                self.check_axes(cols, rows, ijk.astype(float), view, conv)


def edge_boxes():
    """The middle of each edge, where the letters sit (left, right, top, bottom)."""
    m = 48
    return [(slice(H // 2 - m, H // 2 + m), slice(0, m)), (slice(H // 2 - m, H // 2 + m), slice(W - m, W)),
            (slice(0, m), slice(W // 2 - m, W // 2 + m)), (slice(H - m, H), slice(W // 2 - m, W // 2 + m))]


class Letters(unittest.TestCase):
    def differs(self, a, b):
        d = np.any(np.asarray(a) != np.asarray(b), axis=2)
        inside = np.zeros_like(d)
        for box in edge_boxes():
            inside[box] = True
        return [bool(d[box].any()) for box in edge_boxes()], bool(d[~inside].any())

    def test_letters_on_anatomical_volumes_by_default(self):
        img, fit = fit_small_64d()
        on = tg.render(fit, affine=img.affine, size=(W, H))
        off = tg.render(fit, affine=img.affine, size=(W, H), orientation_letters="off")
        edges, elsewhere = self.differs(on, off)
        self.assertEqual(edges, [True] * 4, "a letter at each edge")
        self.assertFalse(elsewhere, "nothing drawn beyond the letters")

    @unittest.skipUnless(os.path.isdir(REAL), "no published datasets at " + REAL)
    def test_letters_follow_the_space(self):
        # Slicer's helix says RAS: letters; Kindlmann's has no space and the
        # kitten is an FEM mesh: none, unless forced on.
        for path, anatomical in ((SLICER_HELIX, True), (KINDLMANN_HELIX, False), (KITTEN, False)):
            default = tg.render(path, size=(W, H))
            off = tg.render(path, size=(W, H), orientation_letters="off")
            on = tg.render(path, size=(W, H), orientation_letters="on")
            self.assertEqual(self.differs(default, off)[0], [anatomical] * 4, path)
            edges, elsewhere = self.differs(on, off)
            self.assertEqual(edges, [True] * 4, path)
            self.assertFalse(elsewhere, path)


class Slices(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.img, cls.fit = fit_small_64d()
        A = cls.img.affine[:3, :3]
        # The voxel axis nearest each world axis: small_64D's i runs mostly
        # posterior, j left, k superior (14 degrees off).
        cls.nearest = [int(np.argmax(np.abs(A[w]) / np.linalg.norm(A, axis=0))) for w in range(3)]
        assert cls.nearest == [1, 0, 2], cls.nearest

    def face_on_tilt(self, fig, ortho):
        """The slope of the glyphs' nearest depth across the image, in world
        units per world unit: 0 for a slice seen face-on."""
        ids, depth = fig.channels["id"], fig.channels["depth"]
        rows, cols = np.nonzero(ids != EMPTY)
        px = ortho / H  # world units a pixel
        near = {}
        for r, c in zip(rows, cols):
            g = int(ids[r, c])
            d = float(depth[r, c])
            if g not in near or d < near[g][0]:
                near[g] = (d, c * px, r * px)
        pts = np.array(list(near.values()))
        A = np.c_[pts[:, 1], pts[:, 2], np.ones(len(pts))]
        slope = np.linalg.lstsq(A, pts[:, 0], rcond=None)[0][:2]
        return float(np.hypot(*slope))

    def test_anatomical_slice_picks_the_nearest_voxel_axis_seen_face_on(self):
        ortho = 30.0
        for plane, world_axis in (("axial", 2), ("coronal", 1), ("sagittal", 0)):
            fig = tg.render(self.fit, affine=self.img.affine, slice=f"{plane}:5", size=(W, H), ortho=ortho,
                            channels=True)
            _, _, _, ijk = world_of_hits(fig.channels["id"], self.fit.shape, self.img.affine)
            axis = self.nearest[world_axis]
            self.assertTrue(np.all(ijk[:, axis] == 5), f"{plane}:5 keeps index 5 of voxel axis {axis}")
            self.assertLess(self.face_on_tilt(fig, ortho), 0.08, f"{plane}:5 seen face-on")
        # The same slab seen down world z, as the camera was fixed before: tilted by the grid's 14 degrees.
        tilted = tg.render(self.fit, affine=self.img.affine, slice="axial:5", size=(W, H), ortho=ortho,
                           channels=True, view="superior")
        self.assertGreater(self.face_on_tilt(tilted, ortho), 0.15)

    def test_voxel_axis_slice_keeps_its_meaning_and_is_seen_face_on(self):
        ortho = 30.0
        fig = tg.render(self.fit, affine=self.img.affine, slice="x:5", size=(W, H), ortho=ortho, channels=True)
        _, _, world, ijk = world_of_hits(fig.channels["id"], self.fit.shape, self.img.affine)
        self.assertTrue(np.all(ijk[:, 0] == 5), "x:5 is voxel axis i, as ever")
        self.assertLess(self.face_on_tilt(fig, ortho), 0.08)

    def test_world_position_slice_is_the_nearest(self):
        A, t = self.img.affine[:3, :3], self.img.affine[:3, 3]
        centre = np.array([4.5, 4.5, 4.5])
        for k in (2, 7):
            z = (t + A @ np.array([centre[0], centre[1], k]))[2]
            fig = tg.render(self.fit, affine=self.img.affine, slice=f"z={z + 0.3:.3f}mm", size=(W, H), channels=True)
            _, _, _, ijk = world_of_hits(fig.channels["id"], self.fit.shape, self.img.affine)
            self.assertTrue(np.all(ijk[:, 2] == k), f"z={z:.3f} is slice {k} of voxel axis k")
        with self.assertRaisesRegex(ValueError, r"slice z=500\b.*index \d+ along voxel axis k\b.*0\.\.9"):
            tg.render(self.fit, affine=self.img.affine, slice="z=500", size=(W, H))

    def test_stride_thins_within_the_slice_and_grows_the_glyphs(self):
        ortho = 30.0
        areas = {}
        for stride in (1, 2):
            fig = tg.render(self.fit, affine=self.img.affine, slice="axial:5", stride=stride, size=(W, H),
                            ortho=ortho, channels=True)
            ids = fig.channels["id"]
            drawn = ids[ids != EMPTY]
            _, _, _, ijk = world_of_hits(ids, self.fit.shape, self.img.affine)
            self.assertTrue(np.all(ijk[:, 2] == 5))
            if stride == 2:
                self.assertTrue(np.all(ijk[:, :2] % 2 == 0), "thinned within the slice only")
            areas[stride] = drawn.size / np.unique(drawn).size
        # Twice the spacing: about four times the pixels a glyph.
        self.assertGreater(areas[2] / areas[1], 2.5)


if __name__ == "__main__":
    unittest.main()
