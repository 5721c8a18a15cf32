"""Exact, sign-aware tensor glyphs from NumPy, nibabel and DIPY.

Every keyword option is an option of ``tensorglyph render`` with the same
name (``--fa-min`` is ``fa_min``), the same values and the same default: both
read one option table (src/app/render_options.h). ``help(tensorglyph.render)``
lists them.

    import tensorglyph as tg
    fig = tg.render(fit, affine=img.affine, glyph="superquadric", fa_min=0.2)
    fig.save("brain.png")          # or show `fig` in Jupyter
    r = tg.Renderer(fit, affine=img.affine)
    r.set(gamma=1.5).render()      # no re-upload: r.uploads stays 1
"""
from __future__ import annotations

import atexit
import contextlib
import numbers
import os
import threading

import numpy as np

from . import _core

__all__ = ["render", "Renderer", "Figure", "save", "options"]

# keyword -> (flag, value names, help, reloads)
_OPTIONS = {kw: (flag, tuple(names), text, reloads) for kw, flag, names, text, reloads in _core.options()}


def options():
    """The render options: {keyword: (flag, value names, help, reloads)}."""
    return dict(_OPTIONS)


def _spell(kw, v):
    if isinstance(v, (bool, np.bool_)):
        raise TypeError(f"{kw}: expected a number or a name, not {v!r}")
    if isinstance(v, (str, os.PathLike)):
        return os.fspath(v)
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        return repr(float(v))
    raise TypeError(f"{kw}: cannot use a {type(v).__name__} as a value")


def _occurrences(kw, value):
    """A keyword's value as occurrences of its flag, each a list of strings."""
    if kw not in _OPTIONS:
        raise TypeError(f"unexpected keyword argument '{kw}'")
    flag, names, _, _ = _OPTIONS[kw]
    if value is None:
        return []
    if not names:  # a switch
        if not isinstance(value, (bool, np.bool_)):
            raise TypeError(f"{kw}: a switch takes True or False, not {value!r}")
        return [[]] if value else []
    scalar = isinstance(value, (str, os.PathLike, numbers.Number, np.generic))
    if scalar:
        return [[_spell(kw, value)]]
    items = list(np.asarray(value, dtype=object).tolist()) if isinstance(value, np.ndarray) else list(value)
    if len(names) == 1:  # repeated: plane=["z:10", "x:4"]
        return [[_spell(kw, v)] for v in items]
    if all(not isinstance(v, (list, tuple, np.ndarray)) for v in items):
        return [[_spell(kw, v) for v in items]]
    return [[_spell(kw, v) for v in occ] for occ in items]


def _is_color_values(kw, value):
    """color= given as an array of numbers: one value per tensor."""
    return kw == "color" and not isinstance(value, (str, os.PathLike)) and np.ndim(value) >= 1


def _color_values(opts):
    """color=array's values as float32 in the tensors' order (None: no array):
    a volume's (X, Y, Z) with x fastest, as its tensors are read."""
    value = opts.get("color")
    if value is None or not _is_color_values("color", value):
        return None
    a = np.asarray(value)
    if not np.issubdtype(a.dtype, np.number) or np.issubdtype(a.dtype, np.complexfloating):
        raise TypeError(f"color: an array of real numbers, not of {a.dtype}")
    return np.ascontiguousarray(a.ravel(order="F" if a.ndim == 3 else "C"), dtype=np.float32)


def _option_list(opts):
    out = []
    for kw, value in opts.items():
        if _is_color_values(kw, value):
            out.append((kw, ["array"]))
            continue
        out.extend((kw, occ) for occ in _occurrences(kw, value))
    return out


def _nifti_layout(img):
    hdr = img.header
    try:
        if hdr.get_intent()[0] == "symmetric matrix":
            return "nifti"
    except Exception:  # an intent nibabel does not know: not SYMMATRIX
        pass
    descrip = bytes(np.asarray(hdr.get("descrip", b""))).decode("latin-1", "replace")
    # "": the core's default, FSL's, refused where it is implausible as the
    # CLI refuses the same file (a layout named here would only warn).
    return "mrtrix" if descrip.startswith("MRtrix version") else ""


