#include "app/view_script.h"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "app/cli_common.h"
#include "app/legend_flags.h"
#include "app/effect_flags.h"
#include "app/scale/frame_size.h"
#include "app/mesh_flags.h"
#include "app/names.h"
#include "app/scale/option_ranges.h"
#include "app/script_commands.h"
#include "io/core/image_writer.h"
#include "io/field/tensor_field.h"
#include "view/anatomy.h"

namespace tg::app {
namespace {

double number(const ScriptStep& s, std::size_t k) { return parseDouble(s.verb, s.args[k]); }

// A value against the range its option declares (app/scale/option_ranges.h), in
// the words render's flags use, naming the script's command.
double ranged(const ScriptStep& s, std::size_t k, const NumberRange& r, const std::string& name = {}) {
  return checkedNumber(name.empty() ? s.verb : name, s.args[k], r);
}

// `plane N on|off`, `plane N SLICE` or `plane N index I`: N counts from 1;
// the plane's own range is checked once the underlay is known (checkPlaneSteps).
std::size_t planeNumber(const ScriptStep& s) {
  return std::size_t(parseInt("plane", s.args[0], 1, static_cast<long long>(render::kMaxContextItems)));
}
long long planeIndex(const ScriptStep& s) { return parseInt("plane index", s.args[2], 0, 1LL << 31); }
bool planeToggles(const ScriptStep& s) { return s.args.size() == 2 && (s.args[1] == "on" || s.args[1] == "off"); }
// A slice as --slice takes it, through its own parser: the script has no grammar of its own for one.
io::SliceSpec sliceArg(const std::string& verb, const std::string& text) {
  try {
    return io::parseSlice(text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(verb + ": " + e.what() + " (a slice as --slice takes it: i|j|k:INDEX[:THICKNESS], "
                     "axial|coronal|sagittal:INDEX[:THICKNESS] or x|y|z=POSITION[mm][:THICKNESS])");
  }
}
void checkPlaneSyntax(const ScriptStep& s) {
  planeNumber(s);
  if (s.args.size() == 2 && !planeToggles(s)) {
    if (s.args[1].find_first_of(":=") == std::string::npos)
      throw UsageError("plane: give N on|off, N SLICE or N index I");
    if (sliceArg("plane", s.args[1]).thickness != 1)
      throw UsageError("plane: " + s.args[1] + ": a plane is one slice; give no :THICKNESS");
  }
  if (s.args.size() == 3) {
    if (s.args[1] != "index") throw UsageError("plane: give N on|off, N SLICE or N index I");
    planeIndex(s);
  }
}

// `shadow TERM V`, range-checked as render's --shadow-* flags are.
double shadowValue(const ScriptStep& s) {
  const std::string& t = s.args[0];
  if (t == "penumbra") return ranged(s, 1, ranges::kShadowPenumbra, "shadow penumbra");
  if (t == "strength") return ranged(s, 1, ranges::kUnit, "shadow strength");
  if (t == "bias") return ranged(s, 1, ranges::kShadowBias, "shadow bias");
  if (t == "map-size") return ranged(s, 1, ranges::kShadowMapSize, "shadow map-size");
  throw UsageError("shadow: unknown parameter \"" + t + "\"; choose penumbra, strength, bias or map-size");
}

// Every value check, so that applyStep cannot fail.
void check(const ScriptStep& s) {
  const ScriptCommand* c = scriptCommand(s.verb);
  if (!c) throw UsageError("unknown command \"" + s.verb + "\"");
  const std::size_t n = s.args.size();
  // The world range `slab x LO HI` of old reads x as world x where --slice's x is voxel i.
  if (s.verb == "slab" && n == 3)
    throw UsageError("slab: give a slice as --slice takes it, or off (slab x LO HI is gone: x there was the world "
                     "axis, in --slice the voxel axis i; for a world position give z=POSITION[:THICKNESS])");
  if (n < std::size_t(c->minArgs) || n > std::size_t(c->maxArgs))
    throw UsageError(s.verb + ": wrong number of arguments");
  const std::string& v = s.verb;
  if (v == "orbit" || v == "pan") ranged(s, 0, ranges::kAnyFloat), ranged(s, 1, ranges::kAnyFloat);
  if (v == "zoom" || v == "scale") ranged(s, 0, ranges::kPositiveFloat);
  if (v == "gamma") ranged(s, 0, ranges::kGamma);
  if (v == "blob-threshold") ranged(s, 0, ranges::kBlobThreshold);
  if (v == "blobbiness") ranged(s, 0, ranges::kBlobbiness);
  if (v == "fa-min") ranged(s, 0, ranges::kUnit);
  if (v == "glyph" && !glyphKindNamed(s.args[0]))
    throw UsageError("glyph: unknown kind \"" + s.args[0] + "\"; choose " + kGlyphKindNames);
  if (v == "color" && !colorModeNamed(s.args[0]))
    throw UsageError("color: unknown mode \"" + s.args[0] + "\"; choose " + kColorModeNames);
  if (v == "colormap" && s.args[0] != "auto" && !render::colormapNamed(s.args[0]))
    throw UsageError("colormap: unknown map \"" + s.args[0] + "\"; choose auto, " + render::kColormapNames);
  if (v == "color-range") {
    if (n == 1 && s.args[0] != "auto") throw UsageError("color-range: give LO HI, or auto");
    if (n == 2) ranged(s, 0, ranges::kAnyFloat, "color-range"), ranged(s, 1, ranges::kAnyFloat, "color-range");
    if (n == 2 && !(number(s, 0) < number(s, 1))) throw UsageError("color-range: LO must be below HI");
  }
  if (v == "slab" && s.args[0] != "off") sliceArg("slab", s.args[0]);
  if (v == "light") {
    const std::string& w = s.args[0];
    if (w != "ambient" && w != "head" && w != "key" && w != "specular" && w != "shininess")
      throw UsageError("light: unknown term \"" + w + "\"; choose ambient, head, key, specular or shininess");
    ranged(s, 1, w == "shininess" ? ranges::kShininess : ranges::kLight, "light " + w);
  }
  if (v == "iterations") ranged(s, 0, ranges::kIterations);
  if (v == "epsilon") ranged(s, 0, ranges::kEpsilon);
  if (v == "stats" && s.args[0] != "on" && s.args[0] != "off") throw UsageError("stats: on or off");
  if (v == "frames") ranged(s, 0, ranges::kScriptFrames);
  if (v == "pick") ranged(s, 0, ranges::kPixelIndex), ranged(s, 1, ranges::kPixelIndex);
  // As render's -o: a format that cannot be written is known before the window opens.
  if (v == "screenshot" && !io::canWriteImage(s.args[0]))
    throw UsageError("screenshot: no image format for \"" + s.args[0] + "\"");
  if (v == "magnitude") {
    if (!tensor::magnitudeNamed(s.args[0]))
      throw UsageError("magnitude: unknown mapping \"" + s.args[0] + "\"; choose " + tensor::kMagnitudeNames);
    if (n == 2 && s.args[0] == "linear") throw UsageError("magnitude: LAMBDA0 applies to log or shape only");
    if (n == 2) ranged(s, 1, ranges::kPositiveFloat, "magnitude LAMBDA0");
  }
  if (v == "clamp") ranged(s, 0, ranges::kClampSpacings);
  if (v == "legend" && s.args[0] != "on" && s.args[0] != "off") throw UsageError("legend: on or off");
  if (v == "letters" && s.args[0] != "on" && s.args[0] != "off") throw UsageError("letters: on or off");
  if (v == "view" && !render::namedView(s.args[0], false))
    throw UsageError("view: unknown view \"" + s.args[0] + "\"; choose " + render::kViewNames);
  if (v == "convention" && s.args[0] != "radiological" && s.args[0] != "neurological")
    throw UsageError("convention: radiological or neurological");
  if (v == "legend-corner" && !legendCornerNamed(s.args[0]))
    throw UsageError("legend-corner: unknown corner \"" + s.args[0] + "\"; choose " + kLegendCornerNames);
  if (v == "units" || v == "length-units") checkLegendText(v, s.args[0]);
  if ((v == "ao" || v == "outlines") && s.args[0] != "on" && s.args[0] != "off") throw UsageError(v + ": on or off");
  if (v == "ao-radius") ranged(s, 0, ranges::kPositiveFloat);
  if (v == "ao-strength") ranged(s, 0, ranges::kAoStrength);
  if (v == "outline-width") ranged(s, 0, ranges::kOutlineWidth);
  if (v == "shadows" && s.args[0] != "on" && s.args[0] != "off") throw UsageError("shadows: on or off");
  if (v == "shadow") shadowValue(s);
  if (v == "plane") checkPlaneSyntax(s);
  if (v == "mesh" || v == "mesh-opacity") parseIntIn(v, s.args[0], 1, int(render::kMaxContextItems));
  if (v == "mesh" && s.args[1] != "on" && s.args[1] != "off" && !meshModeNamed(s.args[1]))
    throw UsageError("mesh: give on, off or a mode (" + std::string(kMeshModeNames) + ")");
  if (v == "mesh-opacity") ranged(s, 1, ranges::kUnit);
}

}  // namespace

int ScriptStep::integer(std::size_t k) const { return int(parseInt(verb, args.at(k))); }

std::vector<ScriptStep> parseScript(const std::string& path) {
  // A regular file of sane size: a FIFO would block and /dev/zero never end.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw io::InputError("parseScript: " + path + ": no such file");
  if (!S_ISREG(st.st_mode)) throw io::InputError("parseScript: " + path + ": not a regular file");
  if (st.st_size > (1 << 20)) throw io::InputError("parseScript: " + path + ": larger than 1 MiB");
  std::ifstream in(path);
  if (!in) throw io::InputError("parseScript: " + path + ": cannot open the script");
  std::vector<ScriptStep> steps;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number > 100000) throw io::InputError("parseScript: " + path + ": more than 100000 lines");
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    ScriptStep s;
    s.line = number;
    if (!(words >> s.verb)) continue;
    for (std::string w; words >> w;) s.args.push_back(w);
    try {
      check(s);
    } catch (const UsageError& e) {
      throw io::InputError(path + ":" + std::to_string(number) + ": " + e.what());
    }
    steps.push_back(std::move(s));
  }
  if (in.bad()) throw io::InputError(path + ": read error");
  return steps;
}

