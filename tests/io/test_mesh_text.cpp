// Tier 2: text meshes whose numbers VTK reads by their prefix (issue 30).
// VTK 9.1 read OBJ's "v 0 2 nan" as (0, 2, 0) and "v 1,5 2 3" as (1, 0, 0),
// and drew them; PLY's "0,5" as 0. A NaN/Inf vertex now skips its cells,
// counted, as for .vtk; a number with anything after it is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/io_test_util.h"
#include "io/core/mesh_reader.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("mesh_text"); }

// Two triangles sharing no vertex: vertices 1-3 and 4-6. `v4` is the fourth
// vertex's coordinates; `face` the first face's indices.
std::string obj(const std::string& v4 = "3 0 0", const std::string& face = "1 2 3") {
  return "# two triangles\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv " + v4 + "\nv 4 0 0\nv 3 1 0\nf " + face + "\nf 4 5 6\n";
}

std::string ply(const std::string& x4 = "3") {
  return "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" + x4 +
         " 0 0\n4 0 0\n3 1 0\n3 0 1 2\n3 3 4 5\n";
}

std::string stl(const std::string& x = "1") {
  return "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex " + x +
         " 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
}

io::MeshData read(const fs::path& p) { return io::readMeshInProcess(p.string(), io::MeshSource::Surface); }

std::string errorOf(const fs::path& p) {
  try {
    read(p);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshText, ObjVerticesWithNanOrInfSkipTheirCellsCounted) {
  for (const char* v4 : {"0 2 nan", "inf 0 0", "3 -Infinity 0", "1e39 0 0"}) {
    const fs::path p = tmpDir() / "nan.obj";
    test::writeFile(p, obj(v4));
    const io::MeshData m = read(p);
    EXPECT_EQ(m.skippedNonFinite, 1u) << v4;
    ASSERT_EQ(m.triangleCount(), 1u) << v4;
    for (float x : m.positionsWC) EXPECT_LE(std::abs(x), 1.0f) << v4;  // the first triangle only
  }
}

TEST(MeshText, ObjNumbersWithTrailingCharactersAreRefused) {
  const fs::path p = tmpDir() / "bad.obj";
  const struct {
    std::string v4, face, problem;
  } cases[] = {
      {"1,5 2 3", "1 2 3", "line 5: \"1,5\" is not a number"},
      {"0x10 0 0", "1 2 3", "line 5: \"0x10\" is not a number"},
      {"3 0 0abc", "1 2 3", "line 5: \"0abc\" is not a number"},
      {"3 0", "1 2 3", "line 5: v needs 3 numbers, the line has 2"},
      {"3 0 0", "1 2 3x", "line 8: \"3x\" is not a vertex index (v, v/vt, v//vn or v/vt/vn)"},
      {"3 0 0", "1 2.5 3", "line 8: \"2.5\" is not a vertex index (v, v/vt, v//vn or v/vt/vn)"},
      {"3 0 0", "1/1/1/1 2 3", "line 8: \"1/1/1/1\" is not a vertex index (v, v/vt, v//vn or v/vt/vn)"},
  };
  for (const auto& c : cases) {
    test::writeFile(p, obj(c.v4, c.face));
    EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": " + c.problem) << c.v4 << " / " << c.face;
  }
}

TEST(MeshText, ObjNeighboursStillRead) {
  const fs::path p = tmpDir() / "good.obj";
  test::writeFile(p, obj("+3 -0 0.0e0", "-6 -5 -4"));  // negative indices count back from the last vertex
  const io::MeshData m = read(p);
  EXPECT_EQ(m.skippedNonFinite, 0u);
  EXPECT_EQ(m.triangleCount(), 2u);
  test::writeFile(p, "v 0 0 0 1\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0\nf 1//1 2//1 3//1\nf 1/1/1 2/1/1 3/1/1\n");
  EXPECT_EQ(read(p).triangleCount(), 2u);
}

TEST(MeshText, PlyValuesAreReadWhole) {
  const fs::path p = tmpDir() / "t.ply";
  for (const char* bad : {"0,5", "3x", "0x10"}) {
    test::writeFile(p, ply(bad));
    EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": line 13: \"" + std::string(bad) + "\" is not a number") << bad;
  }
  test::writeFile(p, ply("3 0"));
  EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": line 13: element vertex 3 has 4 values, its properties take 3");
  std::string face = ply();
  face.replace(face.find("3 3 4 5"), 7, "3 3 4.5 5");
  test::writeFile(p, face);
  EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": line 17: \"4.5\" is not an integer");
  test::writeFile(p, ply("+3.0e0"));
  EXPECT_EQ(read(p).triangleCount(), 2u);
  test::writeFile(p, ply("nan"));
  const io::MeshData m = read(p);
  EXPECT_EQ(m.skippedNonFinite, 1u);
  EXPECT_EQ(m.triangleCount(), 1u);
}

TEST(MeshText, AsciiStlNumbersAreReadWhole) {
  const fs::path p = tmpDir() / "t.stl";
  test::writeFile(p, stl("1.5abc"));
  EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": line 5: \"1.5abc\" is not a number");
  test::writeFile(p, stl("1,5"));
  EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": line 5: \"1,5\" is not a number");
  test::writeFile(p, stl("1 2"));
  EXPECT_EQ(errorOf(p), "readMesh: " + p.string() + ": line 5: \"vertex\" needs three numbers, the line has 4");
  test::writeFile(p, stl("-1E0"));
  EXPECT_EQ(read(p).triangleCount(), 1u);
}