def _unplaced_nifti(img):
    """A nibabel NIfTI image with neither sform nor qform: the CLI reads it as
    a voxel grid, with no anatomical space."""
    if not (hasattr(img, "affine") and hasattr(img, "dataobj")):
        return False
    hdr = img.header
    keys = hdr.keys() if hasattr(hdr, "keys") else ()
    return "sform_code" in keys and int(hdr["sform_code"]) <= 0 and int(hdr["qform_code"]) <= 0


def _nifti_placement(img, frame):
    """The affine and frame the CLI's NIfTI reader uses. For a header with
    neither sform nor qform nibabel's img.affine is ANALYZE's (x reversed,
    centred); NIfTI's method 1, and the CLI, place by pixdim alone and leave
    the tensors unrotated, which the voxel frame of a diagonal affine does."""
    hdr = img.header
    if not _unplaced_nifti(img):
        return img.affine, frame
    zooms = [float(z) if z > 0 else 1.0 for z in hdr.get_zooms()[:3]]
    return np.diag(zooms + [1.0]), "voxel" if frame in (None, "", "fsl") else frame


def _values(name, a):
    """An array the core reads in place: float32 or float64 in this machine's
    byte order (a big-endian NIfTI's data is '>f4'; its bytes read as
    little-endian are other numbers). Integers and booleans become float64."""
    a = np.asarray(a)
    if a.dtype.kind in "iub":
        return a.astype(np.float64)
    if a.dtype.kind != "f":
        raise TypeError(f"{name}: dtype {a.dtype} is not a number type")
    return a if a.dtype.isnative else a.astype(a.dtype.newbyteorder("="))


def _source(tensors, positions, affine, layout, frame):
    """(tensors array or None, positions, affine 16 floats, layout, frame, path)."""
    path = ""
    if tensors is None:
        pass
    elif isinstance(tensors, (str, os.PathLike)):
        path, tensors = os.fspath(tensors), None
        if not path:
            raise ValueError("tensors: an empty path")
    elif hasattr(tensors, "quadratic_form"):  # a DIPY TensorFit: DIPY's axes are the voxel axes
        tensors = np.asarray(tensors.quadratic_form)
        frame = frame or "voxel"
        if affine is None and tensors.ndim == 5:
            raise ValueError("affine: a DIPY TensorFit needs the image's affine (img.affine)")
    elif hasattr(tensors, "affine") and hasattr(tensors, "dataobj"):  # a nibabel image
        img = tensors
        tensors = np.asanyarray(img.dataobj)
        if tensors.ndim == 5 and tensors.shape[3] == 1:
            tensors = tensors[:, :, :, 0, :]
        if affine is None:
            affine, frame = _nifti_placement(img, frame)
        layout = layout or _nifti_layout(img)
    if tensors is not None:
        tensors = _values("tensors", tensors)
        if positions is None and affine is None:
            raise ValueError("positions: tensors (N, 3, 3) or (N, 6) need positions (N, 3); "
                             "a volume (X, Y, Z, 6 | 3, 3) needs an affine")
    if positions is not None:
        positions = _values("positions", positions)
    if affine is not None:
        a = np.asarray(affine, dtype=np.float64)
        if a.shape != (4, 4):
            raise ValueError(f"affine: shape {a.shape} is not (4, 4)")
        if not np.all(np.isfinite(a)):
            raise ValueError("affine: has NaN or Inf")
        affine = [float(x) for x in a.ravel()]
    return tensors, positions, affine, layout or "", frame or "", path


