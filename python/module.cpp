// tensorglyph._core: the render core for Python. One class, Renderer, over
// app::RenderSession: the same options table as the CLI (app/render_options.h),
// the same readers, the same session, so the module and `render` cannot
// drift. Keyword handling (nibabel, DIPY, value spelling) is in __init__.py.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/scale/cli_values.h"
#include "app/field_flags.h"
#include "app/frame_check.h"
#include "app/scale/option_table.h"
#include "app/output_check.h"
#include "app/render_options.h"
#include "app/render_session.h"
#include "app/scene.h"
#include "gl/context.h"
#include "io/core/array_field.h"
#include "io/core/image_writer.h"
#include "io/core/selection.h"
#include "io/field/tensor_field.h"
#include "util/progress.h"
#include "python/array_inputs.h"
#include "python/frame_arrays.h"

namespace py = pybind11;
using namespace tg;
using namespace tg::python;

namespace {

// (keyword, [values]) per occurrence, in the order given.
using OptionList = std::vector<std::pair<std::string, std::vector<std::string>>>;

// The keywords of the option table, as Python takes them.
std::vector<std::string> keywords(const app::OptionTable& table) {
  std::vector<std::string> out;
  for (const auto& opt : table.options())
    if (!opt.positional && !opt.cliOnly && !opt.isHidden) out.push_back(opt.keyword());
  return out;
}

// Usage errors become ValueError, unknown keywords TypeError, as Python's own
// calls report them; bad data (io::InputError) is ValueError too.
void applyOptions(const app::OptionTable& table, const OptionList& given, const char* fn) {
  for (const auto& [kw, values] : given) {
    const app::OptionTable::Option* opt = table.find(kw);
    if (!opt || opt->positional || opt->cliOnly || opt->isHidden || opt->keyword() != kw) {
      const std::string near = app::nearestName(kw, keywords(table));
      throw py::type_error(std::string(fn) + "() got an unexpected keyword argument '" + kw + "'" +
                           (near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
    app::OptionTable::apply(*opt, values);
  }
}

// The files a frame was drawn from, named by keyword ("tensors" for the
// input): what save() must not write over.
InputList inputsOf(const app::OptionTable& table, const std::vector<app::NamedPath>& paths) {
  InputList out;
  for (const app::NamedPath& p : paths) {
    if (p.path.empty()) continue;
    const app::OptionTable::Option* opt = p.flag == "INPUT" ? nullptr : table.find(p.flag);
    out.emplace_back(opt ? opt->keyword() : std::string("tensors"), p.path);
  }
  return out;
}

class ProgressCallback;

// What the glyphs come from: arrays, a file, or the built-in scene.
struct Source {
  std::optional<py::array> tensors, positions;  // kept alive for the views
  std::optional<io::ArrayRef> tensorsRef, positionsRef;
  std::optional<std::vector<double>> affine;  // 16, row-major
  std::string layout, frame, path;
  std::shared_ptr<ProgressCallback> progress;
};

// The caller's progress callback as the core's sink: called with the GIL
// held (the work runs without it); None gives an empty sink, which costs
// nothing. An exception from the callback must not unwind through the
// eigen-decomposition's worker threads: it is kept, later reports are
// dropped, and rethrow() raises it once the work is done.
class ProgressCallback {
 public:
  explicit ProgressCallback(py::object f) : f_(std::move(f)) {}
  util::ProgressSink sink() {
    if (f_.is_none()) return {};
    return [this](std::string_view stage, double done, double total, std::string_view unit) {
      if (error_) return;
      py::gil_scoped_acquire gil;
      try {
        f_(std::string(stage), done, total, std::string(unit));
      } catch (...) {
        error_ = std::current_exception();
      }
    };
  }
  void rethrow() {
    if (std::exception_ptr e = std::exchange(error_, nullptr)) std::rethrow_exception(e);
  }

 private:
  py::object f_;
  std::exception_ptr error_;
};

// Every option checked as the CLI checks it before loading, against this
// source: a file's (or the built-in scene's) through app::checkOptionsApply,
// with the path as the CLI's INPUT (--mesh-from-input reads its mesh);
// arrays' through io::inapplicableArrayOption, and points' selection by the
// Selector a VTK file's points get (stride and ROI apply; a slice or mask,
// which need a grid, is refused). No option is taken and left unused.
void validateFor(const Source& s, app::RenderOptions& o) {
  if (s.tensorsRef) {
    if (const std::string flag = io::inapplicableArrayOption(o.field.read); !flag.empty())
      throw app::UsageError(flag + " does not apply to tensors given as arrays");
    if (o.mesh.fromInput)
      throw app::UsageError("--mesh-from-input does not apply to tensors given as arrays: they come with no FEM mesh");
    if (s.positionsRef) {
      [[maybe_unused]] const io::Selector points(o.field.read.selection, "<array>", nullptr);
    }
  } else {
    app::checkOptionsApply(s.path, o.field.read);
  }
  o.input = s.path;
  app::validateRenderOptions(o, false);
}

app::Scene loadSource(const Source& s, const app::RenderOptions& o) {
  if (!s.tensorsRef) {
    io::ReadOptions read = o.field.read;
    read.progress = s.progress->sink();
    app::Scene scene = app::loadScene(s.path, read);
    app::attachWholeField(scene, o.field, s.path, read);
    return scene;
  }
  const io::ArrayRef& t = *s.tensorsRef;
  if (!s.positionsRef && !s.affine) throw std::invalid_argument("affine: a volume needs its 4x4 voxel-to-world affine");
  // --tensor-axes as a file's reader applies it, so the frame check's advice holds for arrays too.
  const auto field = [&](const io::Selection& sel) {
    io::TensorField f = s.positionsRef ? io::fieldFromPoints(t, s.layout, *s.positionsRef, sel)
                                       : io::fieldFromVolume(t, s.layout, s.affine->data(), s.frame, sel);
    io::applyTensorAxes(f, o.field.read.tensorAxes);
    return f;
  };
  app::Scene scene;
  scene.field = field(o.field.read.selection);
  app::checkLoaded(scene.field, o.field.read);
  app::attachWholeField(scene, o.field, [&] { return field(io::Selection{}); });
  return scene;
}

// The session's context, current for one call and released after it: the
// next call on this Renderer may come from another Python thread, and a
// context is current on one thread at a time (EGL refuses it elsewhere until
// released).
class CurrentFor {
 public:
  explicit CurrentFor(gl::Context& c) : c_(c) { c_.makeCurrent(); }
  ~CurrentFor() { c_.releaseCurrent(); }
  CurrentFor(const CurrentFor&) = delete;
  CurrentFor& operator=(const CurrentFor&) = delete;

 private:
  gl::Context& c_;
};

class Renderer {
 public:
  Renderer(Source source, OptionList options,
           std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>> colorValues,
           const py::dict& volumes)
      : source_(std::move(source)) {
    setColorValues(std::move(colorValues));
    setVolumes(volumes);
    rebuild(options);
  }

  // Re-renders with `options` (all of them, not a difference): loads and
  // uploads again only when an option that reloads (OptionTable::reloads)
  // changed; γ, FA threshold, scale, colour, camera and depth cues do not.
  py::dict render(const OptionList& options, bool channels) {
    // Waited for without the GIL: the thread holding the lock needs the GIL
    // to finish (the result, the progress callback), so waiting with it
    // deadlocked two threads sharing one Renderer.
    std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
    {
      py::gil_scoped_release release;
      lock.lock();
    }
    app::RenderOptions o;
    app::OptionTable table;
    app::addRenderOptions(table, o);
    applyOptions(table, options, "render");
    useVolumes(o);
    validateFor(source_, o);
    // A kind the session's glyph path cannot draw (blobs on the raster path) takes a new session.
    const bool pathDraws = !session_ || !o.look.glyphGiven ||
                           render::pathDraws(session_->renderer().glyphPath().name(), *render::glyphKindNamed(o.glyph));
    if (!session_ || volumesChanged_ || reloadKeys(table, options) != reloadKeys_ || !pathDraws) {
      {
        py::gil_scoped_release release;
        build(o, options, table);
      }
      warnLoaded();
    }
    // color=array: into the renderer's own buffer when new; the records stay.
    if (colorValues_ && colorValuesSent_ != session_.get()) {
      const CurrentFor current(session_->context());
      session_->setColorValues(*colorValues_, "color");
      colorValuesSent_ = session_.get();
    }
    render::FrameImage img;
    render::GlyphKind kind = render::GlyphKind::Superquadric;
    {
      py::gil_scoped_release release;
      const CurrentFor current(session_->context());
      const app::RenderSession::Frame f = session_->frame(o);
      kind = f.params.glyph;
      // The render stage, as the CLI's: the frame's passes as they finish.
      const util::ProgressSink sink = source_.progress->sink();
      if (sink) sink("rendering", 0, 0, util::kPassesUnit);
      session_->draw(f, sink ? render::PassProgress([&sink](std::string_view, int done, int total) {
        sink("rendering", done, total, util::kPassesUnit);
      }) : render::PassProgress{});
      img = session_->readback(f, channels ? render::Channels::All : render::Channels::Rgba8);
    }
    source_.progress->rethrow();
    // `render` refuses a march option for glyphs that do not march; a
    // Renderer keeps it for a later glyph="superquadric", and says so.
    const bool gamma = o.marchFlag == "--gamma";
    if (!o.marchFlag.empty() && kind != render::GlyphKind::Superquadric && !(gamma && kind == render::GlyphKind::Blob)) {
      const std::string kw = table.find(o.marchFlag)->keyword();
      const std::string w = kw + " applies to glyph=\"superquadric\"" + (gamma ? " and \"blob\"" : "") +
                            " only; this frame draws " + o.glyph + " glyphs";
      if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();
    }
    if (kind == render::GlyphKind::Blob)
      if (const std::string hint = app::blobThresholdHint(o.blob, "blob_threshold", "blobbiness"); !hint.empty())
        if (PyErr_WarnEx(PyExc_UserWarning, hint.c_str(), 1) < 0) throw py::error_already_set();
    if (!o.blobFlag.empty() && kind != render::GlyphKind::Blob) {
      const std::string w = table.find(o.blobFlag)->keyword() + " applies to glyph=\"blob\" only; this frame draws " +
                            o.glyph + " glyphs";
      if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();
    }
    py::dict out;
    py::array_t<std::uint8_t> rgba({img.height, img.width, 4});
    const std::vector<unsigned char> px = io::toRgba8(img);
    std::memcpy(rgba.mutable_data(), px.data(), px.size());
    out["rgba"] = rgba;
    if (channels) {
      out["color"] = floatImage(img.rgba, img.height, img.width, 4);
      out["depth"] = floatImage(img.depth, img.height, img.width, 1);
      out["normal"] = floatImage(img.normalWC, img.height, img.width, 3);
      py::array_t<std::uint32_t> id({img.height, img.width});
      std::memcpy(id.mutable_data(), img.id.data(), img.id.size() * sizeof(std::uint32_t));
      out["id"] = id;
    }
    out["glyphs"] = session_->glyphCount();
    std::vector<app::NamedPath> files = app::sceneInputs(source_.path, o);
    std::erase_if(files, [&](const app::NamedPath& p) {
      return (p.flag == "--underlay" && underlay_) || (p.flag == "--mask" && mask_);
    });
    out["inputs"] = inputsOf(table, files);
    // The voxel grid of a gridded input: the id channel's ids are voxel
    // indices i + X (j + Y k) on it.
    if (const auto& g = session_->scene().field.grid) out["grid"] = py::make_tuple(g->dims[0], g->dims[1], g->dims[2]);
    return out;
  }

  // set()'s check: what render() would refuse of `options`, before any load.
  void check(const OptionList& options) const {
    app::RenderOptions o;
    app::OptionTable table;
    app::addRenderOptions(table, o);
    applyOptions(table, options, "set");
    useVolumes(o);
    validateFor(source_, o);
  }

  // underlay= and mask= given in memory: {keyword: (values, shape, affine)};
  // a keyword missing or None has none. A change loads again.
  void setVolumes(const py::dict& volumes) {
    const auto get = [&](const char* kw) {
      return volumes.contains(kw) ? scalarVolume(volumes[kw], kw) : nullptr;
    };
    auto underlay = get("underlay"), mask = get("mask");
    if (!sameVolume(underlay, underlay_) || !sameVolume(mask, mask_)) volumesChanged_ = true;
    underlay_ = std::move(underlay);
    mask_ = std::move(mask);
  }

  // color=array's values, one per input tensor (none: no array); the count
  // is checked here against the loaded field, before any frame.
  // The Python Renderer's lock orders it with render().
  void setColorValues(std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>> values) {
    if (!values) {
      colorValues_.reset();
      colorValuesSent_ = nullptr;
      return;
    }
    std::vector<float> v(values->data(), values->data() + values->size());
    if (session_ && session_->scene().field.totalPoints != v.size())
      throw std::invalid_argument("color: " + std::to_string(v.size()) + " values for " +
                                  std::to_string(session_->scene().field.totalPoints) +
                                  " tensors; give one value per tensor");
    if (colorValues_ != v) colorValuesSent_ = nullptr;
    colorValues_ = std::move(v);
  }

  std::uint64_t uploads() const { return previousUploads_ + (session_ ? session_->renderer().uploadCount() : 0); }
  std::size_t glyphCount() const { return session_ ? session_->glyphCount() : 0; }

 private:
  // What this Renderer holds for the options: colour values, volumes.
  void useVolumes(app::RenderOptions& o) const {
    o.colorValuesGiven = colorValues_.has_value();
    if (underlay_) o.slices.underlayVolume = underlay_;
    if (mask_) o.field.read.selection.maskVolume = mask_;
  }

  // The values of every reloading option given, in order: equal lists mean
  // the loaded scene and the upload still hold.
  static OptionList reloadKeys(const app::OptionTable& table, const OptionList& options) {
    OptionList keys;
    for (const auto& kv : options)
      if (const auto* opt = table.find(kv.first); opt && opt->reload) keys.push_back(kv);
    return keys;
  }

  void rebuild(const OptionList& options) {
    app::RenderOptions o;
    app::OptionTable table;
    app::addRenderOptions(table, o);
    applyOptions(table, options, "Renderer");
    useVolumes(o);
    validateFor(source_, o);
    {
      py::gil_scoped_release release;
      build(o, options, table);
    }
    warnLoaded();
  }

  // What the CLI prints of a load (app::reportLoad) as Python warnings, which
  // a notebook shows and a script can filter or turn into errors; the C
  // stderr that reportLoad writes is not shown in Jupyter.
  void warnLoaded() {
    for (const std::string& w : std::exchange(loadWarnings_, {}))
      if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();
  }

  void build(const app::RenderOptions& o, const OptionList& options, const app::OptionTable& table) {
    loadWarnings_.clear();
    app::Scene scene = loadSource(source_, o);
    const io::TensorField& loaded = scene.field;
    for (const std::string& w : loaded.warnings) loadWarnings_.push_back(loaded.path + ": " + w);
    if (loaded.skippedNonFinite)
      loadWarnings_.push_back(loaded.path + ": skipped " + std::to_string(loaded.skippedNonFinite) +
                              " tensors with NaN/Inf components");
    if (loaded.skippedOverflow)
      loadWarnings_.push_back(loaded.path + ": skipped " + std::to_string(loaded.skippedOverflow) +
                              " tensors whose values overflow single precision (beyond 3.4e38)");
    if (const std::string w = app::frameWarning(app::checkFrame(loaded, o.field.read)); !w.empty())
      loadWarnings_.push_back(loaded.path + ": " + w);
    std::vector<io::MeshData> meshes = o.mesh.read(source_.path, "python");
    if (session_) previousUploads_ += session_->renderer().uploadCount();
    // Freed before the next is made (peak memory): if making it throws, the
    // next render builds again instead of drawing with no session.
    session_.reset();
    session_ = std::make_unique<app::RenderSession>(o, std::move(scene), std::move(meshes), true, "python",
                                                    [](io::TensorField& f) { f.releaseSamples(); },
                                                    source_.progress->sink());
    session_->context().releaseCurrent();  // made current on this thread; the next call may come from another
    colorValuesSent_ = nullptr;  // a new session has no colour values yet
    reloadKeys_ = reloadKeys(table, options);
    volumesChanged_ = false;
    source_.progress->rethrow();
  }

  Source source_;
  std::unique_ptr<app::RenderSession> session_;
  OptionList reloadKeys_;
  std::vector<std::string> loadWarnings_;  // made without the GIL, raised with it
  std::uint64_t previousUploads_ = 0;
  std::optional<std::vector<float>> colorValues_;
  const app::RenderSession* colorValuesSent_ = nullptr;  // the session holding colorValues_
  std::shared_ptr<const io::ScalarVolume> underlay_, mask_;
  bool volumesChanged_ = false;
  std::mutex mutex_;
};

Source makeSource(std::optional<py::array> tensors, std::optional<py::array> positions,
                  std::optional<std::vector<double>> affine, std::string layout, std::string frame, std::string path,
                  py::object progress) {
  Source s;
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: must be callable as f(stage, done, total, unit)");
  s.progress = std::make_shared<ProgressCallback>(std::move(progress));
  if (tensors && !path.empty()) throw std::invalid_argument("tensors: give tensors or a path, not both");
  if (positions && !tensors) throw std::invalid_argument("positions: given without tensors");
  // A file places its own voxels, and the built-in scene has its own place.
  if (affine && !tensors)
    throw std::invalid_argument("affine: applies to tensors given as arrays, not to " +
                                (path.empty() ? std::string("the built-in scene") : "the file " + path));
  if (affine && affine->size() != 16) throw std::invalid_argument("affine: must be 4x4");
  if (positions && affine) throw std::invalid_argument("affine: applies to a volume, not to points with positions");
  if (positions && !frame.empty())
    throw std::invalid_argument("frame: applies to a volume; the tensors of points with positions are in world axes");
  s.tensors = std::move(tensors);
  s.positions = std::move(positions);
  if (s.tensors) s.tensorsRef = arrayRef(*s.tensors, "tensors");
  if (s.positions) s.positionsRef = arrayRef(*s.positions, "positions");
  s.affine = std::move(affine);
  s.layout = std::move(layout);
  s.frame = std::move(frame);
  s.path = std::move(path);
  return s;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "tensorglyph's render core (see the tensorglyph package)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const app::UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const io::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::domain_error& e) {
      PyErr_SetString(PyExc_TypeError, e.what());
    } catch (const app::HelpShown&) {
      PyErr_SetString(PyExc_ValueError, "help is not an option here; see help(tensorglyph.render)");
    }
  });
  py::class_<Renderer>(m, "Renderer")
      .def(py::init([](std::optional<py::array> tensors, std::optional<py::array> positions,
                       std::optional<std::vector<double>> affine, std::string layout, std::string frame,
                       std::string path, OptionList options, py::object progress,
                       std::optional<py::array_t<float, py::array::c_style | py::array::forcecast>> colorValues,
                       const py::dict& volumes) {
             return std::make_unique<Renderer>(makeSource(std::move(tensors), std::move(positions), std::move(affine),
                                                          std::move(layout), std::move(frame), std::move(path),
                                                          std::move(progress)),
                                               std::move(options), std::move(colorValues), volumes);
           }),
           py::arg("tensors"), py::arg("positions"), py::arg("affine"), py::arg("layout"), py::arg("frame"),
           py::arg("path"), py::arg("options"), py::arg("progress"), py::arg("color_values") = py::none(),
           py::arg("volumes") = py::dict())
      .def("render", &Renderer::render, py::arg("options"), py::arg("channels"))
      .def("check", &Renderer::check, py::arg("options"))
      .def("set_color_values", &Renderer::setColorValues, py::arg("values"))
      .def("set_volumes", &Renderer::setVolumes, py::arg("volumes"))
      .def_property_readonly("uploads", &Renderer::uploads)
      .def_property_readonly("glyph_count", &Renderer::glyphCount);
  // The option table, for keyword checks, docstrings and the type stubs:
  // (keyword, flag, value names, help with the option's range, reloads).
  m.def("options", [] {
    app::RenderOptions o;
    app::OptionTable table;
    app::addRenderOptions(table, o);
    py::list out;
    for (const auto& opt : table.options())
      if (!opt.positional && !opt.cliOnly && !opt.isHidden)
        out.append(py::make_tuple(opt.keyword(), opt.flag, opt.metavars, opt.description(), opt.reload));
    return out;
  });
  // {keyword: names} of the options that take a name from a fixed list.
  m.def("choices", [] {
    app::RenderOptions o;
    app::OptionTable table;
    app::addRenderOptions(table, o);
    py::dict out;
    for (const auto& opt : table.options())
      if (!opt.positional && !opt.cliOnly && !opt.isHidden && !opt.choices.empty()) out[py::str(opt.keyword())] = opt.choices;
    return out;
  });
  m.def("save", &saveFrame, py::arg("frame"), py::arg("path"), py::arg("inputs"));
  // The CLI's "did you mean": the name of `names` nearest `word`, or "".
  m.def("nearest", [](const std::string& word, const std::vector<std::string>& names) {
    return app::nearestName(word, names);
  }, py::arg("word"), py::arg("names"));
}
