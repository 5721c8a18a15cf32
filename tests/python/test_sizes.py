"""Issue 31's sizes through the module: arrays are sized by the whole field
before a selection, so one tensor covers the same pixels on a slice and on
that slice cut by an ROI; --sizes-from selection brings back the old size."""
import unittest

import numpy as np

import tensorglyph as tg

from test_module import fit_small_64d


def pixels_per_glyph(fig):
    ids = fig.channels["id"]
    hit = ids != np.iinfo(ids.dtype).max
    values, counts = np.unique(ids[hit], return_counts=True)
    return dict(zip(values.tolist(), counts.tolist()))


class Sizes(unittest.TestCase):
    def test_a_slice_and_its_roi_draw_one_tensor_alike(self):
        img, fit = fit_small_64d()
        A = img.affine
        k = 5
        centre = A @ np.array([4.5, 4.5, k, 1.0])
        normal = A[:3, 2] / np.linalg.norm(A[:3, 2])
        cam = dict(size=(320, 320), ortho=24.0, eye=centre[:3] + 100.0 * normal, look_at=centre[:3],
                   up=A[:3, 0] / np.linalg.norm(A[:3, 0]), channels=True)
        # The ROI: the voxels i <= 4 of the slice, in world coordinates.
        corners = np.array([A @ np.array([i, j, k, 1.0]) for i in (-0.5, 4.4) for j in (-0.5, 9.5)])[:, :3]
        lo, hi = corners.min(axis=0) - [0, 0, 1], corners.max(axis=0) + [0, 0, 1]
        roi = tuple(lo) + tuple(hi)
        whole = tg.render(fit, affine=A, slice=f"z:{k}", **cam)
        cut = tg.render(fit, affine=A, slice=f"z:{k}", roi=roi, **cam)
        own = tg.render(fit, affine=A, slice=f"z:{k}", roi=roi, sizes_from="selection", **cam)
        a, b, c = pixels_per_glyph(whole), pixels_per_glyph(cut), pixels_per_glyph(own)
        self.assertLess(len(b), len(a))
        compared = 0
        for gid, n in b.items():
            if gid in a and n >= 20:
                self.assertAlmostEqual(a[gid], n, delta=0.1 * n, msg=f"glyph {gid}")
                compared += 1
        self.assertGreater(compared, 5)
        # Sized by the ROI alone the same glyphs differ (else this test shows nothing).
        self.assertNotEqual(sum(c.get(g, 0) for g in b), sum(b.values()))


if __name__ == "__main__":
    unittest.main()
