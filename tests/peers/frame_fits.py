"""DWIs fitted with tensors by DIPY, correct and with the b-table mirrored,
for the frame check (app/frame_check.h).

usage: frame_fits.py OUTDIR [TILES]
For NAME in small_64D and small_101D (DIPY's bundled DWIs) and sim (a DWI
simulated here of three known bundles, see simulated_dwi), writes
OUTDIR/NAME.nii (the fit, FSL's order xx xy xz yy yz zz, 4-D, in the axes
of the b-vectors as given: read with --frame voxel) and
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
from dipy.sims.voxel import add_noise

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


def simulated_dwi(bvals, bvecs, affine):
    """A 40x40x30 DWI in voxel axes (2 mm, small_64D's oblique affine) of
    three bundles of known direction, each a tube 2.5 voxels in radius: an
    arc in the i-j plane, a straight bundle along (1, 1, 1) and a helix about
    k; isotropic tissue elsewhere in an ellipsoidal brain. Signals
    S0 exp(-b g'Dg) with the b-vectors as given, DIPY's Rician noise at SNR
    20. The tensors are in the b-vectors' axes, so a fit with them as given
    is correct in the voxel frame."""
    shape = (40, 40, 30)
    i, j, k = np.meshgrid(*[np.arange(n, dtype=np.float64) for n in shape], indexing="ij")
    p = np.stack([i, j, k], -1)
    c = np.array([19.5, 19.5, 14.5])
    best = np.full(shape, np.inf)
    axis = np.zeros(shape + (3,))

    def bundle(dist, tangent):
        closer = (dist < 2.5) & (dist < best)
        best[closer] = dist[closer]
        axis[closer] = tangent[closer]

    # The arc: a circle of radius 12 about c in the plane k = 10.
    d = p - c
    r = np.hypot(d[..., 0], d[..., 1]) + 1e-9
    bundle(np.hypot(r - 12, k - 10), np.stack([-d[..., 1] / r, d[..., 0] / r, 0 * r], -1))
    # The straight bundle through c along (1, 1, 1).
    u = np.ones(3) / np.sqrt(3)
    along = d @ u
    bundle(np.linalg.norm(d - along[..., None] * u, axis=-1), np.broadcast_to(u, shape + (3,)))
    # The helix: radius 6 about the k axis through c, 2 turns over k 4..26.
    turn = 2 * np.pi * 2 / 22
    phase = (k - 4) * turn
    hx, hy = c[0] + 6 * np.cos(phase), c[1] + 6 * np.sin(phase)
    tangent = np.stack([-6 * turn * np.sin(phase), 6 * turn * np.cos(phase), np.ones(shape)], -1)
    tangent /= np.linalg.norm(tangent, axis=-1, keepdims=True)
    inside = (k >= 4) & (k <= 26)
    bundle(np.where(inside, np.hypot(i - hx, j - hy), np.inf), tangent)

    brain = ((d / np.array([19, 19, 14])) ** 2).sum(-1) <= 1
    fibre = np.isfinite(best) & brain
    lo, hi, iso = 0.3e-3, 1.7e-3, 0.8e-3
    D = np.where(brain[..., None, None], iso * np.eye(3), 0.0)
    D[fibre] = lo * np.eye(3) + (hi - lo) * axis[fibre][:, :, None] * axis[fibre][:, None, :]
    g = np.nan_to_num(bvecs)  # small_64D gives its b0 vector as NaN
    g = g / np.maximum(np.linalg.norm(g, axis=1, keepdims=True), 1e-12)
    signal = 100 * np.exp(-bvals * np.einsum("na,...ab,nb->...n", g, D, g))
    np.random.seed(7)  # add_noise draws from NumPy's global generator
    signal = add_noise(signal, snr=20, S0=100, noise_type="rician")
    signal[~brain] = 0
    return signal, brain, affine


def fsl_order(fit):
    q = fit.quadratic_form
    return np.stack([q[..., 0, 0], q[..., 0, 1], q[..., 0, 2], q[..., 1, 1], q[..., 1, 2], q[..., 2, 2]], -1)


for name in ("small_64D", "small_101D", "sim"):
    fdata, fbval, fbvec = get_fnames("small_64D" if name == "sim" else name)
    img = nib.load(fdata)
    bvals, bvecs = read_bvals_bvecs(fbval, fbvec)
    if name == "sim":
        data, mask, affine = simulated_dwi(bvals, bvecs, img.affine)
    else:
        data = np.asanyarray(img.dataobj).astype(np.float64)
        b0 = data[..., bvals < 50].mean(-1)
        mask = b0 > 0.2 * np.percentile(b0[b0 > 0], 95)
        affine = img.affine
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
        nib.save(nib.Nifti1Image(t, affine), f"{out}/{name}{suffix}.nii")
        if name == "small_64D" and suffix == "" and len(sys.argv) > 2:
            n = int(sys.argv[2])
            nib.save(nib.Nifti1Image(np.tile(t, (n, n, max(1, n // 2), 1)), affine), f"{out}/tiled.nii")
