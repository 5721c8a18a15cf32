#pragma once
// The command-line face of context meshes (render/mesh_item.h): --mesh FILE
// (repeatable), --mesh-from-input and the render::MeshParams flags, whose
// help quotes the struct's defaults. Shared by render and view.
#include <memory>
#include <optional>
#include <string_view>
#include <string>
#include <vector>

#include "app/scale/option_table.h"
#include <glm/vec3.hpp>

#include "app/output_check.h"
#include "io/core/mesh_reader.h"
#include "render/mesh_item.h"
#include "render/renderer.h"

namespace tg::app {

struct MeshFlags {
  std::vector<std::string> files;
  bool fromInput = false;
  render::MeshParams params;
  std::string firstParameterFlag;  // a --mesh-* parameter flag given, for validate()
  bool opacityGiven = false, featureAngleGiven = false;  // for modeApplies()

  void addTo(OptionTable& ap);
  // UsageError for a parameter flag without a mesh, and for --mesh-from-input
  // without an input file (the built-in scene has no FEM mesh).
  void validate(const std::string& input) const;
  bool any() const { return fromInput || !files.empty(); }
  // UsageError for a parameter of another mode than the one drawn: --mesh-opacity
  // without see-through, --mesh-feature-angle without edges. Only where the
  // mode stays as given (render); the viewer's panel switches modes.
  void checkModeParameters() const;
  // The mesh files, for refuseOutputsOverInputs.
  std::vector<NamedPath> inputs() const;
  // Reads every mesh (io::readMesh, in the guarded child), warning on stderr
  // as `command` of triangles skipped for NaN/Inf vertices.
  std::vector<io::MeshData> read(const std::string& input, const char* command) const;
};

// Adds one MeshItem per mesh, with `params`, labelled "mesh FILENAME".
void addMeshes(render::GlyphRenderer& r, const gl::Api& gl, const gl::ShaderLibrary& lib,
               const std::vector<io::MeshData>& meshes, const render::MeshParams& params);
// Grows lo..hi (WC) by the meshes' drawn vertices: the camera's depth range must hold them.
void growByMeshes(const std::vector<io::MeshData>& meshes, glm::dvec3& lo, glm::dvec3& hi);

// "opaque", "see-through" or "edges"; nothing for another name.
std::optional<render::MeshMode> meshModeNamed(std::string_view name);
inline constexpr const char* kMeshModeNames = "opaque, see-through or edges";

}  // namespace tg::app
