"""Figure.save() and tg.save() go through the CLI's output checks (issue 30):
a FIFO, a device, a directory, a missing directory or one of the files the
figure was drawn from is refused, naming it, and left as it was."""
import os
import stat
import tempfile
import unittest

import numpy as np

import tensorglyph as tg


def _points(n=8):
    rng = np.random.default_rng(5)
    m = rng.normal(size=(n, 3, 3))
    return m + np.swapaxes(m, 1, 2) + 6 * np.eye(3), rng.uniform(0, 10, size=(n, 3))


class Save(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.dir = self._tmp.name
        t, p = _points()
        self.fig = tg.render(t, positions=p, size=(32, 24))

    def tearDown(self):
        self._tmp.cleanup()

    def refused(self, path, words, fig=None):
        with self.assertRaises(ValueError) as cm:
            (fig if fig is not None else self.fig).save(path)
        for w in words:
            self.assertIn(w, str(cm.exception))
        self.assertEqual([n for n in os.listdir(os.path.dirname(path) or ".") if n.endswith(".tmp.png")], [],
                         "a temporary file stayed behind")

    def test_a_fifo_stays_a_fifo(self):
        fifo = os.path.join(self.dir, "out.png")
        os.mkfifo(fifo)
        self.refused(fifo, ["path", fifo, "FIFO"])
        self.assertTrue(stat.S_ISFIFO(os.stat(fifo).st_mode), "the FIFO was replaced")
        # Through a link to it, and by tg.save on a plain array too.
        link = os.path.join(self.dir, "link.png")
        os.symlink(fifo, link)
        self.refused(link, ["FIFO"])
        with self.assertRaisesRegex(ValueError, "FIFO"):
            tg.save(np.zeros((4, 4, 4), np.uint8), fifo)
        self.assertTrue(stat.S_ISFIFO(os.stat(fifo).st_mode))

    def test_a_device_is_refused(self):
        """Refused before anything is written: as root the rename replaced the
        device node. As root the test's device is a null device made in its
        own directory (a regression replaces that one, not /dev/null); others
        cannot replace /dev/null, and try it."""
        dev = "/dev/null"
        if os.geteuid() == 0:
            dev = os.path.join(self.dir, "null.png")
            os.mknod(dev, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        before = os.stat(dev)
        with self.assertRaisesRegex(ValueError, f'"{dev}" is a device'):
            self.fig.save(dev)
        after = os.stat(dev)
        self.assertTrue(stat.S_ISCHR(after.st_mode), "the device node was replaced")
        self.assertEqual((before.st_ino, before.st_rdev), (after.st_ino, after.st_rdev))

    def test_a_directory_or_a_missing_one_is_refused(self):
        sub = os.path.join(self.dir, "d.png")
        os.mkdir(sub)
        self.refused(sub, ["path", "is a directory"])
        self.assertTrue(os.path.isdir(sub))
        with self.assertRaisesRegex(ValueError, "no directory"):
            self.fig.save(os.path.join(self.dir, "missing", "x.png"))

    def test_an_input_is_not_overwritten(self):
        """The tensors file, a mask, an underlay and a mesh, by name or by a
        hard link: each is named and keeps its bytes."""
        import nibabel as nib
        rng = np.random.default_rng(2)
        L = rng.normal(size=(3, 3, 2, 3, 3)) * 0.3 + np.eye(3)
        D = L @ np.swapaxes(L, -1, -2)
        fsl = np.stack([D[..., 0, 0], D[..., 0, 1], D[..., 0, 2], D[..., 1, 1], D[..., 1, 2], D[..., 2, 2]], -1)
        dt = os.path.join(self.dir, "dt.nii")
        mask = os.path.join(self.dir, "mask.nii")
        under = os.path.join(self.dir, "under.nii")
        nib.save(nib.Nifti1Image(fsl.astype(np.float32), np.eye(4)), dt)
        nib.save(nib.Nifti1Image(np.ones((3, 3, 2), np.float32), np.eye(4)), mask)
        nib.save(nib.Nifti1Image(rng.uniform(size=(3, 3, 2)).astype(np.float32), np.eye(4)), under)
        mesh = os.path.join(self.dir, "tri.obj")
        with open(mesh, "w") as f:
            f.write("v 0 0 0\nv 2 0 0\nv 0 2 1\nf 1 2 3\n")
        fig = tg.render(dt, size=(32, 24), mask=mask, underlay=under, mesh=mesh)
        self.assertEqual(dict(fig.inputs), {"tensors": dt, "mask": mask, "underlay": under, "mesh": mesh})
        link = os.path.join(self.dir, "hard.nii")
        os.link(dt, link)
        for path, name in [(dt, "tensors"), (mask, "mask"), (under, "underlay"), (mesh, "mesh"), (link, "tensors")]:
            with self.subTest(input=name, path=path):
                with open(path, "rb") as f:
                    before = f.read()
                # The writer chooses by extension: .nii is none of its formats, so
                # the check must come first for the message to name the input.
                with self.assertRaises(ValueError) as cm:
                    tg.save(fig, path)
                self.assertIn(f"the {name} file", str(cm.exception))
                with open(path, "rb") as f:
                    self.assertEqual(f.read(), before)
        # Arrays with a mask file: the mask is still an input.
        arr = tg.render(fsl.astype(np.float32), affine=np.eye(4), size=(32, 24), mask=mask)
        self.assertEqual(dict(arr.inputs), {"mask": mask})
        with self.assertRaisesRegex(ValueError, "the mask file"):
            arr.save(mask)
        # A png input-less figure saves; a second save over its own output is fine.
        out = os.path.join(self.dir, "ok.png")
        fig.save(out)
        fig.save(out)
        self.assertGreater(os.path.getsize(out), 0)


if __name__ == "__main__":
    unittest.main()
