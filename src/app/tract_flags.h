#pragma once
// The command-line face of tracts (render/tract_item.h): --tracts FILE
// (repeatable), --tract-color and --tract-width, whose help quotes
// render::TractParams's defaults. Shared by render, view and Python.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/scale/option_table.h"
#include "app/output_check.h"
#include "io/core/tract_reader.h"
#include "render/renderer.h"
#include "render/tract_item.h"

namespace tg::app {

struct TractFlags {
  std::vector<std::string> files;
  render::TractParams params;
  std::string firstParameterFlag;  // a --tract-* flag given, for validate()

  void addTo(OptionTable& ap);
  // UsageError for a --tract-* flag without --tracts, and for a file name no
  // tract reader takes.
  void validate() const;
  bool any() const { return !files.empty(); }
  std::vector<NamedPath> inputs() const;
  // Reads every file (io::readTracts, in the guarded child), warning on
  // stderr as `command` of streamlines skipped for NaN/Inf points and of
  // the readers' own warnings; InputError for a file with nothing to draw.
  std::vector<io::TractData> read(const char* command) const;
};

// Adds one TractItem per file, with `params`, labelled "tracts FILENAME".
void addTracts(render::GlyphRenderer& r, const gl::Api& gl, const gl::ShaderLibrary& lib,
               const std::vector<io::TractData>& tracts, const render::TractParams& params);
// Grows lo..hi (WC) by the points: the camera's depth range must hold them.
void growByTracts(const std::vector<io::TractData>& tracts, glm::dvec3& lo, glm::dvec3& hi);

}  // namespace tg::app
