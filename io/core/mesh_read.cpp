// readMesh's guarded child and the checks it makes first; the reading itself
// is the VTK module's (io/modules/vtk/mesh_reader.cpp, io/core/format_modules.h).
#include <algorithm>
#include <memory>

#include "io/core/format_modules.h"
#include "io/core/format_table.h"
#include "io/core/guard_wire.h"
#include "io/core/mesh_reader.h"
#include "io/core/read_guard.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readMesh: " + path + ": " + what);
}

constexpr std::uint32_t kMeshWireMagic = 0x54474d31;  // "TGM1"

}  // namespace

std::string meshExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::uint64_t checkMeshFile(const std::string& path, MeshSource source) {
  const std::uint64_t size = checkInputFile("readMesh", path);
  if (const std::string problem = meshExtensionProblem(path, source); !problem.empty()) fail(path, problem);
  return size;
}

std::string meshExtensionProblem(const std::string& path, MeshSource source) {
  const InputFormatRow* row = inputFormatRowOf(path);
  std::string ext = "\"";
  ext.append(shownExtension(path)).append("\"");
  if (source == MeshSource::FemBoundary)
    return row && row->uses & kFemUse ? ""
                                      : "--mesh-from-input needs an FEM mesh input (an unstructured grid: " +
                                            extensionList(kFemUse, " ", " or ") + "), not " + ext;
  if (row && row->uses & (kSurfaceUse | kVolumeMeshUse)) return "";
  return "unknown mesh extension " + ext + "; supported: " + extensionList(kSurfaceUse) + ", and " +
         extensionList(kVolumeMeshUse) + " (outer surface)";
}

MeshData readMesh(const std::string& path, MeshSource source) {
  const std::uint64_t size = checkMeshFile(path, source);
  const std::uint64_t budget = defaultMemoryBudget();
  MeshData out;
  runInChild(
      "readMesh", path, limitsFor(size, budget),
      [&](const PromiseFn& promise) -> SendFn {
        auto m = std::make_shared<const MeshData>(vtkFormats("readMesh", path).readMesh(path, source, budget, promise));
        return [m](WireOut& w) {
          w.pod(kMeshWireMagic);
          w.str(m->path);
          w.str(m->description);
          w.pod(std::uint64_t(m->skippedNonFinite));
          w.array(m->positionsWC);
          w.array(m->triangles);
        };
      },
      [&](WireIn& in) {
        if (in.pod<std::uint32_t>() != kMeshWireMagic) throw std::runtime_error("the reader's result is malformed");
        out.path = in.str();
        out.description = in.str();
        out.skippedNonFinite = std::size_t(in.pod<std::uint64_t>());
        in.array(out.positionsWC);
        in.array(out.triangles);
      });
  // The child's indices are checked here, where they are used: a reader
  // that returned garbage must not index past the vertices on the GPU.
  const std::size_t nv = out.vertexCount();
  if (out.positionsWC.size() % 3 || out.triangles.size() % 3 ||
      std::any_of(out.triangles.begin(), out.triangles.end(), [nv](std::uint32_t i) { return i >= nv; }))
    fail(path, "the reader's triangles index past its vertices");
  return out;
}

}  // namespace tg::io
