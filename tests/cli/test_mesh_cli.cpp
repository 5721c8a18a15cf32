// --mesh and --mesh-from-input through the real binary: every format reads
// the same box, a volume mesh gives its outer surface, and hostile mesh files
// (truncated, lying counts, huge, NaN, a FIFO, a directory) each fail with
// exit 1 and one line naming the file, under an address-space limit.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_run.h"
#include "real_data.h"

namespace fs = std::filesystem;
using tg::test::CmdResult;

namespace {

// As tests/cli/test_hostile.cpp: anything a hostile file makes the binary
// allocate beyond 1.5 GiB of address space fails the run.
constexpr long kVirtualKiB = 1536 * 1024;

const fs::path& dir() {
  static const fs::path d = tg::test::cliDir("mesh");
  return d;
}

fs::path write(const std::string& name, const std::string& bytes) {
  const fs::path p = dir() / name;
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

CmdResult run(const std::string& args) {
  return tg::test::runBinary("", dir(), "ulimit -v " + std::to_string(kVirtualKiB) + "; exec " TG_BINARY " " + args);
}

// The kitten's stress field, published by others: only the tests about its
// FEM mesh need it, and they skip where the datasets are absent.
const std::string kKitten = std::string(TG_REAL_DATA_DIR) + "/tsv-kitten-stress/kitten-stress.vtu";

// A synthetic stress field (a point load) for the tests that only need
// glyphs beside their mesh.
std::string field() {
  const fs::path p = dir() / "field.vtu";
  if (!fs::exists(p)) {
    EXPECT_EQ(tg::test::runBinary("synth boussinesq -o " + p.string(), dir()).code, 0);
  }
  return p.string();
}

// A unit box, as 8 vertices and 6 quads (faces listed 1-based as OBJ wants them).
const double kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const int kQuad[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};

std::string boxVtk() {
  std::string s = "# vtk DataFile Version 3.0\nbox\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n";
  for (const auto& c : kCorner) s += std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + "\n";
  s += "POLYGONS 6 30\n";
  for (const auto& q : kQuad) s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " + std::to_string(q[3]) + "\n";
  return s;
}

std::string boxObj() {
  std::string s;
  for (const auto& c : kCorner) s += "v " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + "\n";
  for (const auto& q : kQuad) s += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " + std::to_string(q[2] + 1) + " " + std::to_string(q[3] + 1) + "\n";
  return s;
}

std::string boxPly(const std::string& vertexCount = "8") {
  std::string s = "ply\nformat ascii 1.0\nelement vertex " + vertexCount +
                  "\nproperty float x\nproperty float y\nproperty float z\nelement face 6\n"
                  "property list uchar int vertex_indices\nend_header\n";
  for (const auto& c : kCorner) s += std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + "\n";
  for (const auto& q : kQuad) s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " + std::to_string(q[3]) + "\n";
  return s;
}

// Binary STL: 80-byte header, count, then per triangle a normal, 3 vertices and 2 bytes.
std::string boxStl(std::uint32_t claimed = 12) {
  std::string s(80, ' ');
  s.append(reinterpret_cast<const char*>(&claimed), 4);
  for (const auto& q : kQuad)
    for (const std::array<int, 3>& tri : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      float rec[12] = {};
      for (int v = 0; v < 3; ++v)
        for (int c = 0; c < 3; ++c) rec[3 + 3 * v + c] = float(kCorner[tri[v]][c]);
      s.append(reinterpret_cast<const char*>(rec), sizeof rec);
      s.append(2, '\0');
    }
  return s;
}

// The contract for a bad mesh: exit 1, one line naming the file and `what`, no image.
void expectRefused(const std::string& meshArgs, const std::string& what, const std::string& named) {
  const fs::path out = dir() / "refused.png";
  fs::remove(out);
  const std::string args = "render " + field() + " -o " + out.string() + " --size 64 48 " + meshArgs;
  const CmdResult r = run(args);
  EXPECT_EQ(r.code, 1) << args << " -> " << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << " -> " << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << "names the file: " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << " -> " << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
}

}  // namespace

// The same box from every surface format: 6 quads become 12 triangles.
TEST(MeshCli, EveryFormatReadsTheBox) {
  const std::string vtp =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      "<Piece NumberOfPoints=\"8\" NumberOfPolys=\"6\">\n<Points><DataArray type=\"Float32\" "
      "NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1</DataArray></Points>\n"
      "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 2 3 1 4 5 7 6 0 1 5 4 2 6 7 3 0 4 6 2 "
      "1 3 7 5</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4 8 12 16 20 24</DataArray>"
      "</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  const fs::path files[] = {write("box.vtk", boxVtk()), write("box.obj", boxObj()), write("box.ply", boxPly()),
                            write("box.stl", boxStl()), write("box.vtp", vtp)};
  for (const fs::path& f : files) {
    const fs::path out = dir() / "box.png";
    const CmdResult r = run("render " + field() + " -o " + out.string() + " --size 64 48 --verbose --mesh " + f.string());
    EXPECT_EQ(r.code, 0) << f << ": " << r.err;
    EXPECT_NE(r.err.find("mesh " + f.filename().string() + ": 12 triangles, opaque"), std::string::npos) << r.err;
  }
}

