// Tier 2: the guarded read (a child process, the field back through a socket,
// its arrays copied out of the child's memory) gives exactly what the same
// read gives in process, for every format and for small fields, which an
// earlier spliced-pipe version let the child overwrite before the parent
// read them.
#include <gtest/gtest.h>

#include <filesystem>

#include "data-synthetic/generators.h"
#include "io/io_test_util.h"
#include "io/readers.h"
#include "io/writers.h"

using namespace tg;
namespace fs = std::filesystem;

namespace {

void expectSame(const io::TensorField& a, const io::TensorField& b, const std::string& what) {
  EXPECT_EQ(a.positions, b.positions) << what;
  EXPECT_EQ(a.tensors, b.tensors) << what;
  EXPECT_EQ(a.ids, b.ids) << what;
  EXPECT_EQ(a.path, b.path) << what;
  EXPECT_EQ(a.description, b.description) << what;
  EXPECT_EQ(a.arrayName, b.arrayName) << what;
  EXPECT_EQ(a.space, b.space) << what;
  EXPECT_EQ(a.layout, b.layout) << what;
  EXPECT_EQ(a.frame, b.frame) << what;
  EXPECT_EQ(a.measurementFrame, b.measurementFrame) << what;
  EXPECT_EQ(a.tensorToWC, b.tensorToWC) << what;
  EXPECT_EQ(a.hasConfidence, b.hasConfidence) << what;
  EXPECT_EQ(a.warnings, b.warnings) << what;
  EXPECT_EQ(a.totalPoints, b.totalPoints) << what;
  EXPECT_EQ(a.skippedNonFinite, b.skippedNonFinite) << what;
  EXPECT_EQ(a.skippedOverflow, b.skippedOverflow) << what;
  EXPECT_EQ(a.masked, b.masked) << what;
  EXPECT_EQ(a.unselected, b.unselected) << what;
  EXPECT_EQ(a.grid.has_value(), b.grid.has_value()) << what;
  if (a.grid && b.grid) {
    EXPECT_TRUE(std::equal(a.grid->dims, a.grid->dims + 3, b.grid->dims)) << what;
    EXPECT_TRUE(std::equal(a.grid->origin, a.grid->origin + 3, b.grid->origin)) << what;
  }
  EXPECT_EQ(a.sampleSpacing, b.sampleSpacing) << what;
}

}  // namespace

TEST(ReadGuard, GivesExactlyTheInProcessFieldForEveryFormatAndSize) {
  const fs::path d = test::scratchDir("read_guard");
  const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (const int n : {1, 2, 3, 7, 40}) {
    const io::TensorField helix = synth::helixPhantom(n, n > 3 ? 5 : 1, n > 3 ? 4 : 1).field;
    for (const char* ext : {".vtk", ".vti", ".vtu", ".vtp", ".nrrd"}) {
      const fs::path p = d / ("field-" + std::to_string(n) + ext);
      if (std::string(ext) == ".nrrd") io::writeNrrd(helix, p.string(), identity);
      else io::writeVtk(helix, p.string());
      const io::TensorField guarded = io::readTensorField(p.string(), {});
      const io::TensorField direct = io::readTensorFieldInProcess(p.string(), {});
      ASSERT_EQ(direct.size(), helix.size()) << p;
      expectSame(guarded, direct, p.string());
    }
  }
}

TEST(ReadGuard, ASelectionAndItsCountsCrossTheBoundary) {
  const fs::path d = test::scratchDir("read_guard");
  const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const fs::path p = d / "sel.nrrd";
  io::writeNrrd(synth::helixPhantom(9, 8, 7).field, p.string(), identity);
  io::ReadOptions o;
  o.selection.stride = 2;
  o.selection.roiWC = std::array<double, 6>{-100, -100, -100, 100, 100, 1};
  const io::TensorField guarded = io::readTensorField(p.string(), o);
  EXPECT_GT(guarded.unselected, 0u);
  expectSame(guarded, io::readTensorFieldInProcess(p.string(), o), p.string());
}

// A selection that keeps nothing: the field crosses with empty arrays, and
// both ends agree that no array is fetched. (They once disagreed, and the
// child waited for a reply the parent never sent: `info` hung.)
TEST(ReadGuard, AnEmptyFieldCrossesWithoutWaiting) {
  const fs::path d = test::scratchDir("read_guard");
  const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const fs::path p = d / "none.nrrd";
  io::writeNrrd(synth::helixPhantom(5, 4, 3).field, p.string(), identity);
  io::ReadOptions o;
  o.selection.roiWC = std::array<double, 6>{1e6, 1e6, 1e6, 2e6, 2e6, 2e6};
  const io::TensorField guarded = io::readTensorField(p.string(), o);
  EXPECT_EQ(guarded.size(), 0u);
  EXPECT_EQ(guarded.unselected, 60u);
  expectSame(guarded, io::readTensorFieldInProcess(p.string(), o), p.string());
}
