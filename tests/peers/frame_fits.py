"""DIPY's bundled DWIs fitted with tensors, correct and with the b-table
mirrored, for the frame check (app/frame_check.h).

usage: frame_fits.py OUTDIR [TILES]
Writes OUTDIR/NAME.nii (the fit, FSL's order xx xy xz yy yz zz, 4-D, in
the axes of the b-vectors as given: read with --frame voxel) and
OUTDIR/NAME-flip-A.nii for A in x, y, z (the same DWI fitted with b-vector
component A negated, the commonest b-table error), and NAME-swap-xy.nii
(x and y swapped). With TILES, OUTDIR/tiled.nii: small_64D's fit repeated
TILES times along each axis (a whole-brain size for timing).
"""
import os
import sys

import numpy as np
import nibabel as nib
from dipy.core.gradients import gradient_table
from dipy.data import get_fnames
from dipy.io.gradients import read_bvals_bvecs
from dipy.reconst.dti import TensorModel

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


def fsl_order(fit):
    q = fit.quadratic_form
    return np.stack([q[..., 0, 0], q[..., 0, 1], q[..., 0, 2], q[..., 1, 1], q[..., 1, 2], q[..., 2, 2]], -1)


for name in ("small_64D", "small_101D"):
    fdata, fbval, fbvec = get_fnames(name)
    img = nib.load(fdata)
    data = np.asanyarray(img.dataobj).astype(np.float64)
    bvals, bvecs = read_bvals_bvecs(fbval, fbvec)
    b0 = data[..., bvals < 50].mean(-1)
    mask = b0 > 0.2 * np.percentile(b0[b0 > 0], 95)
    variants = {"": bvecs}
    for a in range(3):
        flipped = bvecs.copy()
        flipped[:, a] = -flipped[:, a]
        variants["-flip-" + "xyz"[a]] = flipped
    variants["-swap-xy"] = bvecs[:, [1, 0, 2]]
    for suffix, bv in variants.items():
        fit = TensorModel(gradient_table(bvals, bvecs=bv)).fit(data, mask=mask)
        t = fsl_order(fit).astype(np.float32)
        t[~mask] = 0
        nib.save(nib.Nifti1Image(t, img.affine), f"{out}/{name}{suffix}.nii")
        if name == "small_64D" and suffix == "" and len(sys.argv) > 2:
            n = int(sys.argv[2])
            nib.save(nib.Nifti1Image(np.tile(t, (n, n, max(1, n // 2), 1)), img.affine), f"{out}/tiled.nii")
