"""The Python module and its process (run by ctest with Debian's python3):
a child forked after rendering, and the exit while daemon threads render."""
import os
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

import tensorglyph as tg

_TMP = tempfile.TemporaryDirectory()  # removed when the interpreter exits


def points(n=5):
    rng = np.random.default_rng(1)
    m = rng.normal(size=(n, 3, 3))
    return m + np.swapaxes(m, 1, 2) + 6 * np.eye(3), rng.uniform(0, 10, size=(n, 3))


class Process(unittest.TestCase):
    def test_a_child_forked_after_rendering_raises_instead_of_hanging(self):
        # GL's threads (Mesa's llvmpipe) stay in the parent: the child's
        # render waited for them for ever, as in a multiprocessing pool
        # forked after a render. Saving needs no GL and still works.
        t, p = points(8)
        image = tg.render(t, positions=p, size=(32, 24))
        pid = os.fork()
        if pid == 0:
            code = 1
            try:
                tg.render(t, positions=p, size=(32, 24))
            except RuntimeError as e:
                code = 0 if "forked" in str(e) else 2
            try:
                image.save(os.path.join(_TMP.name, f"forked{os.getpid()}.png"))
            except Exception:
                code = 3
            os._exit(code)
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                break
            time.sleep(0.1)
        else:
            os.kill(pid, 9)
            os.waitpid(pid, 0)
            self.fail("the forked child's render hung")
        self.assertEqual(os.waitstatus_to_exitcode(status), 0)
        self.assertTrue(np.array_equal(tg.render(t, positions=p, size=(32, 24)), image))  # the parent still renders

    def test_exit_while_a_daemon_thread_renders_is_clean(self):
        # Python ends a daemon thread that takes the GIL back at exit by
        # unwinding it, through the core's frames: C++ aborted the process
        # ("terminate called without an active exception", status 134).
        script = (
            "import threading, time, numpy as np, tensorglyph as tg\n"
            "t = np.tile([3e-3, 0, 0, 2e-3, 0, 1e-3], (4000, 1)); p = np.random.rand(4000, 3)\n"
            "r = tg.Renderer(t, positions=p, size=(256, 256))\n"
            "def draw():\n"
            "    k = 0\n"
            "    while True:\n"
            "        k += 1; r.render(gamma=1 + k % 2)\n"
            "def load():\n"
            "    while True: tg.Renderer(t, positions=p, size=(64, 64)).render()\n"
            "for f in (draw, load, load): threading.Thread(target=f, daemon=True).start()\n"
            "time.sleep(0.5)\n")
        for _ in range(3):
            done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertNotIn("terminate called", done.stderr)



if __name__ == "__main__":
    unittest.main()