void checkPlaneSteps(const std::vector<ScriptStep>& steps, const std::vector<PlaneView>& planes,
                     const std::string& path, const std::optional<SliceGrid>& underlay) {
  for (const ScriptStep& s : steps) {
    if (s.verb != "plane") continue;
    const std::string where = path + ":" + std::to_string(s.line) + ": plane " + s.args[0] + ": ";
    const std::size_t n = planeNumber(s);
    if (n > planes.size())
      throw io::InputError(where + (planes.empty() ? std::string("the view has no slice planes (give --plane or --underlay)")
                                                   : "the view has " + std::to_string(planes.size()) +
                                                         " slice plane(s), numbered from 1 in the order of --plane and --plane-at"));
    const PlaneView& p = planes[n - 1];
    if (planeToggles(s)) continue;
    if (p.slices <= 0) throw io::InputError(where + "an oblique plane (--plane-at) can only be switched on or off");
    if (s.args.size() == 2) {
      if (!underlay) throw io::InputError(where + "the view has no underlay grid to place " + s.args[1] + " on");
      try {
        resolveOn("plane " + s.args[0] + " " + s.args[1], sliceArg("plane", s.args[1]), *underlay);
      } catch (const UsageError& e) {
        throw io::InputError(path + ":" + std::to_string(s.line) + ": " + e.what() + " of the underlay's grid");
      }
      continue;
    }
    if (planeIndex(s) >= p.slices)
      throw io::InputError(where + "index " + s.args[2] + " is outside 0.." + std::to_string(p.slices - 1) + " along " +
                           std::string(1, "xyz"[p.spec.axis]));
  }
}

