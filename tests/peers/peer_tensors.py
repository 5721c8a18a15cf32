"""Tensor files written by real peers, from one synthetic DWI whose world
tensors are known: MRtrix's dwi2tensor, DIPY's ReconstDtiFlow (5-D SYMMATRIX,
and 4-D upper triangle with nifti_tensor=False), and DIPY's
lower_triangular() saved as a plain 4-D image. FSL's convention comes from
MRtrix's own FSL export (mrinfo -export_grad_fsl), which FSL's dtifit reads.

usage: peer_tensors.py OUTDIR DET   (DET: "pos" or "neg", the affine's sign)
Writes OUTDIR/truth.txt: "i j k xx xy xz yy yz zz" per voxel, world frame.
"""
import os
import subprocess
import sys

import numpy as np
import nibabel as nib
from dipy.core.gradients import gradient_table
from dipy.io.utils import nifti1_symmat
from dipy.reconst.dti import TensorModel, lower_triangular
from dipy.workflows.reconst import ReconstDtiFlow

out, det = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
rng = np.random.default_rng(11)


def rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


# Voxel grid: rotated, anisotropic, with the handedness asked for.
R = rotation([1, -2, 0.5], 0.6)
scale = np.diag([-2.0 if det == "neg" else 2.0, 2.2, 2.5])
affine = np.eye(4)
affine[:3, :3] = R @ scale
affine[:3, 3] = [-10, 4, 7]
dims = (3, 3, 2)

# One distinct prolate tensor per voxel, world (scanner RAS) frame, mm^2/s.
world = np.zeros(dims + (3, 3))
for idx in np.ndindex(dims):
    Q = rotation(rng.normal(size=3), rng.uniform(0, np.pi))
    world[idx] = Q @ np.diag([1.7e-3, rng.uniform(0.2, 0.6) * 1e-3, 0.2e-3]) @ Q.T

# 30 gradient directions in world axes, one b0; noise-free signal.
g = rng.normal(size=(30, 3))
g /= np.linalg.norm(g, axis=1)[:, None]
g = np.vstack([[0, 0, 0], g])
b = np.array([0] + [1000] * 30, float)
signal = 1000 * np.exp(-b * np.einsum("ni,...ij,nj->...n", g, world, g))
nib.save(nib.Nifti1Image(signal.astype(np.float32), affine), f"{out}/dwi.nii")
np.savetxt(f"{out}/grad.b", np.column_stack([g, b]), fmt="%.10f")

# MRtrix: gradients in scanner axes; dwi2tensor writes D11 D22 D33 D12 D13 D23.
run = lambda *a: subprocess.run(a, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
run("dwi2tensor", "-quiet", "-force", "-grad", f"{out}/grad.b", f"{out}/dwi.nii", f"{out}/mrtrix.nii")
# FSL's b-vectors for this image, as MRtrix exports them for FSL.
run("mrinfo", "-quiet", "-grad", f"{out}/grad.b", f"{out}/dwi.nii", "-export_grad_fsl", f"{out}/fsl.bvec",
    f"{out}/fsl.bval")
# The same directions in plain voxel axes: the orthogonal part of the affine.
u, _, vt = np.linalg.svd(affine[:3, :3])
Qv = u @ vt
np.savetxt(f"{out}/voxel.bvec", (g @ Qv).T, fmt="%.10f")
np.savetxt(f"{out}/voxel.bval", b[None, :], fmt="%g")

# DIPY's workflow, as `dipy_fit_dti` runs it: FSL b-vectors give tensors in
# FSL's frame, saved 4-D in upper-triangle order (nifti_tensor=False);
# voxel b-vectors give voxel-frame tensors, saved 5-D with the SYMMATRIX intent.
nib.save(nib.Nifti1Image(np.ones(dims, np.uint8), affine), f"{out}/mask.nii")
for name, bvec, nifti_tensor in (("dipy-fsl", "fsl", False), ("dipy-voxel", "voxel", True)):
    ReconstDtiFlow().run(f"{out}/dwi.nii", f"{out}/{bvec}.bval", f"{out}/{bvec}.bvec", f"{out}/mask.nii",
                         fit_method="WLS", save_metrics=["tensor"], out_dir=out, out_tensor=f"{name}.nii.gz", nifti_tensor=nifti_tensor)

# A script's save: tenfit.lower_triangular() as a plain 4-D image.
fit = TensorModel(gradient_table(b, np.loadtxt(f"{out}/voxel.bvec"))).fit(signal)
nib.save(nib.Nifti1Image(fit.lower_triangular().astype(np.float32), affine), f"{out}/dipy-script.nii")

with open(f"{out}/truth.txt", "w") as t:
    for (i, j, k) in np.ndindex(dims):
        d = world[i, j, k]
        t.write(f"{i} {j} {k} " + " ".join(f"{x:.12e}" for x in (d[0, 0], d[0, 1], d[0, 2], d[1, 1], d[1, 2], d[2, 2]))
                + "\n")
