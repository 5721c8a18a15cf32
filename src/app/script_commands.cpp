#include "app/script_commands.h"

#include <algorithm>
#include <vector>

#include "app/legend_flags.h"
#include "app/mesh_flags.h"
#include "app/names.h"
#include "tensor/glyph_scale.h"
#include "view/anatomy.h"
#include "view/underlay.h"

namespace tg::app {
namespace {

// In the order the reference lists them; built once, never changed. A SLICE is written as --slice
// takes it (io::parseSlice): i|j|k:INDEX[:THICKNESS] (x, y, z: the voxel
// axes i, j, k), axial|coronal|sagittal:INDEX[:THICKNESS] (the voxel axis
// nearest S, A or R) or x|y|z=POSITION[mm][:THICKNESS] (the slice nearest a
// world position).
const std::vector<ScriptCommand>& commands() {
  static const std::vector<ScriptCommand> kCommands = {
    {"orbit", "YAW PITCH", 2, 2, "turn by degrees, turntable about the world's up axis"},
    {"pan", "DX DY", 2, 2, "move the scene by view heights, right and up"},
    {"zoom", "F", 1, 1, "F times closer"},
    {"reset", "", 0, 0, "the initial view"},
    {"view", "NAME", 1, 1,
     std::string("look from an anatomical side, keeping the look-at point and distance: ") + render::kViewNames +
         " (render --view; keys 1, 2, 3: axial, coronal, sagittal)"},
    {"convention", "radiological|neurological", 1, 1,
     "the side axial and coronal views look from (render --radiological, --neurological; key V)"},
    {"letters", "on|off", 1, 1, "R/L, A/P, S/I on the image's edges (render --orientation-letters; key L)"},
    {"glyph", "KIND", 1, 1, "the glyph kind: " + kGlyphKindNames},
    {"gamma", "G", 1, 1, "superquadric sharpness, >= 0 (and a blob's bumps')"},
    {"blob-threshold", "T", 1, 1, "blob: the surface where the bumps' sum is T (render --blob-threshold)"},
    {"blobbiness", "B", 1, 1, "blob: Blinn's blobbiness, < 0 (render --blobbiness)"},
    {"fa-min", "F", 1, 1, "hide glyphs with FA below F"},
    {"scale", "F", 1, 1, "glyph size, F times the initial scale"},
    {"magnitude", "MAPPING [LAMBDA0]", 1, 2,
     std::string("the size mapping (render --magnitude): ") + tensor::kMagnitudeNames +
         "; LAMBDA0 (log and shape) defaults to the median"},
    {"clamp", "N", 1, 1, "no glyph wider than N sample spacings; 0: off"},
    {"color", "MODE", 1, 1, std::string("what the colour shows: ") + kColorModeNames},
    {"colormap", "NAME|auto", 1, 1,
     std::string("the colormap of a scalar colour: ") + render::kColormapNames + "; auto: the quantity's own"},
    {"color-range", "LO HI|auto", 1, 2, "the values at the colormap's ends; auto: the whole field's range"},
    {"slab", "SLICE|off", 1, 1,
     "only the glyphs of one slice or slab of the field's grid, SLICE as render's --slice takes it: "
     "i|j|k:INDEX[:THICKNESS], axial|coronal|sagittal:INDEX[:THICKNESS], x|y|z=POSITION[mm][:THICKNESS] (the "
     "glyphs that --slice would load, on oblique grids too); off: every glyph"},
    {"plane", "N on|off, N SLICE, N index I", 2, 3,
     "slice plane N (1: the first --plane or --plane-at): shown or hidden; moved to a SLICE of the underlay's "
     "grid, as --slice takes it but one slice thick; or to slice I of its own axis (0-based, as --plane)"},
    {"light", "ambient|head|key|specular|shininess V", 2, 2, "a lighting term (render's --ambient and others)"},
    {"iterations", "N", 1, 1, "superquadric Newton iterations at most"},
    {"epsilon", "E", 1, 1, "superquadric hit tolerance"},
    {"stats", "on|off", 1, 1, "count Newton iterations (status line)"},
    {"legend", "on|off", 1, 1, "the colour key and scale bar (render --legend)"},
    {"legend-corner", "CORNER", 1, 1, std::string("where the legend goes: ") + kLegendCornerNames},
    {"units", "TEXT", 1, 1, "units of the tensor values in the legend (one word)"},
    {"length-units", "TEXT", 1, 1, "units of positions for the scale bar (one word)"},
    {"ao", "on|off", 1, 1, "screen-space ambient occlusion"},
    {"ao-radius", "R", 1, 1, "its radius in world units (> 0)"},
    {"ao-strength", "S", 1, 1, "its weight, 0..4"},
    {"outlines", "on|off", 1, 1, "silhouette and crease lines"},
    {"outline-width", "W", 1, 1, "their width in pixels, 0.25..8"},
    {"shadows", "on|off", 1, 1, "soft shadows from the key light"},
    {"shadow", "penumbra|strength|bias|map-size V", 2, 2, "a shadow parameter (render's --shadow-* flags and ranges)"},
    {"mesh", "N on|off|MODE", 2, 2,
     std::string("the N-th mesh (--mesh-from-input first, then each --mesh; from 1): shown, hidden, or drawn in "
                 "MODE, as render's --mesh-mode: ") + kMeshModeNames},
    {"mesh-opacity", "N A", 2, 2, "the N-th mesh's see-through opacity, 0..1"},
    {"frames", "N", 1, 1, "render N frames unchanged (for timing)"},
    {"screenshot", "FILE", 1, 1, "save the rendered view (without the panel)"},
    {"pick", "I J", 2, 2,
     "print what pixel (I, J) shows as one line of JSON on stdout, as render --pick (column I, row J from the top)"},
  };
  return kCommands;
}

constexpr const char* kIntro =
    "One command per line; '#' starts a comment. A script is parsed and checked whole before the window opens, so "
    "a mistake on line 40 costs no run. Values are held to the ranges of the render options they match.";

// `text` in lines of at most about 100 columns, each begun with `indent`.
std::string wrapped(const std::string& text, const std::string& indent) {
  constexpr std::size_t kWidth = 100;
  std::string out, line = indent;
  std::size_t k = 0;
  while (k < text.size()) {
    const std::size_t end = std::min(text.find(' ', k), text.size());
    const std::string word = text.substr(k, end - k);
    if (line.size() > indent.size() && line.size() + 1 + word.size() > kWidth) {
      out += line + "\n";
      line = indent;
    }
    line += (line.size() > indent.size() ? " " : "") + word;
    k = end + 1;
  }
  return out + line + "\n";
}

}  // namespace

std::span<const ScriptCommand> scriptCommands() { return commands(); }

const ScriptCommand* scriptCommand(const std::string& verb) {
  const std::vector<ScriptCommand>& all = commands();
  const auto it = std::find_if(all.begin(), all.end(), [&](const ScriptCommand& c) { return verb == c.verb; });
  return it == all.end() ? nullptr : &*it;
}

std::string scriptReference(bool markdown) {
  std::string s;
  if (markdown) {
    s = "# The viewer's script language\n\nGenerated from the command table (src/app/script_commands.cpp) by the "
        "build; `tensorglyph help script` prints the same. Run a script with `tensorglyph view INPUT --script "
        "FILE`.\n\n" + std::string(kIntro) + "\n\n| command | arguments | what it does |\n|---|---|---|\n";
    // A table cell: '|' separates choices here, not columns.
    auto cell = [](std::string t) {
      for (std::size_t k = 0; (k = t.find('|', k)) != std::string::npos; k += 2) t.replace(k, 1, "\\|");
      return t;
    };
    // Appended, not `"| `" + ...`: GCC 12 warns falsely (-Wrestrict).
    for (const ScriptCommand& c : commands()) {
      s.append("| `").append(c.verb).append("` | ");
      if (!c.args.empty()) s.append("`").append(cell(c.args)).append("`");
      s.append(" | ").append(cell(c.help)).append(" |\n");
    }
    return s;
  }
  s = "the viewer's script language (tensorglyph view INPUT --script FILE):\n" + wrapped(kIntro, "") + "\n";
  for (const ScriptCommand& c : commands()) {
    const std::string form = c.verb + (c.args.empty() ? "" : " ") + c.args;
    s += "  " + form + "\n" + wrapped(c.help, "      ");
  }
  return s;
}

}  // namespace tg::app