void checkSlabSteps(const std::vector<ScriptStep>& steps, const std::optional<SliceGrid>& field,
                    const std::string& path) {
  for (const ScriptStep& s : steps) {
    if (s.verb != "slab" || s.args[0] == "off") continue;
    const std::string where = path + ":" + std::to_string(s.line) + ": ";
    if (!field)
      throw io::InputError(where + "slab " + s.args[0] + ": the glyphs are a point set, with no grid to slice");
    try {
      resolveOn("slab " + s.args[0], sliceArg("slab", s.args[0]), *field);
    } catch (const UsageError& e) {
      throw io::InputError(where + e.what() + " of the glyphs' grid");
    }
  }
}

SliceGrid sliceGridOf(const io::GridInfo& g) {
  SliceGrid out;
  std::copy(g.dims, g.dims + 3, out.dims);
  std::copy(g.origin, g.origin + 3, out.placement.originWC);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.placement.axesWC[3 * r + c] = g.directions[3 * r + c] * g.spacing[c];
  return out;
}

SliceGrid sliceGridOf(const render::UnderlayVolume& v) {
  SliceGrid out;
  std::copy(v.dims, v.dims + 3, out.dims);
  for (int r = 0; r < 3; ++r) {
    out.placement.originWC[r] = v.indexToWC[3][r];
    for (int c = 0; c < 3; ++c) out.placement.axesWC[3 * r + c] = v.indexToWC[c][r];
  }
  return out;
}

