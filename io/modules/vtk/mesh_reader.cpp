#include "io/core/mesh_reader.h"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "io/core/format_impl.h"
#include "io/modules/vtk/mesh_text_checks.h"
#include "io/core/readers.h"
#include "io/core/tract_builder.h"
#include "io/modules/vtk/vtk_capture.h"
#include "io/modules/vtk/vtk_dataset.h"

namespace tg::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError("readMesh: " + path + ": " + what);
}

// A binary STL is an 80-byte header, a triangle count and 50 bytes per
// triangle; one whose count disagrees with its size is truncated or lies.
// ASCII STL ("solid ...") has no counts to check.
void checkStl(const std::string& path, std::uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, 84);
  const std::uint64_t got = std::uint64_t(in.gcount());
  // ASCII, or a binary file whose header begins with "solid": VTK's binary
  // reader reads to the end of the file whatever the count says.
  if (got >= 5 && std::memcmp(head, "solid", 5) == 0) return;
  if (got < 84) fail(path, "too short for a binary STL (" + std::to_string(size) + " bytes; the header alone is 84)");
  std::uint32_t n = 0;
  std::memcpy(&n, head + 80, 4);
  if (84 + 50 * std::uint64_t(n) != size)
    fail(path, "binary STL header counts " + std::to_string(n) + " triangles (" + std::to_string(84 + 50 * std::uint64_t(n)) +
                   " bytes), the file has " + std::to_string(size) + " bytes: truncated or corrupt");
}

// A PLY header's element counts, which VTK's reader allocates from: every
// vertex takes at least 3 bytes of the file and every face at least 4.
void checkPly(const std::string& path, std::uint64_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) fail(path, "not a PLY file (no \"ply\" line)");
  long double need = 0;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (lineNo > 10000 || in.tellg() > std::streamoff(1 << 20)) break;
    if (line.rfind("end_header", 0) == 0) {
      if (need > (long double)size) fail(path, "PLY header's element counts exceed the file size");
      return;
    }
    std::istringstream ls(line);
    std::string key, name;
    long double n = -1;
    if (ls >> key >> name >> n && key == "element") {
      if (n < 0) fail(path, "negative count for PLY element \"" + name + "\"");
      need += n * (name == "vertex" ? 3 : name == "face" ? 4 : 1);
      if (need > (long double)size) fail(path, "PLY element \"" + name + "\" count exceeds the file size");
    }
  }
  fail(path, "PLY header has no end_header line in its first MiB");
}

// Runs a VTK source whose errors and messages we collect; any word from VTK
// means its output cannot be trusted.
void runVtk(vtkAlgorithm* a, const std::string& path) {
  const VtkMessageCapture said;
  a->Update();
  if (a->GetErrorCode() || !said.first().empty())
    fail(path, said.first().empty() ? "VTK could not read the file" : said.first());
}

vtkSmartPointer<vtkPolyData> triangulate(vtkDataSet* ds, const std::string& path) {
  vtkNew<vtkTriangleFilter> tri;
  tri->PassVertsOff();
  tri->PassLinesOff();
  if (vtkPolyData::SafeDownCast(ds)) {
    tri->SetInputData(ds);
  } else {
    // The outer surface: faces used by one cell only (vtkDataSetSurfaceFilter,
    // which handles every cell type, quadratic ones by subdivision).
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputData(ds);
    runVtk(surface, path);
    tri->SetInputConnection(surface->GetOutputPort());
  }
  runVtk(tri, path);
  return tri->GetOutput();
}

bool finiteFloat(const double p[3], const NonFiniteText* nonFinite, double out[3]) {
  bool fits = true;
  for (int c = 0; c < 3; ++c) {
    out[c] = nonFinite ? nonFinite->restore(p[c]) : p[c];
    fits &= std::abs(out[c]) <= double(FLT_MAX);  // false for NaN
  }
  return fits;
}

