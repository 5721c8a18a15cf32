// Sizes a command is asked for, checked before any work (issue 30): synth's
// --n per KIND and output format, and a NRRD header naming a million data
// files, which render's output check once took minutes to list.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

fs::path dir() { return tg::test::cliDir("limits"); }

CmdResult run(const std::string& args) { return tg::test::runBinary(args, dir()); }

double secondsOf(const std::string& args, CmdResult& r) {
  const auto t0 = std::chrono::steady_clock::now();
  r = run(args);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// Each refused at once with exit 2 and the range or the memory it needs,
// writing nothing: before, helix --n 600 was cut to 512 without a word and
// generated 67 M voxels for minutes, random --n 0 wrote 10,000 points, and
// random --n 300000000 allocated until bad_alloc.
TEST(SynthLimits, OutOfRangeSizesAreRefusedBeforeGenerating) {
  const struct {
    std::string args;
    const char* said;
  } cases[] = {
      {"helix --n 600", "--n 600: helix's --n is the grid side, within 2..256"},
      {"helix --n 1", "within 2..256"},
      {"helix --n 0", "within 2..256"},
      {"boussinesq --n 513", "--n 513: boussinesq's --n is the grid side, within 2..512"},
      {"boussinesq --n -3", "within 2..512"},
      {"random --n 0", "--n 0: random's --n is the tensor count, within 1..4000000000"},
      {"random --n 4000000001", "within 1..4000000000"},
      {"extremes --n 10", "--n does not apply to extremes: its gallery has a fixed size"},
      {"extremes-huge --n 10", "--n does not apply to extremes-huge"},
      {"helix --seed 4", "--seed applies to random only"},
  };
  for (const auto& c : cases)
    for (const char* ext : {".vtk", ".vtu"}) {
      const fs::path out = dir() / (std::string("s") + ext);
      CmdResult r;
      const double s = secondsOf("synth " + c.args + " -o " + out.string(), r);
      tg::test::expectFailsCleanly("synth " + c.args + " -o " + out.string(), c.said, out, dir(), 1);
      EXPECT_EQ(r.code, 2) << c.args;
      EXPECT_LT(s, 10.0) << c.args << ": refused only after work";
    }
}

// A field too big for this machine's memory is refused with what it needs,
// by output format: the streamed .nhdr holds one chunk whatever the count,
// and is not refused for its size.
TEST(SynthLimits, MemoryIsCheckedPerFormatBeforeGenerating) {
  for (const char* ext : {".vtk", ".vtu", ".vtp"}) {
    const fs::path out = dir() / (std::string("big") + ext);
    CmdResult r;
    const double s = secondsOf("synth random --n 4000000000 -o " + out.string(), r);
    EXPECT_EQ(r.code, 2) << ext << ": " << r.err;
    EXPECT_NE(r.err.find("--n 4000000000: random written as " + std::string(ext) + " needs about "), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("MiB this machine allows; .nhdr streams any size"), std::string::npos) << r.err;
    EXPECT_LT(s, 10.0);
    EXPECT_FALSE(fs::exists(out));
  }
  // The streamed .nhdr needs 24 B a tensor on disk: refused at once when its
  // directory has less free, exit 1 as a full disk (run only there, or it
  // would write 96 GB).
  const fs::path nhdr = dir() / "big.nhdr";
  if (fs::space(dir()).available < 4000000000ULL * 24) {
    CmdResult r;
    EXPECT_LT(secondsOf("synth random --n 4000000000 -o " + nhdr.string(), r), 10.0);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(nhdr.string() + ": random --n 4000000000 needs about 91552 MiB on disk, more than the"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(nhdr));
  }
  // Within range and memory, the sizes asked for are the sizes written.
  const fs::path h = dir() / "h.nrrd", r = dir() / "r.nhdr";
  ASSERT_EQ(run("synth helix --n 6 -o " + h.string()).code, 0);
  EXPECT_NE(run("info " + h.string()).out.find("6x6x3"), std::string::npos) << run("info " + h.string()).out;
  ASSERT_EQ(run("synth random --n 7 -o " + r.string()).code, 0);
  EXPECT_NE(run("info " + r.string()).out.find("tensors: 7 total"), std::string::npos) << run("info " + r.string()).out;
}

// "data file: LIST" and a million names: render's check that -o is none of
// the input's files listed them through Teem's quadratic parser, in the
// unguarded parent, for 196 s before the read (info: 6 s). Now both refuse
// at once, naming the count; the bound is far below the old time.
TEST(SynthLimits, AMillionListedDataFilesAreRefusedFast) {
  const fs::path header = dir() / "million.nhdr", out = dir() / "million.png";
  {
    std::ofstream h(header);
    h << "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 4 4 4\nkinds: 3D-symmetric-matrix space space space\n"
         "encoding: raw\ndata file: LIST 3\n";
    for (int k = 0; k < 1000000; ++k) h << "d" << k << ".raw\n";
  }
  for (const std::string& cmd : {"render " + header.string() + " -o " + out.string(), "info " + header.string()}) {
    CmdResult r;
    const double s = secondsOf(cmd, r);
    EXPECT_EQ(r.code, 1) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("1000000 data files; at most 100000 are accepted"), std::string::npos) << r.err;
    EXPECT_LT(s, 30.0) << cmd;
  }
  EXPECT_FALSE(fs::exists(out));
  fs::remove(header);  // 13 MB
}