io::SliceSpec resolveOn(const std::string& what, const io::SliceSpec& spec, const SliceGrid& g) {
  const io::SliceSpec r = io::resolveSlice(spec, g.placement, g.dims);
  const int size = g.dims[r.axis];
  if (r.index < 0 || r.index >= size)
    throw UsageError(what + ": " +
                     (spec.positionWC ? "the position falls at index " : "index ") + std::to_string(r.index) +
                     (spec.positionWC ? ", outside 0.." + std::to_string(size - 1) + " along voxel axis " + "ijk"[r.axis]
                                      : " is outside 0.." + std::to_string(size - 1) + " along voxel axis " + "ijk"[r.axis]));
  return r;
}

render::Slab slabOf(const io::SliceSpec& r, const SliceGrid& g) {
  // Voxel coordinate a of a point p is row a of the axes' inverse applied to
  // p - origin: the slab is the band of that coordinate the slice's voxels
  // fill (io::Selector's), a quarter voxel wider each side.
  glm::dmat3 m;
  for (int row = 0; row < 3; ++row)
    for (int c = 0; c < 3; ++c) m[c][row] = g.placement.axesWC[3 * row + c];
  const glm::dmat3 inv = glm::inverse(m);
  const glm::dvec3 row(inv[0][r.axis], inv[1][r.axis], inv[2][r.axis]);
  const double len = glm::length(row);
  const glm::dvec3 n = row / len;
  const glm::dvec3 origin(g.placement.originWC[0], g.placement.originWC[1], g.placement.originWC[2]);
  const double at = glm::dot(n, origin);
  double lo = at + (double(r.index - (r.thickness - 1) / 2) - 0.25) / len;
  double hi = at + (double(r.index + r.thickness / 2) + 0.25) / len;
  // Across a world axis (a grid whose axes are the world's): the axis form,
  // exact in the shaders and cutting the shadow casters' box.
  for (int w = 0; w < 3; ++w)
    if (n[(w + 1) % 3] == 0.0 && n[(w + 2) % 3] == 0.0) {
      if (n[w] < 0) std::tie(lo, hi) = std::pair(-hi, -lo);
      return render::Slab{w, lo, hi};
    }
  return render::Slab{r.axis, lo, hi, n};
}

void resize(ViewState& v) {
  const tensor::ResolvedScale r = tensor::resolveScale(v.sizing, v.magnitudes);
  v.baseScale = r.scale;
  v.params.scale = r.scale * v.scaleFactor;
  v.params.sizing = r.mapping;
}

void turnToView(ViewState& v, const std::string& name) {
  if (const std::optional<render::ViewAxes> axes = render::namedView(name, v.radiological)) {
    v.camera.turn(*axes);
    v.view = name;
  }
}

