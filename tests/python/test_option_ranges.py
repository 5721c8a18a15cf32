"""Python's keywords refuse what the command line refuses, in the same words:
the ranges are declared once (src/app/scale/option_ranges.h), and the CLI, the
view script and the module read them (issue 29, item 4)."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

import tensorglyph as tg

CLI = os.environ.get("TG_CLI", "")


def points(n=5):
    rng = np.random.default_rng(1)
    m = rng.normal(size=(n, 3, 3))
    return m + np.swapaxes(m, 1, 2) + 6 * np.eye(3), rng.uniform(0, 10, size=(n, 3))


class SameRangesAsTheCli(unittest.TestCase):
    # keyword, flag, a value outside, the range's words, what else it needs
    CASES = [
        ("gamma", "--gamma", -1, "0..10000", {"glyph": "superquadric"}),
        ("gamma", "--gamma", 1e300, "0..10000", {"glyph": "superquadric"}),
        ("fa_min", "--fa-min", 2, "0..1", {}),
        ("iterations", "--iterations", 5000, "1..1000", {"glyph": "superquadric"}),
        ("epsilon", "--epsilon", 1, "1e-09..0.5", {"glyph": "superquadric"}),
        ("clamp", "--clamp", 1e-40, "0 (off) or 0.01..1e+06", {}),
        ("lambda0", "--lambda0", 1e-39, "1.2e-38..3.4e+38", {"magnitude": "shape"}),
        ("fov", "--fov", 1e-10, "0.01..179", {}),
        ("min_eigenvalue", "--min-eigenvalue", 1e300, "-1e+37..1e+37", {}),
    ]

    def test_each_keyword_refuses_as_its_flag_does(self):
        t, p = points()
        out = os.path.join(tempfile.mkdtemp(), "x.png")
        for kw, flag, bad, words, needs in self.CASES:
            with self.subTest(kw=kw, value=bad):
                with self.assertRaises(ValueError) as cm:
                    tg.render(t, positions=p, **{kw: bad}, **needs)
                self.assertIn(flag + " must be within " + words, str(cm.exception))
                if CLI:
                    args = [CLI, "render", "-o", out, flag, repr(float(bad))]
                    for k, v in needs.items():
                        args += ["--" + k.replace("_", "-"), v]
                    r = subprocess.run(args, capture_output=True, text=True)
                    self.assertEqual(r.returncode, 2, r.stderr)
                    self.assertIn(flag + " must be within " + words, r.stderr)

    def test_the_documented_keywords_show_their_ranges(self):
        docs = tg.options()
        self.assertIn("[0..10000; default 3]", docs["gamma"][2])
        self.assertIn("[0..1]", docs["fa_min"][2])


if __name__ == "__main__":
    unittest.main()
