"""Fit DIPY's bundled small_64D DWI with a tensor model and render the fit.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/dipy_small_64d.py small_64d.png
"""
import sys

import nibabel as nib
from dipy.core.gradients import gradient_table
from dipy.data import get_fnames
from dipy.io.gradients import read_bvals_bvecs
from dipy.reconst.dti import TensorModel

import tensorglyph as tg

fdata, fbval, fbvec = get_fnames("small_64D")
img = nib.load(fdata)
bvals, bvecs = read_bvals_bvecs(fbval, fbvec)
fit = TensorModel(gradient_table(bvals, bvecs)).fit(img.get_fdata())

# DIPY's tensors are in the image's voxel axes: the module's default frame
# for a TensorFit ("voxel"); the affine places them in world space.
r = tg.Renderer(fit, affine=img.affine, glyph="superquadric", color="dec", size=(800, 600), legend=True)
fig = r.render()
fig.save(sys.argv[1] if len(sys.argv) > 1 else "small_64d.png")
# A change of gamma or FA threshold draws again without uploading.
r.render(gamma=1.5, fa_min=0.2).save("small_64d_gamma1.5.png")
print(f"{fig.glyphs} glyphs, {r.uploads} upload(s)")
