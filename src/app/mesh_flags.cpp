#include "app/mesh_flags.h"

#include <cstdio>

#include "app/scale/option_table.h"
#include "app/scale/cli_values.h"
#include "app/scale/option_ranges.h"
#include "io/core/format_table.h"

namespace tg::app {
std::optional<render::MeshMode> meshModeNamed(std::string_view name) {
  for (render::MeshMode m : {render::MeshMode::Opaque, render::MeshMode::SeeThrough, render::MeshMode::Edges})
    if (name == render::meshModeName(m)) return m;
  return std::nullopt;
}

void MeshFlags::addTo(OptionTable& ap) {
  using Args = OptionArgs;
  const render::MeshParams d;
  auto given = [this](const char* flag) {
    if (firstParameterFlag.empty()) firstParameterFlag = flag;
  };
  const std::string group = ap.groupDefault();
  ap.setGroup("context");
  ap.arg("--mesh FILE")
      .help("draw a surface with the glyphs: " + io::extensionList(io::kSurfaceUse) + ", or the outer surface of a " +
            io::extensionList(io::kVolumeMeshUse, "/") + " volume mesh")
      .repeats().action([this](Args a) { files.emplace_back(a[1]); });
  ap.arg("--mesh-from-input").help("draw the boundary of the FEM mesh the tensors came from (a " + io::extensionList(io::kFemUse, "/") + " input)")
      .action([this](Args) { fromInput = true; });
  ap.arg("--mesh-mode MODE")
      .help("how meshes are drawn: opaque, see-through (the front layer blended over the glyphs) or edges (feature "
            "edges)")
      .oneOf(kMeshModeNames).byDefault(render::meshModeName(d.mode))
      .action([this, given](Args a) {
        given("--mesh-mode");
        const auto m = meshModeNamed(a[1]);
        if (!m) throw UsageError("--mesh-mode: unknown mode \"" + std::string(a[1]) + "\"; choose " + kMeshModeNames);
        params.mode = *m;
      });
  ap.arg("--mesh-color R G B")
      .help("mesh colour")
      .range(ranges::kUnit).byDefault(formatNumber(d.color.r) + " " + formatNumber(d.color.g) + " " + formatNumber(d.color.b)).action([this, given](Args a) {
        given("--mesh-color");
        for (int k = 0; k < 3; ++k) params.color[k] = float(parseDouble(a[0], a[1 + std::size_t(k)]));
      });
  ap.arg("--mesh-opacity A")
      .help("see-through: opacity of a face seen head-on, rising towards the outline")
      .range(ranges::kUnit).byDefault(formatNumber(d.opacity)).action([this, given](Args a) {
        given("--mesh-opacity");
        opacityGiven = true;
        params.opacity = float(parseDouble(a[0], a[1]));
      });
  ap.arg("--mesh-feature-angle DEG")
      .help("edges: draw creases sharper than this, and every boundary edge")
      .range(ranges::kFeatureAngleDeg).byDefault(formatNumber(d.featureAngleDeg)).action([this, given](Args a) {
        given("--mesh-feature-angle");
        featureAngleGiven = true;
        params.featureAngleDeg = float(parseDouble(a[0], a[1]));
      });
  ap.setGroup(group);
}

void MeshFlags::validate(const std::string& input) const {
  if (!firstParameterFlag.empty() && !any()) throw UsageError(firstParameterFlag + " needs --mesh or --mesh-from-input");
  if (fromInput && input.empty())
    throw UsageError("--mesh-from-input needs an input file: the built-in scene has no FEM mesh");
  // A name that cannot be a mesh is a command-line mistake, found before the
  // tensors load (readMesh would find it after, with exit 1).
  if (fromInput)
    if (const std::string p = io::meshExtensionProblem(input, io::MeshSource::FemBoundary); !p.empty())
      throw UsageError(input + ": " + p);
  for (const std::string& f : files)
    if (const std::string p = io::meshExtensionProblem(f, io::MeshSource::Surface); !p.empty())
      throw UsageError("--mesh: " + f + ": " + p);
}

void MeshFlags::checkModeParameters() const {
  if (opacityGiven && params.mode != render::MeshMode::SeeThrough)
    throw UsageError("--mesh-opacity applies to --mesh-mode see-through; the meshes are drawn " +
                     std::string(render::meshModeName(params.mode)));
  if (featureAngleGiven && params.mode != render::MeshMode::Edges)
    throw UsageError("--mesh-feature-angle applies to --mesh-mode edges; the meshes are drawn " +
                     std::string(render::meshModeName(params.mode)));
}

std::vector<NamedPath> MeshFlags::inputs() const {
  std::vector<NamedPath> v;
  for (const std::string& f : files) v.push_back({"--mesh", f});
  return v;
}

std::vector<io::MeshData> MeshFlags::read(const std::string& input, const char* command) const {
  std::vector<io::MeshData> meshes;
  if (fromInput) meshes.push_back(io::readMesh(input, io::MeshSource::FemBoundary));
  for (const std::string& f : files) meshes.push_back(io::readMesh(f, io::MeshSource::Surface));
  for (const io::MeshData& m : meshes)
    if (m.skippedNonFinite)
      std::fprintf(stderr, "tensorglyph %s: %s: %zu cells skipped: a vertex is NaN/Inf or beyond single precision\n",
                   command, printable(m.path).c_str(), m.skippedNonFinite);
  return meshes;
}

void addMeshes(render::GlyphRenderer& r, const gl::Api& gl, const gl::ShaderLibrary& lib,
               const std::vector<io::MeshData>& meshes, const render::MeshParams& params) {
  for (const io::MeshData& m : meshes) {
    const std::string name = m.path.substr(m.path.find_last_of('/') + 1);
    r.addContext(std::make_unique<render::MeshItem>(gl, lib, "mesh " + name, m.positionsWC, m.triangles, params));
  }
}

void growByMeshes(const std::vector<io::MeshData>& meshes, glm::dvec3& lo, glm::dvec3& hi) {
  for (const io::MeshData& m : meshes)
    for (std::uint32_t i : m.triangles) {
      const glm::dvec3 p(m.positionsWC[3 * std::size_t(i)], m.positionsWC[3 * std::size_t(i) + 1],
                         m.positionsWC[3 * std::size_t(i) + 2]);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
}

}  // namespace tg::app