// A cell of a fixed-size type must list that many points: VTK's filters
// read a tetra's fourth id whatever the file gave (past the connectivity for
// a tetra of three ids, drawn; a crash for a hexahedron of four). VTK's own
// cells say their size; polygons and the like (0) vary, and Lagrange and
// Bézier cells (68 on) have at least theirs.
void checkCellSizes(vtkUnstructuredGrid* ug, const std::string& path) {
  vtkUnsignedCharArray* types = ug->GetCellTypesArray();
  vtkCellArray* cells = ug->GetCells();
  if (!types || !cells || types->GetNumberOfValues() != cells->GetNumberOfCells())
    fail(path, "its cell types do not match its cells");
  std::array<int, 256> size;
  size.fill(-1);
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c) {
    const unsigned char type = types->GetValue(c);
    if (size[type] < 0) {
      vtkCell* cell = vtkGenericCell::InstantiateCell(type);
      size[type] = cell ? int(cell->GetNumberOfPoints()) : 0;
      if (cell) cell->Delete();
    }
    const vtkIdType n = cells->GetCellSize(c);
    if (size[type] > 0 && (type >= VTK_LAGRANGE_CURVE ? n < size[type] : n != size[type]))
      fail(path, "cell " + std::to_string(c) + " of type " + std::to_string(int(type)) + " lists " +
                     std::to_string(n) + " points; that type has " + std::to_string(size[type]) +
                     (type >= VTK_LAGRANGE_CURVE ? " or more" : ""));
  }
}

// VTK's readers keep a cell's point ids as the file gives them (legacy,
// XML, OBJ and PLY alike). An id outside the points made the filters and
// toMesh read, and toMesh's remap write, outside their arrays: a negative id
// drew a triangle to a "vertex" read from before the points, a large one
// crashed. Checked before anything walks the cells.
void checkCellPoints(vtkDataSet* ds, const std::string& path) {
  const vtkIdType n = ds->GetNumberOfPoints();
  auto outside = [&](double id) {
    fail(path, "a cell refers to point " + std::to_string(std::int64_t(id)) + ", but the file has " + std::to_string(n) +
                   " points (0.." + std::to_string(n - 1) + ")");
  };
  auto checkCells = [&](vtkCellArray* cells) {
    if (!cells) return;
    if (!cells->IsValid()) fail(path, "its cell offsets do not index its cell connectivity");
    if (cells->GetNumberOfConnectivityIds() == 0) return;
    double range[2];
    cells->GetConnectivityArray()->GetRange(range, 0);
    if (range[0] < 0) outside(range[0]);
    if (range[1] >= double(n)) outside(range[1]);
  };
  if (auto* pd = vtkPolyData::SafeDownCast(ds)) {
    for (vtkCellArray* cells : {pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips()}) checkCells(cells);
  } else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds)) {
    checkCells(ug->GetCells());
    checkCellSizes(ug, path);
    // Polyhedra: per cell, a face count, then each face's size and ids.
    vtkIdTypeArray* faces = ug->GetFaces();
    vtkIdTypeArray* at = ug->GetFaceLocations();
    if (!faces || !at) return;
    const vtkIdType size = faces->GetNumberOfValues();
    for (vtkIdType c = 0; c < at->GetNumberOfValues(); ++c) {
      vtkIdType k = at->GetValue(c);
      if (k < 0) continue;  // not a polyhedron
      if (k >= size) fail(path, "a polyhedron's faces lie beyond its face list");
      for (vtkIdType f = faces->GetValue(k++); f > 0; --f) {
        if (k >= size) fail(path, "a polyhedron's faces lie beyond its face list");
        const vtkIdType m = faces->GetValue(k++);
        if (m < 0 || m > size - k) fail(path, "a polyhedron's faces lie beyond its face list");
        for (const vtkIdType end = k + m; k < end; ++k)
          if (const vtkIdType id = faces->GetValue(k); id < 0 || id >= n) outside(double(id));
      }
    }
  }
}