void applyStep(const ScriptStep& s, ViewState& v) {
  const std::string& w = s.verb;
  render::FrameParams& p = v.params;
  if (w == "orbit") v.camera.orbit(number(s, 0), number(s, 1));
  else if (w == "pan") v.camera.pan(number(s, 0), number(s, 1));
  else if (w == "zoom") v.camera.zoom(number(s, 0));
  else if (w == "reset") v.camera.reset();
  else if (w == "glyph") p.glyph = *glyphKindNamed(s.args[0]);
  else if (w == "gamma") p.gamma = number(s, 0);
  else if (w == "blob-threshold") p.blob.threshold = number(s, 0);
  else if (w == "blobbiness") p.blob.blobbiness = number(s, 0);
  else if (w == "fa-min") p.faMin = number(s, 0);
  else if (w == "color") p.color = *colorModeNamed(s.args[0]);
  else if (w == "colormap") p.colormap = s.args[0] == "auto" ? std::nullopt : render::colormapNamed(s.args[0]);
  else if (w == "color-range")
    p.colorWindow = s.args.size() == 1 ? std::nullopt : std::optional(glm::dvec2(number(s, 0), number(s, 1)));
  else if (w == "iterations") p.march.maxIterations = parseIntIn(w, s.args[0], 1, 1000);
  else if (w == "epsilon") p.march.epsilon = number(s, 0);
  else if (w == "stats") p.iterationStats = s.args[0] == "on";
  else if (w == "legend") p.legend.enabled = s.args[0] == "on";
  else if (w == "letters") p.orientationLetters = s.args[0] == "on";
  else if (w == "view") turnToView(v, s.args[0]);
  else if (w == "convention") {
    v.radiological = s.args[0] == "radiological";
    if (v.view == "axial" || v.view == "coronal") turnToView(v, v.view);
  }
  else if (w == "legend-corner") p.legend.corner = *legendCornerNamed(s.args[0]);
  else if (w == "units") p.legend.units = s.args[0];
  else if (w == "length-units") p.legend.lengthUnits = s.args[0];
  else if (w == "ao") p.ao.enabled = s.args[0] == "on";
  else if (w == "ao-radius") p.ao.radius = number(s, 0);
  else if (w == "ao-strength") p.ao.strength = number(s, 0);
  else if (w == "outlines") p.outline.enabled = s.args[0] == "on";
  else if (w == "outline-width") p.outline.width = number(s, 0);
  else if (w == "shadows") p.shadow.enabled = s.args[0] == "on";
  else if ((w == "mesh" || w == "mesh-opacity") && std::stoul(s.args[0]) <= v.meshes.size()) {
    MeshView& m = v.meshes[std::stoul(s.args[0]) - 1];
    if (w == "mesh-opacity") m.params.opacity = float(number(s, 1));
    else if (s.args[1] == "on" || s.args[1] == "off") m.visible = s.args[1] == "on";
    else m.params.mode = *meshModeNamed(s.args[1]);
  }
  else if (w == "shadow") {
    const double value = shadowValue(s);
    const std::string& t = s.args[0];
    if (t == "map-size") {
      p.shadow.mapSize = int(value);
      p.shadow.mapDensity = 0.0f;  // fixed, as render's --shadow-map-size
    } else (t == "penumbra" ? p.shadow.penumbra : t == "strength" ? p.shadow.strength : p.shadow.bias) = float(value);
  }
  else if (w == "plane") {
    // checkPlaneSteps has held the plane and index to the view's planes.
    const std::size_t n = planeNumber(s);
    if (n > v.planes.size()) return;
    PlaneView& plane = v.planes[n - 1];
    if (planeToggles(s)) {
      plane.visible = s.args[1] == "on";
    } else if (s.args.size() == 2 && plane.slices > 0 && v.underlayGrid) {
      const io::SliceSpec r = io::resolveSlice(io::parseSlice(s.args[1]), v.underlayGrid->placement, v.underlayGrid->dims);
      plane.slices = v.underlayGrid->dims[r.axis];
      plane.spec.axis = r.axis;
      plane.spec.index = std::clamp(r.index, 0LL, plane.slices - 1);
    } else if (s.args.size() == 3 && plane.slices > 0) {
      plane.spec.index = std::min(planeIndex(s), plane.slices - 1);
    }
  }
  else if (w == "scale") {
    v.scaleFactor = number(s, 0);
    p.scale = v.baseScale * v.scaleFactor;
  } else if (w == "magnitude" || w == "clamp") {
    if (w == "magnitude") {
      v.sizing.magnitude = *tensor::magnitudeNamed(s.args[0]);
      v.sizing.lambda0 = s.args.size() == 2 ? std::optional<double>(number(s, 1)) : std::nullopt;
    } else {
      v.sizing.clampSpacings = number(s, 0);
    }
    resize(v);
  } else if (w == "slab") {
    // checkSlabSteps has held the slice to the glyphs' grid.
    v.slabSlice.reset();
    if (s.args[0] == "off") p.slab = render::Slab{};
    else if (v.fieldGrid) {
      v.slabSlice = io::resolveSlice(io::parseSlice(s.args[0]), v.fieldGrid->placement, v.fieldGrid->dims);
      p.slab = slabOf(*v.slabSlice, *v.fieldGrid);
    }
  } else if (w == "light") {
    const auto value = float(number(s, 1));
    const std::string& t = s.args[0];
    (t == "ambient" ? p.light.ambient : t == "head" ? p.light.head : t == "key" ? p.light.key
                                        : t == "specular" ? p.light.specular : p.light.shininess) = value;
  }
}

void checkScriptMeshes(const std::vector<ScriptStep>& steps, std::size_t meshes, const std::string& path) {
  for (const ScriptStep& s : steps)
    if ((s.verb == "mesh" || s.verb == "mesh-opacity") && std::stoul(s.args[0]) > meshes)
      throw io::InputError(path + ":" + std::to_string(s.line) + ": " + s.verb + ": mesh " + s.args[0] + " of " +
                       std::to_string(meshes) + " loaded (--mesh, --mesh-from-input)");
}

}  // namespace tg::app