class Figure(np.ndarray):
    """A rendered frame: the (H, W, 4) uint8 image itself, a NumPy array that
    Jupyter shows as a picture. With channels=True, ``channels`` holds
    ``color`` (linear float RGBA), ``depth`` (view-axis distance, inf where
    empty), ``normal`` (world-space) and ``id`` (input index, 0xFFFFFFFF
    where empty); ``glyphs`` is the number of glyphs uploaded; ``inputs``
    the (keyword, path) of each file it was drawn from, which ``save``
    refuses to write over."""

    def __new__(cls, frame):
        fig = np.asarray(frame["rgba"]).view(cls)
        fig.channels = {k: frame[k] for k in ("color", "depth", "normal", "id") if k in frame}
        fig.glyphs = frame["glyphs"]
        fig.inputs = tuple(frame.get("inputs", ()))
        return fig

    def __array_finalize__(self, obj):
        self.channels = getattr(obj, "channels", {})
        self.glyphs = getattr(obj, "glyphs", 0)
        self.inputs = getattr(obj, "inputs", ())

    @property
    def image(self):
        """The image as a plain ndarray."""
        return self.view(np.ndarray)

    def save(self, path):
        """Writes the image in any format the CLI writes (by extension),
        refusing what the CLI's -o refuses: a directory, a FIFO, socket or
        device, or one of the files it was drawn from (``inputs``)."""
        save(self, path)

    def _repr_png_(self):
        if self.ndim != 3 or self.shape[2] != 4 or self.dtype != np.uint8:
            return None  # a slice or a computed array: NumPy's own repr
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            p = os.path.join(d, "figure.png")
            save(self, p)
            with open(p, "rb") as f:
                return f.read()


def save(image, path):
    """Writes a Figure (or an (H, W, 4) uint8 array) to `path`; .exr needs a
    Figure rendered with channels=True. A Figure is not written over a file
    it was drawn from."""
    frame = {"rgba": np.ascontiguousarray(np.asarray(image).view(np.ndarray) if isinstance(image, Figure)
                                          else np.asarray(image))}
    inputs = list(image.inputs) if isinstance(image, Figure) else []
    if isinstance(image, Figure):
        frame.update(image.channels)
    with _process.call("save", gl=False):
        _core.save(frame, os.fspath(path), inputs)


class _Process:
    """This process's calls into the core, which run without the GIL.

    Exit: Python ends a daemon thread that takes the GIL back during
    finalization by unwinding its frames, and C++ aborts the process when
    that unwinding crosses its own ("terminate called without an active
    exception"). The exit waits for running calls to return; one begun later
    waits for ever (a daemon thread is not joined), except in a thread that
    is already inside one (a progress callback's render).

    Fork: GL drivers (Mesa's llvmpipe too) keep threads that a forked child
    does not have, so a child's GL call after the parent made a context
    waited for ever (a multiprocessing pool with the fork start method
    hung). It raises instead."""

    def __init__(self):
        self.cond = threading.Condition()
        self.running = {}  # thread ident -> calls it is inside
        self.exiting = False
        self.gl_made = False
        self.forked = False

    @contextlib.contextmanager
    def call(self, where, gl=True):
        if gl and self.forked:
            raise RuntimeError(f"{where}: this process was forked after tensorglyph rendered in it, and GL's "
                               "threads stay in the parent; render in the parent, or start workers with "
                               "multiprocessing's 'spawn' or 'forkserver' method")
        me = threading.get_ident()
        with self.cond:
            while self.exiting and me not in self.running:
                self.cond.wait()
            self.running[me] = self.running.get(me, 0) + 1
        self.gl_made = self.gl_made or gl
        try:
            yield
        finally:
            with self.cond:
                self.running[me] -= 1
                if not self.running[me]:
                    del self.running[me]
                self.cond.notify_all()

    def wait_at_exit(self):
        with self.cond:
            self.exiting = True
            while self.running:
                self.cond.wait()

    def after_fork_in_child(self):
        self.forked = self.forked or self.gl_made
        self.cond = threading.Condition()  # the parent's may have been held by another thread
        self.running = {}


_process = _Process()
atexit.register(_process.wait_at_exit)
os.register_at_fork(after_in_child=_process.after_fork_in_child)


def _guarded(progress, inside):
    """`progress`, noting in `inside` the threads running it (the core calls
    it from worker threads too): a render() from there would wait for the
    render that called it. It holds the set, not the Renderer, so that the
    core's reference to it makes no cycle."""
    def call(*args):
        me = threading.get_ident()
        inside.add(me)
        try:
            return progress(*args)
        finally:
            inside.discard(me)
    return call


