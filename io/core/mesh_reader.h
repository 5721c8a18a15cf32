#pragma once
// Polygon surfaces for the scene's context (render/mesh_item.h): surfaces
// read through VTK's readers, and the outer surface of volume meshes,
// triangulated. Read in the guarded child like the tensor readers.
#include <cstddef>
#include <cstdint>
#include <string>

#include "util/mapped_array.h"

namespace tg::io {

// More triangles than this are refused before any of ours are allocated:
// 12 bytes of indices each on the GPU, 0.8 GB at the limit.
inline constexpr std::uint64_t kMaxMeshTriangles = std::uint64_t(1) << 26;

struct MeshData {
  std::string path;
  std::string description;  // what was read, e.g. "vtkUnstructuredGrid, 8000 cells: outer surface"
  util::MappedArray<float> positionsWC;       // 3 per vertex
  util::MappedArray<std::uint32_t> triangles;  // 3 vertex indices per triangle
  // Cells of the file (polygons, or a volume mesh's cells) with a vertex
  // NaN/Inf or beyond single precision: none of their triangles is drawn.
  std::size_t skippedNonFinite = 0;
  std::size_t vertexCount() const { return positionsWC.size() / 3; }
  std::size_t triangleCount() const { return triangles.size() / 3; }
};

enum class MeshSource {
  Surface,     // --mesh: a polygon file, or a volume mesh's outer surface
  FemBoundary  // --mesh-from-input: the boundary of the tensors' own FEM mesh
};

// .vtp .vtk .stl .obj .ply, and .vtu .vts (their outer surface); for
// FemBoundary only a .vtu or legacy .vtk unstructured grid with cells.
// Checks the file's type and counts before VTK allocates, reads in a child
// process (io/core/read_guard.h) and throws InputError "readMesh: path: problem".
MeshData readMesh(const std::string& path, MeshSource source);
// The same without the child process, for the fuzzers.
MeshData readMeshInProcess(const std::string& path, MeshSource source, std::uint64_t memoryBudget = 0);

// The checks readMesh makes before reading: the file exists, is a regular,
// non-empty file and has an extension `source` accepts. Returns its size;
// throws InputError "readMesh: path: problem".
std::uint64_t checkMeshFile(const std::string& path, MeshSource source);
// The extension of `path`, lower case, without the dot ("" when none).
std::string meshExtension(const std::string& path);
// Why a file of this name cannot be read as `source` (its extension), or ""
// when it can: the command line checks names before anything is loaded.
std::string meshExtensionProblem(const std::string& path, MeshSource source);

}  // namespace tg::io
