// What the binary loads (issue 17, start-up): OpenImageIO and Mesa only when
// a command needs them, VTK, Teem and libnifti only for their own files (and
// VTK only in the guarded reader's child), and a clear failure when a module
// is missing. The dynamic loader's own trace (LD_DEBUG=files) is the witness.
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

#include "cli/cli_run.h"
#include "io/nifti_fixture.h"

namespace fs = std::filesystem;
using tg::test::cliDir;
using tg::test::runBinary;

namespace {

// The libraries the loader opened while running `args`, as it reports them.
tg::test::CmdResult traced(const std::string& args, const fs::path& scratch, const std::string& binary = TG_BINARY) {
  return runBinary(args, scratch, "env LD_DEBUG=files " + binary);
}

bool opened(const tg::test::CmdResult& r, const std::string& library) {
  return r.err.find("file=" + library) != std::string::npos;
}

// The libraries opened by `args`, per process: LD_DEBUG_OUTPUT also catches
// the guarded reader's child, whose stderr is /dev/null. Each trace line
// begins with the pid; the first is the command's own.
struct Loads {
  std::string parent, child;  // every "file=" line of each
  bool opened(const std::string& library) const { return inParent(library) || inChild(library); }
  bool inParent(const std::string& library) const { return parent.find("file=" + library) != std::string::npos; }
  bool inChild(const std::string& library) const { return child.find("file=" + library) != std::string::npos; }
};

Loads tracedLoads(const std::string& args, const fs::path& scratch, int expectedCode = 0) {
  const fs::path prefix = scratch / "ld";
  for (const auto& e : fs::directory_iterator(scratch))
    if (e.path().filename().string().rfind("ld.", 0) == 0) fs::remove(e.path());
  const auto r = runBinary(args, scratch, "env LD_DEBUG=files LD_DEBUG_OUTPUT=" + prefix.string() + " " TG_BINARY);
  EXPECT_EQ(r.code, expectedCode) << args << " -> " << r.err;
  Loads loads;
  std::string firstPid;
  for (const auto& e : fs::directory_iterator(scratch)) {
    if (e.path().filename().string().rfind("ld.", 0) != 0) continue;
    std::istringstream in(tg::test::slurp(e.path()));
    for (std::string line; std::getline(in, line);) {
      std::istringstream words(line);
      std::string pid;
      words >> pid;
      if (firstPid.empty()) firstPid = pid;
      if (line.find("file=") != std::string::npos) (pid == firstPid ? loads.parent : loads.child) += line + "\n";
    }
  }
  EXPECT_NE(loads.parent.find("file="), std::string::npos) << "no loader trace for " << args;
  return loads;
}

}  // namespace

TEST(Startup, HelpLoadsNeitherImageLibraryNorMesa) {
  const fs::path d = cliDir("startup_help");
  const auto r = traced("--help", d);
  ASSERT_EQ(r.code, 0) << r.err.substr(0, 2000);
  EXPECT_NE(r.out.find("render"), std::string::npos);
  // The trace lists libc, so an empty trace cannot pass for a lean one.
  EXPECT_TRUE(opened(r, "libc.so.6"));
  EXPECT_FALSE(opened(r, "libOpenImageIO.so"));
  EXPECT_FALSE(opened(r, "libOSMesa.so"));
  EXPECT_FALSE(opened(r, "libLLVM"));
  for (const char* lib : {"libvtk", "libteem", "libnifti", "libznz", "tensorglyph-"})
    EXPECT_EQ(r.err.find(lib), std::string::npos) << lib;
}

TEST(Startup, PngRenderLoadsMesaButNotOpenImageIO) {
  const fs::path d = cliDir("startup_png");
  const auto r = traced("render -o " + (d / "a.png").string() + " --size 64 48", d);
  ASSERT_EQ(r.code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::file_size(d / "a.png") > 100);
  EXPECT_TRUE(opened(r, "libOSMesa.so.8"));
  EXPECT_FALSE(opened(r, "libOpenImageIO.so"));
}

TEST(Startup, ExrRenderLoadsTheOpenImageIOModule) {
  const fs::path d = cliDir("startup_exr");
  const auto r = traced("render -o " + (d / "a.exr").string() + " --size 64 48", d);
  ASSERT_EQ(r.code, 0) << r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0);
  EXPECT_TRUE(fs::exists(d / "a.exr"));
  EXPECT_NE(r.err.find("tensorglyph-oiio.so"), std::string::npos);
  EXPECT_TRUE(opened(r, "libOpenImageIO.so.2.4"));
}

// A binary installed without its module still writes PNG, and refuses the
// formats that need the module in one line, before rendering anything.
TEST(Startup, WithoutTheModuleOnlyItsFormatsFail) {
  const fs::path d = cliDir("startup_nomodule");
  const fs::path lone = d / "tensorglyph";
  fs::copy_file(TG_BINARY, lone, fs::copy_options::overwrite_existing);
  ASSERT_FALSE(fs::exists(d / "tensorglyph-oiio.so"));
  const auto png = runBinary("render -o " + (d / "a.png").string() + " --size 64 48", d, lone.string());
  EXPECT_EQ(png.code, 0) << png.err;
  EXPECT_TRUE(fs::exists(d / "a.png"));
  tg::test::expectFailsCleanly("render -o " + (d / "a.exr").string() + " --size 64 48",
                               "needs OpenImageIO, through the module " + (d / "tensorglyph-oiio.so").string(),
                               d / "a.exr", d, 1, lone.string());
}

// The inputs of the format tests: a one-glyph .vtk and a small helix .nrrd
// written by the binary itself, and a 2x2x2 NIfTI-1 tensor volume.
struct FormatInputs {
  fs::path vtk, nrrd, nifti;
};

