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
# The module's own keywords, beside the option table's.
_OWN = ("tensors", "positions", "affine", "layout", "frame", "progress", "channels", "underlay_affine", "mask_affine")
# Options that take a volume in memory (an array, a nibabel image) as well as
# a file: the keyword of each one's affine.
_VOLUME_AFFINE = {"underlay": "underlay_affine", "mask": "mask_affine"}


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


def _unexpected(kw):
    """The TypeError for an unknown keyword, with the CLI's "did you mean"."""
    near = _core.nearest(kw, list(_OPTIONS) + list(_OWN))
    return TypeError(f"unexpected keyword argument '{kw}'" + (f"; did you mean '{near}'?" if near else ""))


def _occurrences(kw, value):
    """A keyword's value as occurrences of its flag, each a list of strings."""
    if kw not in _OPTIONS:
        raise _unexpected(kw)
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


def _is_image(x):
    return hasattr(x, "affine") and hasattr(x, "dataobj")


def _is_volume(kw, value):
    """underlay= or mask= given in memory: an array or a nibabel image."""
    if kw not in _VOLUME_AFFINE or value is None or isinstance(value, (str, os.PathLike)):
        return False
    return _is_image(value) or np.ndim(value) >= 1


def _affine16(kw, affine):
    a = np.asarray(affine, dtype=np.float64)
    if a.shape != (4, 4):
        raise ValueError(f"{kw}: shape {a.shape} is not (4, 4)")
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{kw}: has NaN or Inf")
    return [float(x) for x in a.ravel()]


def _volume(kw, value, affine):
    """(values as float32 with i fastest, shape, 16 affine values or None) of
    underlay= or mask= given in memory. With no affine (an array alone) the
    core lays it on the tensors' grid, whose shape it must have."""
    akw = _VOLUME_AFFINE[kw]
    if _is_image(value):
        if affine is not None:
            raise ValueError(f"{akw}: the nibabel image given as {kw} has its own affine")
        affine, _ = _nifti_placement(value, None)
        value = np.asanyarray(value.dataobj)
    a = np.asarray(value)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{kw}: an array of numbers, not of {a.dtype}")
    while a.ndim > 3 and a.shape[-1] == 1:  # a NIfTI's (X, Y, Z, 1)
        a = a[..., 0]
    if a.ndim != 3:
        hint = (f"; an integer index drops an axis: keep it with a range ({kw}[:, :, 5:6])" if a.ndim == 2 else "")
        raise ValueError(f"{kw}: shape {a.shape} is not a volume (X, Y, Z){hint}")
    values = np.ascontiguousarray(a.ravel(order="F"), dtype=np.float32)
    return values, tuple(int(n) for n in a.shape), None if affine is None else _affine16(akw, affine)


def _volumes(opts):
    """{keyword: (values, shape, affine)} of the volumes given in memory, after
    checking that each _affine keyword comes with one."""
    out = {}
    for kw, akw in _VOLUME_AFFINE.items():
        value, affine = opts.get(kw), opts.get(akw)
        if _is_volume(kw, value):
            out[kw] = _volume(kw, value, affine)
        elif affine is not None:
            raise ValueError(f"{akw}: applies to {kw}= given as an array, not to " +
                             ("no " + kw if value is None else repr(value)))
    return out


def _option_list(opts):
    out = []
    for kw, value in opts.items():
        if kw in _VOLUME_AFFINE.values():
            continue
        if _is_color_values(kw, value):
            out.append((kw, ["array"]))
            continue
        if _is_volume(kw, value):
            out.append((kw, [f"<{kw} array>"]))
            continue
        out.extend((kw, occ) for occ in _occurrences(kw, value))
    return out


def _check_keyword(kw, value):
    """TypeError for an unknown keyword or a value of the wrong kind, before
    anything is made."""
    if kw in _VOLUME_AFFINE.values() or _is_color_values(kw, value) or _is_volume(kw, value):
        return
    _occurrences(kw, value)


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