// The kitten's hexahedral mesh: its boundary is what --mesh-from-input draws,
// the same surface whether read as the input or as a --mesh .vtu; the legacy
// copy of the same mesh gives the same triangle count.
TEST(MeshCli, FemBoundaryOfTheKitten) {
  TG_REQUIRE_REAL_DATA();
  const fs::path out = dir() / "kitten.png";
  const CmdResult a = run("render " + kKitten + " -o " + out.string() + " --size 64 48 --verbose --mesh-from-input");
  ASSERT_EQ(a.code, 0) << a.err;
  const auto at = a.err.find("mesh kitten-stress.vtu: ");
  ASSERT_NE(at, std::string::npos) << a.err;
  const long triangles = std::stol(a.err.substr(at + 24));
  EXPECT_GT(triangles, 1000);
  const CmdResult b = run("render " + kKitten + " -o " + out.string() + " --size 64 48 --verbose --mesh " + kKitten);
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("mesh kitten-stress.vtu: " + std::to_string(triangles) + " triangles"), std::string::npos) << b.err;
}

TEST(MeshCli, FlagsAreChecked) {
  const fs::path out = dir() / "flags.png";
  CmdResult r = run("render -o " + out.string() + " --mesh-from-input");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--mesh-from-input needs an input file"), std::string::npos) << r.err;
  r = run("render " + field() + " -o " + out.string() + " --mesh-opacity 0.5");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--mesh-opacity needs --mesh"), std::string::npos) << r.err;
  r = run("render " + field() + " -o " + out.string() + " --mesh-from-input --mesh-mode glass");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("opaque, see-through or edges"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(MeshCli, HostileMeshesFailInOneLine) {
  expectRefused("--mesh " + write("truncated.stl", boxStl().substr(0, 300)).string(), "truncated or corrupt",
                "truncated.stl");
  expectRefused("--mesh " + write("lying.stl", boxStl(1000)).string(), "header counts 1000 triangles", "lying.stl");
  expectRefused("--mesh " + write("huge.stl", boxStl(0xFFFFFFFFu).substr(0, 84)).string(), "header counts 4294967295",
                "huge.stl");
  expectRefused("--mesh " + write("huge.ply", boxPly("1000000000000")).string(), "exceeds the file size", "huge.ply");
  expectRefused("--mesh " + write("noheader.ply", "ply\nformat ascii 1.0\nelement vertex 3\n").string(),
                "no end_header", "noheader.ply");
  std::string nan = boxVtk();
  for (std::size_t at; (at = nan.find("0.000000")) != std::string::npos;) nan.replace(at, 8, "nan");
  expectRefused("--mesh " + write("allnan.vtk", nan).string(), "NaN/Inf", "allnan.vtk");
  expectRefused("--mesh " + write("garbage.vtp", "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"><Poly").string(),
                "garbage.vtp", "garbage.vtp");
  expectRefused("--mesh " + write("empty.obj", "").string(), "file is empty", "empty.obj");
  expectRefused("--mesh " + (dir() / "missing.stl").string(), "no such file", "missing.stl");
  fs::create_directories(dir() / "folder.vtp");
  expectRefused("--mesh " + (dir() / "folder.vtp").string(), "is a directory", "folder.vtp");
  const fs::path fifo = dir() / "fifo.stl";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectRefused("--mesh " + fifo.string(), "not a regular file", "fifo.stl");
  // A volume mesh cut in half: VTK's XML reader must not draw what it made of the rest.
  std::ifstream in(field(), std::ios::binary);
  const std::string whole{std::istreambuf_iterator<char>(in), {}};
  expectRefused("--mesh " + write("half.vtu", whole.substr(0, whole.size() / 2)).string(), "half.vtu", "half.vtu");
}

// A NaN corner: the three quads that share it are skipped, named as cells
// of the file, and the other three drawn, two triangles each.
TEST(MeshCli, NanVerticesSkipTheirCells) {
  std::string s = boxVtk();
  const auto at = s.find("1.000000 1.000000 1.000000");  // the last corner, on 3 of the 6 quads
  ASSERT_NE(at, std::string::npos);
  s.replace(at, 8, "nan");
  const fs::path f = write("somenan.vtk", s), out = dir() / "somenan.png";
  const CmdResult r = run("render " + field() + " -o " + out.string() + " --size 64 48 --verbose --mesh " + f.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("somenan.vtk: 3 cells skipped: a vertex is NaN/Inf"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mesh somenan.vtk: 6 triangles"), std::string::npos) << r.err;
}

// --mesh-from-input needs cells: a point cloud has no FEM mesh.
TEST(MeshCli, FemBoundaryNeedsCells) {
  const std::string cloud = "# vtk DataFile Version 3.0\ncloud\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n"
                            "0 0 0 1 0 0\nCELLS 0 0\nCELL_TYPES 0\nPOINT_DATA 2\nTENSORS t float\n"
                            "1 0 0 0 1 0 0 0 1\n2 0 0 0 1 0 0 0 1\n";
  const fs::path f = write("cloud.vtk", cloud), out = dir() / "cloud.png";
  fs::remove(out);
  const CmdResult r = run("render " + f.string() + " -o " + out.string() + " --size 64 48 --mesh-from-input");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("no cells"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}