class Renderer:
    """Keeps the GL context and the uploaded glyphs: ``set`` changes options,
    ``render`` draws. Changing gamma, fa_min, scale, colour, camera or depth
    cues draws again without uploading (``uploads`` counts uploads); options
    that change what is loaded (selection, size, meshes, planes) reload."""

    def __init__(self, tensors=None, *, positions=None, affine=None, layout=None, frame=None, progress=None,
                 **options):
        """`progress`: None, or f(stage, done, total, unit), called while a
        file loads ("loading"), the tensors are decomposed ("eigen") and each
        frame is drawn ("rendering", in "passes" as each finishes; total 0:
        not known)."""
        self._options = {}
        self._lock = threading.RLock()
        self._callback_threads = set()
        if callable(progress):
            progress = _guarded(progress, self._callback_threads)
        if _unplaced_nifti(tensors) and affine is None and options.get("orientation_letters") is None:
            # An affine given with arrays is taken as RAS (NIfTI's); this
            # one is the CLI's voxel grid, which has no letters by default.
            options["orientation_letters"] = "off"
        t, p, a, lay, fr, path = _source(tensors, positions, affine, layout, frame)
        if t is None:
            # A file's order and frame are its reader's options, --layout and
            # --frame; the built-in scene refuses them as the CLI does.
            options.update({k: v for k, v in (("layout", lay), ("frame", fr)) if v})
            lay = fr = ""
        for kw, value in options.items():
            if not _is_color_values(kw, value):
                _occurrences(kw, value)  # TypeError before anything is made
        self._options = {kw: value for kw, value in options.items() if value is not None}
        self._array_source = t is not None
        # The core checks every option against this source (as set() does)
        # before it loads anything.
        with _process.call("Renderer"):
            self._core = _core.Renderer(t, p, a, lay, fr, path, _option_list(self._options), progress,
                                        _color_values(self._options))

    def set(self, **options):
        """Changes options (None: back to the default); returns self."""
        with self._lock:
            return self._set(options)

    def _set(self, options):
        # Checked on a copy: a refused value must not stay behind and fail
        # every later render.
        changed = dict(self._options)
        for kw, value in options.items():
            if not _is_color_values(kw, value):
                _occurrences(kw, value)  # TypeError now, not at render time
            if self._array_source and kw in ("layout", "frame"):
                raise TypeError(f"{kw}: an array's {kw} is given when the Renderer is made")
            if value is None:
                changed.pop(kw, None)
            else:
                changed[kw] = value
        values = _color_values(changed)
        previous = _color_values(self._options)
        self._core.set_color_values(values)
        try:
            self._core.check(_option_list(changed))
        except Exception:
            self._core.set_color_values(previous)
            raise
        self._options = changed
        return self

    def render(self, channels=False, **options):
        """Draws with the current options (updated by `options` first)."""
        if threading.get_ident() in self._callback_threads:
            raise RuntimeError("Renderer.render: a re-entrant call from this Renderer's own progress callback "
                               "would wait forever for the render that called it; render after it returns")
        with self._lock:  # another thread's set() must not change this call's options
            if options:
                self.set(**options)
            with _process.call("Renderer.render"):
                return Figure(self._core.render(_option_list(self._options), bool(channels)))

    @property
    def options(self):
        return dict(self._options)

    @property
    def uploads(self):
        """How many times glyphs were uploaded to the GPU."""
        return self._core.uploads


def render(tensors=None, *, positions=None, affine=None, layout=None, frame=None, channels=False, progress=None,
           **options):
    """Renders tensors (an array, a nibabel image, a DIPY TensorFit or a file
    path; None: the built-in scene) to a Figure. See the module's docstring."""
    return Renderer(tensors, positions=positions, affine=affine, layout=layout, frame=frame, progress=progress,
                    **options).render(channels=channels)


def _document():
    lines = ["", "Options (as ``tensorglyph render``; value names after the keyword):"]
    for kw, (flag, names, text, _) in _OPTIONS.items():
        lines.append(f"    {kw}{'=' + ' '.join(names) if names else '=True'}: {text}")
    doc = "\n".join(lines)
    render.__doc__ += doc
    Renderer.__doc__ += doc


_document()
