// The table of input formats (io/core/format_table.h) walked row by row: every
// extension is accepted by the checks of the uses its row names and routed
// to that row's reader, every other use refuses it, and every option a row
// does not take is refused for it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cctype>
#include <filesystem>

#include "io/core/format_table.h"
#include "io/io_test_util.h"
#include "io/core/mesh_reader.h"
#include "io/core/readers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

fs::path tmpDir() { return test::scratchDir("formats"); }

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Bytes no reader takes, so that each says who it is in refusing them.
fs::path garbage(const std::string& ext) {
  const fs::path p = tmpDir() / ("garbage" + ext);
  test::writeFile(p, "not a file of any format\n");
  return p;
}

template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

TEST(Formats, EveryExtensionNamesItsRowInAnyCase) {
  for (const io::InputFormatRow& row : io::inputFormats()) {
    ASSERT_FALSE(row.extensions.empty()) << row.name;
    for (const std::string& ext : row.extensions) {
      std::string inFolder = "dir.x/f", shouted = "F";
      inFolder += ext;
      shouted += upper(ext);
      for (const std::string& path : {inFolder, shouted}) {
        EXPECT_EQ(io::inputFormatRowOf(path), &row) << path;
        EXPECT_EQ(io::inputFormatOf(path), row.readTensors ? row.format : io::InputFormat::Unknown) << path;
      }
    }
  }
  EXPECT_EQ(io::inputFormatRowOf("field.gz"), nullptr);
  EXPECT_EQ(io::inputFormatRowOf("a.nii/field"), nullptr);
}

TEST(Formats, TensorRowsRouteToTheirReaderAndTheRestAreRefused) {
  for (const io::InputFormatRow& row : io::inputFormats())
    for (const std::string& ext : row.extensions) {
      const fs::path p = garbage(ext);
      const std::string e = errorOf([&] { io::readTensorFieldInProcess(p.string(), {}); });
      ASSERT_FALSE(e.empty()) << p;
      if (row.uses & io::kTensorUse) {
        ASSERT_TRUE(row.readTensors) << row.name;
        EXPECT_TRUE(startsWith(e, std::string(row.tensorReader) + ": ")) << ext << ": " << e;
      } else {
        EXPECT_EQ(row.readTensors, nullptr) << row.name;
        // Tracts are named for what they are, and where they go.
        if (row.uses & io::kTractUse)
          EXPECT_EQ(e, "readTensorField: " + p.string() + ": " + row.name +
                           " holds streamlines, not tensors: give it with --tracts beside a tensor input");
        else
          EXPECT_EQ(e, "readTensorField: " + p.string() + ": unknown extension \"" + ext + "\"; supported: " +
                           io::extensionList(io::kTensorUse));
      }
    }
}

TEST(Formats, ScalarRowsServeMasksAndUnderlaysAndTheRestAreRefused) {
  const int dims[3] = {1, 1, 1};
  for (const io::InputFormatRow& row : io::inputFormats())
    for (const std::string& ext : row.extensions) {
      const fs::path p = garbage(ext);
      const std::string mask = errorOf([&] { io::readScalarVolume(p.string(), dims); });
      const std::string underlay = errorOf([&] { io::readUnderlay(p.string()); });
      const bool scalar = row.uses & io::kScalarUse;
      EXPECT_EQ(bool(row.readScalars), scalar) << row.name << ext;
      EXPECT_EQ(mask.find("unknown mask format") == std::string::npos, scalar) << mask;
      EXPECT_EQ(underlay.find("unknown underlay format") == std::string::npos, scalar) << underlay;
      EXPECT_FALSE(mask.empty() || underlay.empty()) << p;
      if (!scalar) {
        EXPECT_NE(mask.find(io::extensionList(io::kScalarUse, ", ", " or ")), std::string::npos) << mask;
      }
    }
}

TEST(Formats, MeshRowsAreAcceptedForTheirUsesOnly) {
  for (const io::InputFormatRow& row : io::inputFormats())
    for (const std::string& ext : row.extensions) {
      const std::string path = "m" + ext;
      const bool surface = row.uses & (io::kSurfaceUse | io::kVolumeMeshUse);
      EXPECT_EQ(io::meshExtensionProblem(path, io::MeshSource::Surface).empty(), surface) << path;
      EXPECT_EQ(io::meshExtensionProblem(path, io::MeshSource::FemBoundary).empty(), bool(row.uses & io::kFemUse))
          << path;
    }
}

TEST(Formats, AnOptionARowDoesNotTakeIsRefusedForIt) {
  struct Option {
    unsigned bit;
    const char* flag;
    void (*set)(io::ReadOptions&);
  };
  const Option options[] = {
      {io::kLayoutOption, "--layout", [](io::ReadOptions& o) { o.layout = "fsl"; }},
      {io::kFrameOption, "--frame", [](io::ReadOptions& o) { o.frame = "world"; }},
      {io::kArrayOption, "--array", [](io::ReadOptions& o) { o.arrayName = "tensors"; }},
      {io::kConfidenceOption, "--confidence-min", [](io::ReadOptions& o) { o.confidenceGiven = true; }},
  };
  for (const io::InputFormatRow& row : io::inputFormats()) {
    if (!(row.uses & io::kTensorUse)) continue;
    for (const Option& option : options) {
      io::ReadOptions opt;
      option.set(opt);
      EXPECT_EQ(io::inapplicableOption(row.format, opt), row.options & option.bit ? "" : option.flag)
          << row.name << " " << option.flag;
    }
  }
  // A row's options are its family's: readers name the family, not the row.
  for (const io::InputFormatRow& a : io::inputFormats())
    for (const io::InputFormatRow& b : io::inputFormats())
      if (a.format == b.format && a.readTensors) {
        EXPECT_EQ(a.options, b.options) << a.name;
      }
}

// The one check before any reader: each entry point says the same four
// things about a file it cannot read, naming itself and the file.
TEST(Formats, EveryEntryPointChecksTheFileAlike) {
  const fs::path dir = tmpDir() / "folder.nrrd";
  fs::create_directories(dir);
  const fs::path empty = tmpDir() / "empty.nrrd";
  test::writeFile(empty, "");
  const fs::path fifo = tmpDir() / "fifo.nrrd";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path missing = tmpDir() / "missing.nrrd";
  const int dims[3] = {1, 1, 1};
  const std::pair<fs::path, std::string> cases[] = {
      {dir, "is a directory"}, {empty, "file is empty"}, {fifo, "not a regular file"}, {missing, "no such file"}};
  for (const auto& [path, said] : cases) {
    const std::string p = path.string();
    EXPECT_EQ(errorOf([&] { io::readTensorFieldInProcess(p, {}); }), "readTensorField: " + p + ": " + said);
    EXPECT_EQ(errorOf([&] { io::readScalarVolume(p, dims); }), "readScalarVolume: " + p + ": " + said);
    EXPECT_EQ(errorOf([&] { io::readUnderlay(p); }), "readUnderlay: " + p + ": " + said);
    const std::string mesh = (path.parent_path() / (path.stem().string() + ".stl")).string();
    if (path == dir) fs::create_directories(mesh);
    if (path == empty) test::writeFile(mesh, "");
    if (path == fifo) {
      fs::remove(mesh);
      ASSERT_EQ(::mkfifo(mesh.c_str(), 0600), 0);
    }
    EXPECT_EQ(errorOf([&] { io::readMesh(mesh, io::MeshSource::Surface); }), "readMesh: " + mesh + ": " + said);
  }
}