// VTK's OBJ reader cannot read a NaN/Inf coordinate (its stream stops and
// leaves 0 or the last vertex's value): the vertices checkObjText found are
// made NaN here, so that their cells are skipped and counted.
void markNonFiniteVertices(vtkDataSet* ds, const std::string& path, const std::vector<std::uint64_t>& vertices,
                           std::uint64_t fileVertices) {
  if (vertices.empty()) return;
  auto* ps = vtkPointSet::SafeDownCast(ds);
  if (!ps || !ps->GetPoints() || std::uint64_t(ps->GetNumberOfPoints()) != fileVertices)
    fail(path, "a vertex has a NaN/Inf coordinate, and VTK's points do not follow the file's vertices (faces index "
               "normals or texture coordinates apart), so its cells cannot be told");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::uint64_t v : vertices) ps->GetPoints()->SetPoint(vtkIdType(v), nan, nan, nan);
}

constexpr const char* kSourceCell = "tg_source_cell";

// Cells of `ds` with a NaN/Inf or out-of-range vertex, counted in `skipped`;
// when there are any, each cell is tagged with its index (a cell array the
// filters carry to every triangle they make of it), so that toMesh drops all
// of a bad cell's triangles: VTK cuts a polygon with a NaN corner into
// triangles unpredictably, and one that misses the corner is no truer.
std::vector<char> markBadCells(vtkDataSet* ds, const NonFiniteText* nonFinite, std::size_t& skipped) {
  const vtkIdType nPts = ds->GetNumberOfPoints(), nCells = ds->GetNumberOfCells();
  std::vector<char> badPoint(static_cast<std::size_t>(nPts));
  bool any = false;
  for (vtkIdType i = 0; i < nPts; ++i) {
    double p[3], q[3];
    ds->GetPoint(i, p);
    badPoint[std::size_t(i)] = !finiteFloat(p, nonFinite, q);
    any |= badPoint[std::size_t(i)] != 0;
  }
  std::vector<char> bad;
  if (!any) return bad;
  bad.resize(static_cast<std::size_t>(nCells));
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < nCells; ++c) {
    ds->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds() && !bad[std::size_t(c)]; ++k)
      bad[std::size_t(c)] = badPoint[std::size_t(ids->GetId(k))];
    skipped += bad[std::size_t(c)] ? 1 : 0;
  }
  vtkNew<vtkIdTypeArray> tag;
  tag->SetName(kSourceCell);
  tag->SetNumberOfTuples(nCells);
  for (vtkIdType c = 0; c < nCells; ++c) tag->SetValue(c, c);
  ds->GetCellData()->AddArray(tag);
  return bad;
}

// Our triangles from VTK's, with the triangles of `badCells` (markBadCells)
// dropped and vertices compacted.
MeshData toMesh(vtkPolyData* pd, const std::string& path, const NonFiniteText* nonFinite,
                const std::vector<char>& badCells, std::size_t skippedCells) {
  MeshData m;
  m.path = path;
  m.skippedNonFinite = skippedCells;
  const vtkIdType nPts = pd->GetNumberOfPoints();
  vtkCellArray* polys = pd->GetPolys();
  const vtkIdType nTri = polys ? polys->GetNumberOfCells() : 0;
  if (nTri <= 0) fail(path, "no surface to draw: the file holds no polygons or faces");
  if (std::uint64_t(nTri) > kMaxMeshTriangles)
    fail(path, std::to_string(nTri) + " triangles, more than the limit of " + std::to_string(kMaxMeshTriangles));
  if (std::uint64_t(nPts) >= std::numeric_limits<std::uint32_t>::max())
    fail(path, std::to_string(nPts) + " vertices, more than 32-bit indices hold");
  vtkDataArray* source = badCells.empty() ? nullptr : pd->GetCellData()->GetArray(kSourceCell);
  if (!badCells.empty() && (!source || source->GetNumberOfTuples() != nTri))
    fail(path, "VTK lost track of which cells its triangles came from");
  std::vector<std::uint32_t> remap(static_cast<std::size_t>(nPts), std::numeric_limits<std::uint32_t>::max());
  m.triangles.reserve(3 * std::size_t(nTri));
  vtkIdType n = 0, t = 0;
  const vtkIdType* ids = nullptr;
  std::uint32_t next = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids); ++t) {
    if (n != 3) continue;  // the triangle filter leaves none
    if (source) {
      const auto cell = std::size_t(source->GetTuple1(t));
      if (cell >= badCells.size() || badCells[cell]) continue;
    }
    double p[3][3];
    bool fits = true;
    for (int k = 0; k < 3; ++k) {
      double raw[3];
      pd->GetPoint(ids[k], raw);
      fits &= finiteFloat(raw, nonFinite, p[k]);
    }
    if (!fits) fail(path, "a triangle VTK made has a NaN/Inf vertex that no cell of the file has");
    std::uint32_t* tri = m.triangles.extend(3);
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& r = remap[std::size_t(ids[k])];
      if (r == std::numeric_limits<std::uint32_t>::max()) {
        r = next++;
        float* out = m.positionsWC.extend(3);
        for (int c = 0; c < 3; ++c) out[c] = float(p[k][c]);
      }
      tri[k] = r;
    }
  }
  if (m.triangles.empty())
    fail(path, "nothing to draw: every cell with faces has a NaN/Inf or out-of-range vertex (" +
                   std::to_string(skippedCells) + " cells)");
  return m;
}