FormatInputs formatInputs(const fs::path& d) {
  FormatInputs in{d / "one.vtk", d / "helix.nrrd", d / "dti.nii.gz"};
  EXPECT_EQ(runBinary("synth random --n 1 -o " + in.vtk.string(), d).code, 0);
  EXPECT_EQ(runBinary("synth helix --n 4 -o " + in.nrrd.string(), d).code, 0);
  tg::test::NiftiTensors fx;
  fx.dims[0] = fx.dims[1] = fx.dims[2] = 2;
  fx.voxels.assign(8, {1.0f, 0.1f, 0.0f, 0.5f, 0.0f, 0.3f});  // FSL order: xx xy xz yy yz zz
  tg::test::writeNifti(in.nifti, fx);
  return in;
}

TEST(Startup, NrrdRenderLoadsTeemAloneOfTheFormatLibraries) {
  const fs::path d = cliDir("startup_nrrd");
  const FormatInputs in = formatInputs(d);
  const Loads l = tracedLoads("render " + in.nrrd.string() + " -o " + (d / "a.png").string() + " --size 64 48", d);
  EXPECT_TRUE(l.opened("libteem.so"));
  EXPECT_TRUE(l.opened("libOSMesa.so.8"));
  for (const char* lib : {"libvtk", "libnifti", "libOpenImageIO.so", "tensorglyph-vtk.so", "tensorglyph-nifti.so"})
    EXPECT_FALSE(l.opened(lib)) << lib;
}

TEST(Startup, NiftiRenderLoadsLibniftiAloneOfTheFormatLibraries) {
  const fs::path d = cliDir("startup_nifti");
  const FormatInputs in = formatInputs(d);
  const Loads l = tracedLoads("render " + in.nifti.string() + " -o " + (d / "a.png").string() + " --size 64 48", d);
  EXPECT_TRUE(l.opened("libnifti2.so"));
  for (const char* lib : {"libvtk", "libteem", "libOpenImageIO.so", "tensorglyph-vtk.so", "tensorglyph-teem.so"})
    EXPECT_FALSE(l.opened(lib)) << lib;
}

// VTK, the largest of the three, never enters the rendering process: only
// the guarded reader's child loads it.
TEST(Startup, VtkRenderLoadsVtkInTheReadersChildAlone) {
  const fs::path d = cliDir("startup_vtk");
  const FormatInputs in = formatInputs(d);
  const Loads l = tracedLoads("render " + in.vtk.string() + " -o " + (d / "a.png").string() + " --size 64 48", d);
  EXPECT_TRUE(l.inChild("libvtkCommonCore-9.1.so"));
  EXPECT_FALSE(l.inParent("libvtk"));
  EXPECT_TRUE(l.inParent("libOSMesa.so.8"));
  for (const char* lib : {"libteem", "libnifti", "tensorglyph-teem.so", "tensorglyph-nifti.so"})
    EXPECT_FALSE(l.opened(lib)) << lib;
}

// Each format's module missing: its files are refused in one line naming the
// module's file, with no output; the other formats still render.
TEST(Startup, WithoutAFormatModuleOnlyItsFilesFail) {
  const fs::path d = cliDir("startup_noformats");
  const FormatInputs in = formatInputs(d);
  const fs::path lone = d / "bin" / "tensorglyph";
  fs::create_directories(lone.parent_path());
  fs::copy_file(TG_BINARY, lone, fs::copy_options::overwrite_existing);
  const fs::path built = fs::path(TG_BINARY).parent_path();
  const struct {
    fs::path input;
    const char* module;
    const char* library;
  } cases[] = {{in.vtk, "tensorglyph-vtk.so", "VTK"},
               {in.nrrd, "tensorglyph-teem.so", "Teem"},
               {in.nifti, "tensorglyph-nifti.so", "libnifti"}};
  for (const auto& c : cases)
    fs::copy_file(built / c.module, lone.parent_path() / c.module, fs::copy_options::overwrite_existing);
  for (const auto& missing : cases) {
    fs::remove(lone.parent_path() / missing.module);
    for (const auto& c : cases) {
      const fs::path out = d / "a.png";
      const std::string args = "render " + c.input.string() + " -o " + out.string() + " --size 64 48";
      if (&c == &missing) {
        tg::test::expectFailsCleanly(args,
                                     std::string("needs ") + c.library + ", through the module " +
                                         (lone.parent_path() / c.module).string() + ", which is missing",
                                     out, d, 1, lone.string());
      } else {
        const auto r = runBinary(args, d, lone.string());
        EXPECT_EQ(r.code, 0) << args << " without " << missing.module << " -> " << r.err;
      }
    }
    // `help formats` finds it before any file does: the missing module's
    // rows say so, the others load.
    const auto help = runBinary("help formats", d, lone.string());
    EXPECT_EQ(help.code, 0) << help.err;
    const std::string name = std::string(missing.module).substr(12, std::string(missing.module).find('.') - 12);
    EXPECT_NE(help.out.find("module " + name + " NOT AVAILABLE: " + (lone.parent_path() / missing.module).string() +
                            " is missing"),
              std::string::npos)
        << help.out;
    for (const auto& c : cases)
      if (&c != &missing) {
        const std::string other = std::string(c.module).substr(12, std::string(c.module).find('.') - 12);
        EXPECT_NE(help.out.find("module " + other + " (loads)"), std::string::npos) << other << "\n" << help.out;
      }
    fs::copy_file(built / missing.module, lone.parent_path() / missing.module, fs::copy_options::overwrite_existing);
  }
}
