"""How far two renders' coverage agrees, for tests/bench/peers.sh.

usage: peer_mask_diff.py A.png CHANNEL_A B.png CHANNEL_B
A pixel is covered where the channel (0-based; tensorglyph's alpha is 3, a
mask's 0) exceeds 127. Prints the covered pixels of each, those covered by
one only, and those of each farther than one pixel from the other's (a
tessellated and an exact silhouette differ by a pixel along thin glyphs; a
wrong camera, scale or orientation does not stay within one).
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def mask(path, channel):
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    im = r.GetOutput()
    w, h, _ = im.GetDimensions()
    return vtk_to_numpy(im.GetPointData().GetScalars()).reshape(h, w, -1)[..., channel] > 127


def grow(m):
    out = m.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            out |= np.roll(np.roll(m, dy, 0), dx, 1)
    return out


if len(sys.argv) != 5:
    sys.exit(__doc__)
a, b = mask(sys.argv[1], int(sys.argv[2])), mask(sys.argv[3], int(sys.argv[4]))
if a.shape != b.shape:
    sys.exit(f"peer_mask_diff.py: the images differ in size: {a.shape} and {b.shape}")
print(f"{a.sum()} {b.sum()} {(a ^ b).sum()} {(a & ~grow(b)).sum()} {(b & ~grow(a)).sum()}")