// readVtk's read and checks, its errors in the words of `reader`.
ReadResult readDataSetAs(const char* reader, const std::string& path, std::uint64_t budget,
                         const PromiseFn& promise) {
  ReadOptions opt;
  opt.memoryBudget = budget;
  opt.onPromise = promise;
  try {
    return readDataSet(path, opt);
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind("readVtk: ", 0) != 0) throw;
    throw InputError(std::string(reader).append(what.substr(7)));
  }
}

}  // namespace

MeshData impl::readMesh(const std::string& path, MeshSource source, std::uint64_t budget, const PromiseFn& promise) {
  const std::uint64_t size = checkMeshFile(path, source);
  const std::string ext = meshExtension(path);
  MeshData m;
  if (ext == "stl" || ext == "obj" || ext == "ply") {
    if (ext == "stl") checkStl(path, size);
    if (ext == "stl") checkStlText(path);
    if (ext == "ply") checkPly(path, size);
    if (ext == "ply") checkPlyText(path);
    std::uint64_t objVertices = 0;
    const std::vector<std::uint64_t> nonFiniteVertices = ext == "obj" ? checkObjText(path, objVertices)
                                                                       : std::vector<std::uint64_t>{};
    // VTK's points and cells, its triangulated copy and ours: every value
    // takes at least a byte of the file, and becomes at most 8 bytes, thrice.
    const long double need = 24.0L * (long double)size + (64 << 20);
    if (budget && need > (long double)budget)
      fail(path, "reading would need about " + std::to_string(std::uint64_t(need / (1 << 20))) +
                     " MiB, more than the " + std::to_string(budget >> 20) + " MiB this load may use");
    if (promise) promise(size, std::uint64_t(need));
    vtkSmartPointer<vtkAlgorithm> reader;
    if (ext == "stl") {
      auto r = vtkSmartPointer<vtkSTLReader>::New();
      r->SetFileName(path.c_str());
      reader = r;
    } else if (ext == "obj") {
      auto r = vtkSmartPointer<vtkOBJReader>::New();
      r->SetFileName(path.c_str());
      reader = r;
    } else {
      auto r = vtkSmartPointer<vtkPLYReader>::New();
      r->SetFileName(path.c_str());
      reader = r;
    }
    runVtk(reader, path);
    auto* ds = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    if (!ds) fail(path, "VTK read no dataset");
    markNonFiniteVertices(ds, path, nonFiniteVertices, objVertices);
    checkCellPoints(ds, path);
    std::size_t skipped = 0;
    const std::vector<char> bad = markBadCells(ds, nullptr, skipped);
    m = toMesh(triangulate(ds, path), path, nullptr, bad, skipped);
    m.description = std::string(ds->GetClassName()) + ", " + std::to_string(ds->GetNumberOfCells()) + " cells";
  } else {
    const ReadResult read = readDataSetAs("readMesh", path, budget, promise);
    // As readVtk: VTK stops, with a warning, at a 3D-TSV stress trailer,
    // after the geometry; any other word from VTK is refused.
    if (!read.vtkSaid.empty() && read.vtkSaid.find("Unsupported point attribute type") == std::string::npos)
      fail(path, read.vtkSaid);
    vtkDataSet* ds = read.data;
    const bool volume = !vtkPolyData::SafeDownCast(ds);
    if (source == MeshSource::FemBoundary) {
      if (!vtkUnstructuredGrid::SafeDownCast(ds))
        fail(path, std::string("--mesh-from-input: the input is a ") + ds->GetClassName() +
                       ", not an FEM mesh (an unstructured grid)");
      if (ds->GetNumberOfCells() == 0)
        fail(path, "--mesh-from-input: the input has points but no cells, so no FEM mesh to draw the boundary of");
    }
    if (ds->GetNumberOfCells() == 0) fail(path, "no cells: nothing to draw");
    checkCellPoints(ds, path);
    const NonFiniteText* nonFinite = read.nonFinite.empty() ? nullptr : &read.nonFinite;
    std::size_t skipped = 0;
    const std::vector<char> bad = markBadCells(ds, nonFinite, skipped);
    m = toMesh(triangulate(ds, path), path, nonFinite, bad, skipped);
    m.description = std::string(ds->GetClassName()) + ", " + std::to_string(ds->GetNumberOfCells()) + " cells" +
                    (volume ? ": outer surface" : "");
  }
  m.description += ", " + std::to_string(m.triangleCount()) + " triangles";
  return m;
}