def _refuse_dropped_axes(what, shape, dropped):
    """The ValueError for a volume that an integer index cut down: a slice
    keeps its axis as a range (5:6), or is chosen by slice=."""
    raise ValueError(f"tensors: {what} of shape {tuple(shape)} has {3 - dropped} of a volume's 3 axes: an integer "
                     "index drops its axis; keep it with a range, fit[:, :, 5:6] (not fit[:, :, 5]), or give "
                     "the whole volume and slice=\"z:5\"")


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
        if tensors.ndim < 5:
            _refuse_dropped_axes("a DIPY TensorFit", tensors.shape, 5 - tensors.ndim)
        if affine is None:
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
        if positions is None:
            # A volume indexed with an integer: (X, Y, 3, 3) or (X, Y, 6),
            # which no points are either.
            full = tensors.ndim >= 2 and tensors.shape[-2:] == (3, 3)
            rank = tensors.ndim - (2 if full else 1)
            if (full or (tensors.ndim >= 1 and tensors.shape[-1] == 6)) and rank in (0, 2):
                _refuse_dropped_axes("an array", tensors.shape, 3 - rank)
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
    empty), ``normal`` (world-space) and ``id`` (input index: on a grid
    i + X (j + Y k), i fastest; 0xFFFFFFFF where empty); ``glyphs`` is the number of glyphs uploaded; ``inputs``
    the (keyword, path) of each file it was drawn from, which ``save``
    refuses to write over; ``grid`` the input's voxel grid (X, Y, Z), None
    for points, on which ``voxel`` turns ids into voxels."""

    def __new__(cls, frame):
        fig = np.asarray(frame["rgba"]).view(cls)
        fig.channels = {k: frame[k] for k in ("color", "depth", "normal", "id") if k in frame}
        fig.glyphs = frame["glyphs"]
        fig.inputs = tuple(frame.get("inputs", ()))
        fig.grid = tuple(frame["grid"]) if frame.get("grid") is not None else None
        return fig

    def __array_finalize__(self, obj):
        self.channels = getattr(obj, "channels", {})
        self.glyphs = getattr(obj, "glyphs", 0)
        self.inputs = getattr(obj, "inputs", ())
        self.grid = getattr(obj, "grid", None)

    def voxel(self, ids):
        """The voxel (i, j, k) of each input index in `ids` (the id channel's
        values, or one of them) on the input's grid. Ids run i fastest,
        id = i + X (j + Y k), NumPy's order="F": np.unravel_index(id, grid,
        order="F"), not C order's default. An array of ids gives (..., 3),
        with -1 where an id names no voxel (background, a context item)."""
        if self.grid is None:
            raise ValueError("Figure.voxel: the input has no voxel grid (points have input indices only)")
        ids = np.asarray(ids, dtype=np.int64)
        X, Y, Z = self.grid
        ok = (ids >= 0) & (ids < X * Y * Z)
        safe = np.where(ok, ids, 0)
        ijk = np.stack([safe % X, safe // X % Y, safe // (X * Y)], axis=-1)
        return np.where(ok[..., None], ijk, -1)

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
            _check_keyword(kw, value)  # TypeError before anything is made
        self._options = {kw: value for kw, value in options.items() if value is not None}
        self._array_source = t is not None
        volumes = _volumes(self._options)
        # The core checks every option against this source (as set() does)
        # before it loads anything.
        with _process.call("Renderer"):
            self._core = _core.Renderer(t, p, a, lay, fr, path, _option_list(self._options), progress,
                                        _color_values(self._options), volumes)

    def set(self, **options):
        """Changes options (None: back to the default); returns self."""
        with self._lock:
            return self._set(options)

    def _set(self, options):
        # Checked on a copy: a refused value must not stay behind and fail
        # every later render.
        changed = dict(self._options)
        for kw, value in options.items():
            _check_keyword(kw, value)  # TypeError now, not at render time
            if self._array_source and kw in ("layout", "frame"):
                raise TypeError(f"{kw}: an array's {kw} is given when the Renderer is made")
            if value is None:
                changed.pop(kw, None)
            else:
                changed[kw] = value
        values = _color_values(changed)
        previous = _color_values(self._options)
        volumes = _volumes(changed)
        self._core.set_color_values(values)
        self._core.set_volumes(volumes)
        try:
            self._core.check(_option_list(changed))
        except Exception:
            self._core.set_color_values(previous)
            self._core.set_volumes(_volumes(self._options))
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
    path; None: the built-in scene) to a Figure. See the module's docstring.
    ``underlay`` and ``mask`` take a file, an (X, Y, Z) array (DIPY's fit.fa,
    a mask) or a nibabel image; an array lies on the tensors' grid, or where
    ``underlay_affine`` / ``mask_affine`` place it."""
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
