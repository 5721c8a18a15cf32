"""Tract files written by nibabel (and MRtrix's tckconvert), with the points
nibabel.streamlines reads back from each, for tests/io/test_tracts.cpp.

    peer_tracts.py OUT_DIR [FIBRE_VTK]

For each case NAME it writes NAME.tck or NAME.trk, NAME.points (float32 x y z,
RAS+ mm, as nibabel loads them), NAME.lengths (int64 points per streamline)
and, for .trk, NAME.affine (float64 4x4 row-major: nibabel's
get_affine_trackvis_to_rasmm). With FIBRE_VTK (Slicer's polylines) it also
writes that file's lines as VTK reads them (vtk.points, vtk.lengths), and
as .tck and .trk through nibabel and as .tck through MRtrix's tckconvert.
"""
import os
import subprocess
import sys

import numpy as np
import nibabel as nib
from nibabel.streamlines import Field, Tractogram
from nibabel.streamlines.trk import get_affine_trackvis_to_rasmm, header_2_dtype


def streamlines(rng, n, scale=40.0):
    out = []
    for _ in range(n):
        m = int(rng.integers(2, 30))
        start = rng.uniform(-scale, scale, 3)
        steps = rng.normal(0.0, 1.0, (m, 3))
        out.append((start + np.cumsum(steps, axis=0)).astype(np.float32))
    return out


def dump(out, name, path):
    loaded = nib.streamlines.load(path)
    s = loaded.streamlines
    np.asarray(s.get_data(), dtype="<f4").tofile(os.path.join(out, name + ".points"))
    np.asarray(s._lengths, dtype="<i8").tofile(os.path.join(out, name + ".lengths"))
    if path.endswith(".trk"):
        a = get_affine_trackvis_to_rasmm(loaded.header).astype("<f8")
        a.tofile(os.path.join(out, name + ".affine"))


def rotation(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q


def write_trk(out, name, lines, affine, dims, sizes, order, scalars=0, properties=0, rng=None):
    header = {Field.VOXEL_TO_RASMM: affine.astype(np.float32), Field.DIMENSIONS: np.array(dims, np.int16),
              Field.VOXEL_SIZES: np.array(sizes, np.float32), Field.VOXEL_ORDER: order.encode()}
    per_point = {}
    per_line = {}
    if scalars:
        per_point["s"] = [rng.normal(size=(len(l), scalars)).astype(np.float32) for l in lines]
    if properties:
        per_line["p"] = rng.normal(size=(len(lines), properties)).astype(np.float32)
    t = Tractogram(lines, data_per_point=per_point, data_per_streamline=per_line, affine_to_rasmm=np.eye(4))
    path = os.path.join(out, name + ".trk")
    nib.streamlines.TrkFile(t, header=header).save(path)
    dump(out, name, path)
    return path


def big_endian_trk(src, dst):
    """The same file in big-endian order: the header through its dtype, the
    body word by word (every value in it is 4 bytes)."""
    raw = open(src, "rb").read()
    head = np.frombuffer(raw[:1000], dtype=header_2_dtype)
    swapped = head.astype(header_2_dtype.newbyteorder(">"))
    body = np.frombuffer(raw[1000:], dtype="<u4").astype(">u4")
    with open(dst, "wb") as f:
        f.write(swapped.tobytes())
        f.write(body.tobytes())


def big_endian_tck(src, dst):
    raw = open(src, "rb").read()
    end = raw.index(b"\nEND\n") + 5
    head = raw[:end].decode()
    offset = int([l for l in head.splitlines() if l.startswith("file:")][0].split()[2])
    head = raw[:offset].replace(b"Float32LE", b"Float32BE")
    body = np.frombuffer(raw[offset:], dtype="<f4").astype(">f4")
    with open(dst, "wb") as f:
        f.write(head)
        f.write(body.tobytes())


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(32)
    lines = streamlines(rng, 7)

    # .tck: RAS+ mm as written.
    path = os.path.join(out, "plain.tck")
    nib.streamlines.save(Tractogram(lines, affine_to_rasmm=np.eye(4)), path)
    dump(out, "plain", path)
    big_endian_tck(path, os.path.join(out, "bigendian.tck"))
    dump(out, "bigendian", os.path.join(out, "bigendian.tck"))

    # .trk: the voxmm-to-RAS+ transform in its cases. An oblique affine whose
    # axes are LAS with voxel order LAS, one whose voxel order disagrees with
    # the affine (RAS affine, LPS order: two flips over the dimensions), a
    # permuted one (voxel order ASR), one with scalars and properties, and a
    # big-endian copy.
    a = np.eye(4)
    a[:3, :3] = rotation(rng) * 0.2 + np.diag([-2.0, 2.5, 3.0])
    a[:3, 3] = [90.0, -126.0, -72.0]
    write_trk(out, "oblique", lines, a, (40, 50, 30), (2.0, 2.5, 3.0), "LAS")
    b = np.diag([1.5, 1.5, 2.0, 1.0])
    b[:3, 3] = [-10.0, 20.0, 5.0]
    write_trk(out, "lps-order", lines, b, (64, 48, 20), (1.5, 1.5, 2.0), "LPS")
    c = np.zeros((4, 4))
    c[0, 2], c[1, 0], c[2, 1], c[3, 3] = 2.0, -1.0, 1.25, 1.0
    write_trk(out, "permuted", lines, c, (30, 20, 10), (1.0, 1.25, 2.0), "ASR")
    path = write_trk(out, "scalars", lines, a, (40, 50, 30), (2.0, 2.5, 3.0), "LAS", scalars=2, properties=3, rng=rng)
    big_endian_trk(path, os.path.join(out, "bigendian.trk"))
    dump(out, "bigendian-trk", os.path.join(out, "bigendian.trk"))
    os.rename(os.path.join(out, "bigendian.trk"), os.path.join(out, "bigendian-trk.trk"))

    if len(sys.argv) > 2:
        import vtk
        r = vtk.vtkPolyDataReader()
        r.SetFileName(sys.argv[2])
        r.Update()
        pd = r.GetOutput()
        pts, lengths = [], []
        cells = pd.GetLines()
        ids = vtk.vtkIdList()
        cells.InitTraversal()
        while cells.GetNextCell(ids):
            lengths.append(ids.GetNumberOfIds())
            for k in range(ids.GetNumberOfIds()):
                pts.append(pd.GetPoint(ids.GetId(k)))
        np.asarray(pts, dtype="<f4").tofile(os.path.join(out, "vtk.points"))
        np.asarray(lengths, dtype="<i8").tofile(os.path.join(out, "vtk.lengths"))
        fibres = np.split(np.asarray(pts, dtype=np.float32), np.cumsum(lengths)[:-1])
        path = os.path.join(out, "fibres.tck")
        nib.streamlines.save(Tractogram(fibres, affine_to_rasmm=np.eye(4)), path)
        dump(out, "fibres", path)
        write_trk(out, "fibres-trk", fibres, a, (40, 50, 30), (2.0, 2.5, 3.0), "LAS")
        # MRtrix's own writer (its VTK reader takes only binary files, so from the .tck).
        mr = os.path.join(out, "mrtrix.tck")
        subprocess.run(["tckconvert", "-quiet", "-force", path, mr], check=True)
        dump(out, "mrtrix", mr)


main()