// A .vtk or .vtp's polylines (Slicer's and DIPY's fibre files): each LINES
// cell one streamline, its points in world coordinates as the file gives them.
TractData impl::readPolylines(const std::string& path, std::uint64_t budget, const PromiseFn& promise) {
  auto failTracts = [&](const std::string& what) { throw InputError("readTracts: " + path + ": " + what); };
  const ReadResult read = readDataSetAs("readTracts", path, budget, promise);
  if (!read.vtkSaid.empty()) failTracts(read.vtkSaid);
  auto* pd = vtkPolyData::SafeDownCast(read.data);
  if (!pd) failTracts(std::string("a ") + read.data->GetClassName() + " holds no polylines (tracts are POLYDATA LINES)");
  vtkCellArray* lines = pd->GetLines();
  if (!lines || lines->GetNumberOfCells() == 0) failTracts("no polylines (LINES) to draw as tracts");
  try {
    checkCellPoints(pd, path);
  } catch (const InputError& e) {  // in this reader's words
    const std::string what = e.what();
    if (what.rfind("readMesh: ", 0) != 0) throw;
    throw InputError("readTracts" + what.substr(8));
  }
  if (std::uint64_t(lines->GetNumberOfConnectivityIds()) > kMaxTractPoints)
    failTracts(std::to_string(lines->GetNumberOfConnectivityIds()) + " points on its lines, more than the limit of " +
               std::to_string(kMaxTractPoints));
  const NonFiniteText* nonFinite = read.nonFinite.empty() ? nullptr : &read.nonFinite;
  TractData out;
  out.path = path;
  TractBuilder build(out, "readTracts: " + path);
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);) {
    for (vtkIdType k = 0; k < n; ++k) {
      double raw[3];
      pd->GetPoint(ids[k], raw);
      for (double& v : raw) v = nonFinite ? nonFinite->restore(v) : v;
      build.point(raw[0], raw[1], raw[2]);
    }
    build.end(false);
  }
  if (out.pointCount() == 0)
    failTracts("nothing to draw: every polyline has a NaN/Inf point (" + std::to_string(out.skippedNonFinite) + ")");
  out.description = std::string(pd->GetClassName()) + ", " + std::to_string(out.streamlineCount()) + " polylines, " +
                    std::to_string(out.pointCount()) + " points";
  return out;
}

}  // namespace tg::io
