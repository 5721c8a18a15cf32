// Tier 2: the guarded read (a child process, the field back through a socket,
// its arrays copied out of the child's memory) gives exactly what the same
// read gives in process, for every format and for small fields, which an
// earlier spliced-pipe version let the child overwrite before the parent
// read them.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>

#include "data-synthetic/generators.h"
#include "io/core/guard_wire.h"
#include "io/io_test_util.h"
#include "io/mif_fixture.h"
#include "io/core/raw_samples.h"
#include "io/core/readers.h"
#include "io/core/writers.h"

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

// ---- Raw data read by the parent (io/core/raw_samples.h) ------------------------

namespace {

// Voxel v's value k is (v + 1) * 10 + k, in the header's type and byte order.
template <class T>
std::string rawValues(int voxels, int count, bool bigEndian) {
  std::string s;
  for (int v = 0; v < voxels; ++v)
    for (int k = 0; k < count; ++k) {
      const T x = T((v + 1) * 10 + k);
      std::string b(reinterpret_cast<const char*>(&x), sizeof x);
      if (bigEndian) std::reverse(b.begin(), b.end());
      s += b;
    }
  return s;
}

}  // namespace

// The child hands back where the data lies; the parent reads it. Every type,
// both byte orders, detached data in another directory, a byte skip, a
// measurement frame, a selection and a non-finite tensor give what the same
// read gives in one process.
TEST(ReadGuard, RawDataReadByTheParentIsTheInProcessField) {
  const fs::path d = test::scratchDir("read_guard_raw");
  fs::create_directories(d / "data");
  struct Case {
    const char* name;
    const char* type;
    std::string bytes;
    bool big;
  } cases[] = {{"uchar", "uchar", rawValues<std::uint8_t>(24, 6, false), false},
               {"short-be", "short", rawValues<std::int16_t>(24, 6, true), true},
               {"uint64", "uint64", rawValues<std::uint64_t>(24, 6, false), false},
               {"double-be", "double", rawValues<double>(24, 6, true), true}};
  for (const Case& c : cases) {
    const std::string hdr = std::string("NRRD0004\ntype: ") + c.type +
                            "\ndimension: 4\nsizes: 6 4 3 2\nkinds: 3D-symmetric-matrix space space space\n"
                            "space: left-posterior-superior\nspace directions: none (0,2,0) (1,0,0) (0,0,3)\n"
                            "measurement frame: (0,1,0) (-1,0,0) (0,0,1)\nencoding: raw\nendian: " +
                            (c.big ? "big" : "little") + "\nbyte skip: 5\ndata file: data/" + c.name + ".raw\n";
    test::writeFile(d / (std::string(c.name) + ".nhdr"), hdr);
    test::writeFile(d / "data" / (std::string(c.name) + ".raw"), "SKIP!" + c.bytes);
    const fs::path p = d / (std::string(c.name) + ".nhdr");
    // The same values as text, which Teem decodes in the child: the raw
    // read's values are right, not only the same in both processes.
    std::string text;
    for (int v = 0; v < 24; ++v)
      for (int k = 0; k < 6; ++k) text += std::to_string((v + 1) * 10 + k) + " ";
    std::string ascii = hdr.substr(0, hdr.find("encoding:")) + "encoding: ascii\n\n" + text + "\n";
    test::writeFile(d / (std::string(c.name) + ".ascii.nrrd"), ascii);
    const io::TensorField fromText = io::readTensorField((d / (std::string(c.name) + ".ascii.nrrd")).string(), {});
    const io::TensorField fromRaw = io::readTensorField(p.string(), {});
    EXPECT_EQ(fromRaw.tensors, fromText.tensors) << c.name;
    EXPECT_EQ(fromRaw.positions, fromText.positions) << c.name;
    for (const long long stride : {1LL, 2LL}) {
      io::ReadOptions o;
      o.selection.stride = stride;
      const io::TensorField guarded = io::readTensorField(p.string(), o);
      const io::TensorField direct = io::readTensorFieldInProcess(p.string(), o);
      ASSERT_EQ(direct.size(), stride == 1 ? 24u : 4u) << c.name;
      expectSame(guarded, direct, std::string(c.name) + " stride " + std::to_string(stride));
    }
  }
  // A NaN among float values: skipped and counted on the parent's side too.
  std::string values = rawValues<float>(6, 6, false);
  const float nan = std::nanf("");
  std::memcpy(&values[4 * (6 * 2 + 3)], &nan, 4);
  test::writeFile(d / "nan.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 3 2 1\n"
                                  "kinds: 3D-symmetric-matrix domain domain domain\nencoding: raw\nendian: little\n\n" +
                                      values);
  const io::TensorField guarded = io::readTensorField((d / "nan.nrrd").string(), {});
  EXPECT_EQ(guarded.size(), 5u);
  EXPECT_EQ(guarded.skippedNonFinite, 1u);
  EXPECT_FLOAT_EQ(guarded.tensors[6 * 2], 40.0f);  // voxel 3's xx: voxel 2 was skipped
  expectSame(guarded, io::readTensorFieldInProcess((d / "nan.nrrd").string(), {}), "nan");
}

