"""Fibre fields with no mirror in them, for the frame check's calibration
(app/frame_check.h, kStandOut).

usage: frame_null_fields.py OUTDIR COUNT SHAPE SIGMA SEED
Writes OUTDIR/null-NNN.nii: COUNT fields of SHAPE (e.g. 10x15x20) voxels whose
principal axes are white-noise vectors smoothed by a Gaussian of SIGMA
voxels (periodic), eigenvalues 1.7e-3 and 0.3e-3 (FA 0.8), FSL's order, in
the voxel frame under a det < 0 affine. Such a field is isotropic: a flip
or permutation of its tensors is as likely a field as the field itself, so
any reading that scores clearly better than as read is a false alarm.
"""
import os
import sys

import numpy as np
import nibabel as nib
from scipy.ndimage import gaussian_filter

out, count, shape, sigma, seed = sys.argv[1], int(sys.argv[2]), sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
shape = tuple(int(x) for x in shape.split("x"))
os.makedirs(out, exist_ok=True)
rng = np.random.default_rng(seed)
for n in range(count):
    v = rng.standard_normal(shape + (3,))
    for c in range(3):
        v[..., c] = gaussian_filter(v[..., c], sigma, mode="wrap")
    v /= np.linalg.norm(v, axis=-1, keepdims=True)
    lo, hi = 0.3e-3, 1.7e-3
    D = lo * np.eye(3) + (hi - lo) * v[..., :, None] * v[..., None, :]
    t = np.stack([D[..., 0, 0], D[..., 0, 1], D[..., 0, 2], D[..., 1, 1], D[..., 1, 2], D[..., 2, 2]], -1)
    nib.save(nib.Nifti1Image(t.astype(np.float32), np.diag([-2.0, 2.0, 2.0, 1.0])), f"{out}/null-{n:03d}.nii")