namespace {

ino_t inodeOf(int fd) {
  struct stat st {};
  return ::fstat(fd, &st) == 0 ? st.st_ino : 0;
}

}  // namespace

// Where a reader is asked to defer, it returns the field without samples and
// the data file it checked, open: raw data only, and never with a mask (read
// in the child).
TEST(ReadGuard, OnlyUncompressedUnmaskedDataIsDeferred) {
  const fs::path d = test::scratchDir("read_guard_raw");
  const std::string hdr = "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 2 1\n"
                          "kinds: 3D-symmetric-matrix domain domain domain\nendian: little\n";
  test::writeFile(d / "defer.nrrd", hdr + "encoding: raw\n\n" + rawValues<float>(4, 6, false));
  std::optional<io::RawSamples> raw;
  io::ReadOptions o;
  o.deferRaw = &raw;
  const io::TensorField f = io::readTensorFieldInProcess((d / "defer.nrrd").string(), o);
  EXPECT_EQ(f.size(), 0u);
  ASSERT_TRUE(raw);
  ASSERT_TRUE(raw->dataFd);
  struct stat named {};
  ASSERT_EQ(::stat((d / "defer.nrrd").c_str(), &named), 0);
  EXPECT_EQ(inodeOf(raw->dataFd.get()), named.st_ino);
  EXPECT_EQ(raw->offset, fs::file_size(d / "defer.nrrd") - 4 * 24);
  EXPECT_EQ(raw->type, io::RawType::F32);
  EXPECT_EQ(raw->geometry.dims[0], 2);
  EXPECT_EQ(raw->layout.count, 6);

  raw.reset();
  o.selection.maskPath = (d / "mask.nrrd").string();
  test::writeFile(d / "mask.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 1\nencoding: raw\n\n" +
                                       std::string("\1\0\1\1", 4));
  const io::TensorField masked = io::readTensorFieldInProcess((d / "defer.nrrd").string(), o);
  EXPECT_FALSE(raw);
  EXPECT_EQ(masked.size(), 3u);
  EXPECT_EQ(masked.masked, 1u);
}

namespace {

// A descriptor of 3 voxels of int16 values, its data file open.
io::RawSamples sampleDescriptor(const fs::path& data) {
  io::RawSamples r;
  r.dataFd = util::UniqueFd(::open(data.c_str(), O_RDONLY | O_CLOEXEC));
  r.offset = 17;
  r.type = io::RawType::I16;
  r.swap = true;
  r.geometry.dims[0] = 3;
  r.geometry.tensorToWC = std::array<double, 9>{0, 1, 0, -1, 0, 0, 0, 0, 1};
  r.layout.count = 7;
  r.layout.confidence = 0;
  r.layout.sym = {1, 2, 3, 4, 5, 6};
  r.intercept = 0.5;
  r.slope = 2;
  return r;
}

// Sends what `write` puts on a wire and takes a descriptor back off it.
template <class Write>
std::optional<io::RawSamples> overTheWire(Write&& write) {
  int fds[2];
  EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0);
  const util::UniqueFd a(fds[0]), b(fds[1]);
  io::WireOut out(a.get());
  write(out);
  out.finish();
  io::WireIn in(b.get(), ::getpid(), io::WireIn::Clock::now() + std::chrono::seconds(5), 1 << 20);
  return io::receiveRaw(in);
}

}  // namespace

// The descriptor the child sends is checked before the parent sizes anything
// from it; a well-formed one crosses unchanged, its file passed open, so the
// parent reads the file the child checked even after its name is reused.
TEST(ReadGuard, TheRawDescriptorIsCheckedOnArrival) {
  const fs::path d = test::scratchDir("read_guard_wire");
  test::writeFile(d / "a.raw", "the file the child checked");
  const std::optional<io::RawSamples> good = sampleDescriptor(d / "a.raw");
  const ino_t checked = inodeOf(good->dataFd.get());
  // Replaced by rename, as editors and writers save: the name leads elsewhere.
  test::writeFile(d / "b.raw", "another file");
  fs::rename(d / "b.raw", d / "a.raw");
  const auto back = overTheWire([&](io::WireOut& w) { io::sendRaw(w, good); });
  ASSERT_TRUE(back);
  ASSERT_TRUE(back->dataFd);
  EXPECT_EQ(inodeOf(back->dataFd.get()), checked);
  EXPECT_NE(back->dataFd.get(), good->dataFd.get());
  EXPECT_EQ(back->offset, 17u);
  EXPECT_EQ(back->type, io::RawType::I16);
  EXPECT_TRUE(back->swap);
  EXPECT_EQ(back->geometry.dims[0], 3);
  EXPECT_EQ(back->geometry.tensorToWC, good->geometry.tensorToWC);
  EXPECT_EQ(back->layout.sym, good->layout.sym);
  EXPECT_EQ(back->slope, 2.0);
  EXPECT_FALSE(overTheWire([](io::WireOut& w) { io::sendRaw(w, std::nullopt); }));

  const auto mutate = [&](auto&& change) {
    std::optional<io::RawSamples> r = sampleDescriptor(d / "a.raw");
    change(*r);
    return overTheWire([&](io::WireOut& w) { io::sendRaw(w, r); });
  };
  EXPECT_THROW(mutate([](io::RawSamples& r) { r.type = io::RawType(42); }), std::runtime_error);
  EXPECT_THROW(mutate([](io::RawSamples& r) { r.geometry.dims[1] = 0; }), std::runtime_error);
  EXPECT_THROW(mutate([](io::RawSamples& r) { r.layout.count = 0; }), std::runtime_error);
  EXPECT_THROW(mutate([](io::RawSamples& r) { r.layout.sym[5] = 7; }), std::runtime_error);
  EXPECT_THROW(mutate([](io::RawSamples& r) { r.slope = std::nan(""); }), std::runtime_error);
  EXPECT_THROW(mutate([](io::RawSamples& r) { r.geometry.dims[0] = r.geometry.dims[1] = r.geometry.dims[2] = 1 << 20; }),
               std::runtime_error);
  // A description without its file: refused, not read from some name.
  EXPECT_THROW(overTheWire([](io::WireOut& w) {
                 w.pod(std::uint8_t(1));
                 w.pod(std::uint64_t(0));
               }),
               std::runtime_error);
}

// The parent checks the file it was handed again: one cut short is refused,
// named; a FIFO is no data file.
TEST(ReadGuard, TheParentRefusesADataFileThatIsNotWhatTheHeaderSaid) {
  const fs::path d = test::scratchDir("read_guard_raw");
  io::RawSamples raw;
  raw.geometry.dims[0] = 4;
  test::writeFile(d / "short.raw", rawValues<float>(3, 6, false));
  io::TensorField f;
  try {
    const util::UniqueFd in(::open((d / "short.raw").c_str(), O_RDONLY | O_CLOEXEC));
    io::readRawSamples("readNrrd", "h.nhdr", raw, {}, f, in.get());
    ADD_FAILURE() << "a short data file was read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "readNrrd: h.nhdr: data is truncated: the header describes 96 bytes, the data ends after 72");
  }
  const fs::path fifo = d / "fifo";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    const util::UniqueFd in(::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    io::readRawSamples("readNrrd", "h.nhdr", raw, {}, f, in.get());
    ADD_FAILURE() << "a FIFO was read";
  } catch (const io::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "readNrrd: h.nhdr: the data file is not a regular file");
  }
  EXPECT_EQ(f.size(), 0u);
}

// MRtrix images stored voxel by voxel take the same path: scaling, byte
// order and a detached .mih data file arrive as the in-process read has them.
TEST(ReadGuard, MrtrixRawDataReadByTheParentIsTheInProcessField) {
  const fs::path d = test::scratchDir("read_guard_mif");
  for (const char* type : {"Int16BE", "Float64LE", "UInt8"}) {
    test::MifFixture fx;
    fx.datatype = type;
    fx.scaling = "0.5,0.25";
    fx.fillDistinct(std::string(type) == "Int16BE");
    const fs::path mif = d / (std::string(type) + ".mif"), mih = d / (std::string(type) + ".mih");
    test::writeMif(mif, fx);
    test::writeMih(mih, fx, std::string(type) + ".dat", 100);
    for (const fs::path& p : {mif, mih}) {
      std::optional<io::RawSamples> raw;
      io::ReadOptions o;
      o.deferRaw = &raw;
      io::readTensorFieldInProcess(p.string(), o);
      ASSERT_TRUE(raw) << p;  // the parent reads it
      EXPECT_EQ(raw->slope, 0.25) << p;
      const io::TensorField guarded = io::readTensorField(p.string(), {});
      ASSERT_EQ(guarded.size(), fx.voxels()) << p;
      // xx of voxel 1, stored as mrtrix[1][0]: 0.5 + 0.25 * stored.
      EXPECT_FLOAT_EQ(guarded.tensors[6], float(0.5 + 0.25 * fx.mrtrix[1][0])) << p;
      expectSame(guarded, io::readTensorFieldInProcess(p.string(), {}), p.string());
    }
  }
}
