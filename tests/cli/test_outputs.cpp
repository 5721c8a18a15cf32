// Outputs you can trust: integer options never wrap, a frame too large is
// refused up front, no output is written over an input or its data, and a
// full disk or a signal leaves neither a partial output nor a temporary file.
// The disk-full cases run for real on a small tmpfs (root; CI sets
// TG_REQUIRE_TMPFS=1 so that they cannot skip there).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using tg::test::CmdResult;

std::string bytesOf(const fs::path& p) { return tg::test::slurp(p); }

std::set<std::string> namesIn(const fs::path& dir) {
  std::set<std::string> s;
  for (const auto& e : fs::directory_iterator(dir)) s.insert(e.path().filename().string());
  return s;
}

long lines(const std::string& s) { return long(std::count(s.begin(), s.end(), '\n')); }

// A fresh directory for one test, removed afterwards; stdout/stderr go to a
// sibling directory so that the test directory holds outputs only.
struct Scratch {
  fs::path dir, logs;
  explicit Scratch(const std::string& name)
      : dir(tg::test::cliDir("out_" + name) / "d"), logs(tg::test::cliDir("out_" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(logs); }
  CmdResult run(const std::string& args) const { return tg::test::runBinary(args, logs); }
};

// A 64 KiB tmpfs mounted for one test: a disk that really fills.
struct SmallDisk {
  fs::path dir;
  bool mounted = false;
  explicit SmallDisk(const fs::path& d) : dir(d) {
    fs::create_directories(dir);
    mounted = geteuid() == 0 && mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") == 0;
  }
  ~SmallDisk() {
    if (mounted) umount(dir.c_str());
  }
};

#define REQUIRE_SMALL_DISK(disk)                                                          \
  do {                                                                                    \
    if (!(disk).mounted) {                                                                \
      if (std::getenv("TG_REQUIRE_TMPFS")) FAIL() << "cannot mount a tmpfs (needs root)"; \
      GTEST_SKIP() << "needs root to mount a small tmpfs";                                \
    }                                                                                     \
  } while (0)

// A detached NRRD header "name" over raw float data in `dataSpec` (a single
// name, "LIST" followed by names, or a %d format line), 6 x 2 x 2 x 2.
void writeDetachedNrrd(const fs::path& header, const std::string& dataSpec, const std::vector<std::string>& files) {
  std::ofstream h(header);
  h << "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 2 2\nkinds: 3D-symmetric-matrix space space space\n"
       "endian: little\nencoding: raw\ndata file: "
    << dataSpec << "\n";
  for (const auto& f : files) {
    std::vector<float> v(48 / files.size(), 0.5f);
    std::ofstream(header.parent_path() / f, std::ios::binary)
        .write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(float)));
  }
}

}  // namespace

// Each integer option once past 2^32: refused with the flag and its range,
// exit 2, one line, nothing written (today's int casts made 4294967297 a 1).
TEST(Outputs, IntegerOptionsNeverWrap) {
  const Scratch s("ints");
  const std::string out = (s.dir / "x.png").string(), csv = (s.dir / "x.csv").string();
  const std::pair<std::string, std::string> cases[] = {
      {"render -o " + out + " --size 4294967297 4294967297", "--size"},
      {"render -o " + out + " --size 64 4294967297", "--size"},
      {"render -o " + out + " --iterations 4294967297", "--iterations"},
      {"render -o " + out + " --repeat 4294967297", "--repeat"},
      {"render -o " + out + " --glyph superquadric --tessellate 4294967304", "--tessellate"},
      {"render -o " + out + " --stride 4294967297", "--stride"},
      {"render -o " + out + " --size 99999999999999999999 64", "--size"},
      {"synth random --n 18446744073709551617 -o " + (s.dir / "r.vtk").string(), "--n"},
      {"synth random --seed -1 -o " + (s.dir / "r.vtk").string(), "--seed"},
      {"bench accuracy -o " + csv + " --size 4294967312 64", "--size"},
      {"bench accuracy -o " + csv + " --frames 4294967297", "--frames"},
      {"bench accuracy -o " + csv + " --iterations 1,4294967297", "--iterations"},
      {"bench scale -o " + csv + " --frames 4294967297", "--frames"},
      {"bench scale -o " + csv + " --size 16 4294967312", "--size"},
      {"bench scale -o " + csv + " --resolutions 8,4294967304", "--resolutions"},
      {"view --size 4294967297 100", "--size"},
  };
  for (const auto& [args, flag] : cases) {
    const CmdResult r = s.run(args);
    EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << " -> " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << " -> " << r.err;
    EXPECT_TRUE(namesIn(s.dir).empty()) << args;
  }
  for (const char* args : {"--size 4294967297 100", "--frames 4294967297", "--resolutions 4294967304"}) {
    const CmdResult r = tg::test::runBinary("-o " + csv + " " + args, s.logs, TG_GPUBENCH);
    EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
  }
  std::ofstream(s.logs / "script.txt") << "frames 4294967297\n";
  const CmdResult r = s.run("view --script " + (s.logs / "script.txt").string());
  // Held to its declared range in the words every surface uses, not wrapped to 1.
  EXPECT_NE(r.err.find("script.txt:1: frames must be within 1..100000"), std::string::npos) << r.err;
}

// 16384 x 16384 passes the per-side limit but needs ~20 GiB of frame
// buffers: refused in well under a second, before the (missing) input is even
// looked at, naming the size and the budget.
TEST(Outputs, FrameBeyondTheMemoryBudgetIsRefusedUpFront) {
  const Scratch s("size");
  const auto t0 = std::chrono::steady_clock::now();
  const CmdResult r = s.run("render " + (s.dir / "missing.nhdr").string() + " -o " + (s.dir / "x.png").string() +
                            " --size 16384 16384");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--size: 16384x16384 needs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("budget"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_LT(seconds, 5.0);
  EXPECT_TRUE(namesIn(s.dir).empty());
  EXPECT_EQ(s.run("render -o " + (s.dir / "x.png").string() + " --size 16385 64").code, 2);
  EXPECT_EQ(s.run("view --size 16384 16384").code, 2);
}

// An input, a mask, a header's data file (single, LIST and %d forms), a hard
// link or a symbolic link to one: each refused as an output before any work,
// exit 2, every input byte unchanged.
TEST(Outputs, NoOutputIsWrittenOverAnInputOrItsData) {
  const Scratch s("inputs");
  const fs::path d = s.dir;
  ASSERT_EQ(s.run("synth random --n 64 -o " + (d / "r.nhdr").string()).code, 0);
  writeDetachedNrrd(d / "one.nhdr", "data.png", {"data.png"});
  writeDetachedNrrd(d / "list.nhdr", "LIST", {"l0.png", "l1.png"});
  {
    std::ofstream h(d / "list.nhdr", std::ios::app);
    h << "l0.png\nl1.png\n";
  }
  writeDetachedNrrd(d / "fmt.nhdr", "f%02d.png 0 1 1", {"f00.png", "f01.png"});
  fs::create_hard_link(d / "data.png", d / "hard.png");
  fs::create_symlink(d / "data.png", d / "soft.png");
  fs::create_directories(d / "sub");
  const auto before = [&] {
    std::vector<std::string> all;
    for (const auto& n : namesIn(d))
      if (fs::is_regular_file(d / n)) all.push_back(n + "=" + bytesOf(d / n));
    return all;
  }();
  const std::string D = d.string() + "/";
  const std::pair<std::string, std::string> cases[] = {
      {"bench accuracy " + D + "r.nhdr -o " + D + "r.nhdr", "is the INPUT file"},
      {"bench accuracy " + D + "r.nhdr -o " + D + "x.csv --plot " + D + "r.nhdr", "--plot"},
      {"render " + D + "one.nhdr -o " + D + "data.png", "is the data file"},
      {"render " + D + "one.nhdr -o " + D + "sub/../data.png", "is the data file"},
      {"render " + D + "one.nhdr -o " + D + "hard.png", "is the data file"},
      {"render " + D + "one.nhdr -o " + D + "soft.png", "is the data file"},
      {"render " + D + "list.nhdr -o " + D + "l1.png", "is the data file"},
      {"render " + D + "fmt.nhdr -o " + D + "f01.png", "is the data file"},
      {"render " + D + "r.nhdr --mask " + D + "one.nhdr -o " + D + "data.png", "of --mask"},
      {"bench accuracy " + D + "one.nhdr -o " + D + "x.csv --plot " + D + "data.png", "is the data file"},
  };
  for (const auto& [args, what] : cases) {
    const CmdResult r = s.run(args);
    EXPECT_EQ(r.code, 2) << args << " -> " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << args << " -> " << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << " -> " << r.err;
  }
  std::vector<std::string> after;
  for (const auto& n : namesIn(d))
    if (fs::is_regular_file(d / n)) after.push_back(n + "=" + bytesOf(d / n));
  EXPECT_EQ(before, after) << "an input changed, or an output appeared";
}

// An output that is a FIFO or a device is refused (exit 2, one line): the
// file written beside it was renamed over it, so a FIFO became a file and
// whoever read the pipe waited for ever.
TEST(Outputs, FifosAndDevicesAreRefusedAndKept) {
  const Scratch s("special");
  const fs::path fifo = s.dir / "pipe.png", link = s.dir / "null.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  fs::create_symlink("/dev/null", link);
  for (const auto& [out, what] : {std::pair{fifo, "is a FIFO"}, std::pair{link, "is a device"}}) {
    const CmdResult r = s.run("render --size 64 48 -o " + out.string());
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(namesIn(s.dir), (std::set<std::string>{"pipe.png", "null.png"}));
}

// A full disk: every output format fails with exit 1 and one line naming the
// file, and leaves no output and no temporary file. The tmpfs is filled to
// within one page first, so that even small outputs meet the end.
TEST(Outputs, DiskFullFailsCleanlyForEveryFormat) {
  const Scratch s("full");
  SmallDisk disk(s.dir / "disk");
  REQUIRE_SMALL_DISK(disk);
  {
    std::ofstream filler(disk.dir / "filler", std::ios::binary);
    const std::string page(4096, 'x');
    for (int k = 0; k < 15; ++k) filler << page;
  }
  const std::string D = disk.dir.string() + "/";
  const std::string cases[] = {
      "render -o " + D + "a.png --size 320 240",
      "render -o " + D + "a.jpg --size 320 240",
      "render -o " + D + "a.gif --size 320 240",
      "render -o " + D + "a.exr --size 160 120",
      "render -o " + D + "a.tif --size 160 120",
      "synth helix --n 16 -o " + D + "h.vtk",
      "synth helix --n 16 -o " + D + "h.vti",
      "synth random --n 2000 -o " + D + "r.vtu",
      "synth random --n 2000 -o " + D + "r.vtp",
      "synth helix --n 64 -o " + D + "h.nrrd",
      "synth random --n 5000 -o " + D + "r.nhdr",
      // The CSV fits, the plot does not: neither may stay (its summary line comes first).
      "bench accuracy -o " + D + "a.csv --size 64 48 --iterations 1 --epsilon 1e-2 --frames 1",
  };
  for (const std::string& args : cases) {
    const CmdResult r = s.run(args);
    const bool bench = args.starts_with("bench");
    const std::string out = args.substr(args.find(D));
    const std::string file = bench ? D + "a.png" : out.substr(0, out.find(' '));
    EXPECT_EQ(r.code, 1) << args << " -> " << r.err;
    EXPECT_EQ(lines(r.err), bench ? 2 : 1) << args << " -> " << r.err;
    const std::string last = r.err.substr(r.err.rfind('\n', r.err.size() - 2) + 1);
    EXPECT_NE(last.find(file), std::string::npos) << args << " -> " << r.err;
    EXPECT_EQ(namesIn(disk.dir), std::set<std::string>{"filler"}) << args;
  }
}

// A pair whose header cannot be written: the data fits in the last free page,
// the header does not. The old header and the old data stay exactly as they
// were, and the new data is removed.
TEST(Outputs, FailedHeaderLeavesTheOldPairIntact) {
  const Scratch s("pair");
  SmallDisk disk(s.dir / "disk");
  REQUIRE_SMALL_DISK(disk);
  const fs::path hdr = disk.dir / "p.nhdr";
  ASSERT_EQ(s.run("synth random --n 100 --seed 1 -o " + hdr.string()).code, 0);
  const auto oldNames = namesIn(disk.dir);
  ASSERT_EQ(oldNames.size(), 2u);
  std::map<std::string, std::string> old;
  for (const auto& n : oldNames) old[n] = bytesOf(disk.dir / n);
  {
    // 16 pages: two hold the old pair, one is left for the new data.
    std::ofstream filler(disk.dir / "filler", std::ios::binary);
    filler << std::string(13 * 4096, 'x');
  }
  const CmdResult r = s.run("synth random --n 100 --seed 2 -o " + hdr.string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(hdr.string()), std::string::npos) << r.err;
  fs::remove(disk.dir / "filler");
  EXPECT_EQ(namesIn(disk.dir), oldNames);
  for (const auto& [n, bytes] : old) EXPECT_EQ(bytesOf(disk.dir / n), bytes) << n;
}

namespace {

// The header's one data file and its size, read back by the real reader.
void expectConsistentPair(const Scratch& s, const fs::path& hdr) {
  std::ifstream in(hdr);
  std::string line, data, sizes;
  while (std::getline(in, line)) {
    if (line.rfind("data file: ", 0) == 0) data = line.substr(11);
    if (line.rfind("sizes: ", 0) == 0) sizes = line.substr(7);
  }
  ASSERT_FALSE(data.empty());
  std::istringstream ss(sizes);
  std::size_t n = 1;
  for (std::size_t v; ss >> v;) n *= v;
  EXPECT_EQ(fs::file_size(hdr.parent_path() / data), n * sizeof(float)) << data;
  const CmdResult r = s.run("info " + hdr.string());
  EXPECT_EQ(r.code, 0) << r.err;
  std::size_t raws = 0;
  for (const auto& name : namesIn(hdr.parent_path())) raws += name.ends_with(".raw");
  EXPECT_EQ(raws, 1u) << "a displaced header's data was left behind";
}

}  // namespace

// Two writers of different sizes on the same .nhdr at once, several times:
// the header in place always names its own, complete data, and the data of
// every displaced header is gone.
TEST(Outputs, ConcurrentPairWritersNeverMixHeaderAndData) {
  const Scratch s("race");
  const fs::path hdr = s.dir / "c.nhdr";
  for (int round = 0; round < 4; ++round) {
    const fs::path logsA = s.logs / "a";
    fs::create_directories(logsA);
    std::thread a([&] { tg::test::runBinary("synth random --n 20000 --seed 1 -o " + hdr.string(), logsA); });
    const CmdResult b = tg::test::runBinary("synth random --n 30000 --seed 2 -o " + hdr.string(), s.logs);
    a.join();
    ASSERT_EQ(b.code, 0) << b.err;
    expectConsistentPair(s, hdr);
  }
}

namespace {

pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(TG_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    // A test runner may have left SIGINT ignored; the writer must see it.
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    execv(TG_BINARY, argv.data());
    _exit(127);
  }
  return pid;
}

}  // namespace

// SIGTERM and SIGINT while the data of a large pair is being written: the
// process dies of the signal, its temporary files are gone, and the pair that
// was there before is untouched.
TEST(Outputs, SignalMidWriteLeavesNoTemporaryFile) {
  const Scratch s("signal");
  const fs::path hdr = s.dir / "big.nhdr";
  ASSERT_EQ(s.run("synth random --n 100 -o " + hdr.string()).code, 0);
  std::map<std::string, std::string> old;
  for (const auto& n : namesIn(s.dir)) old[n] = bytesOf(s.dir / n);
  for (int sig : {SIGTERM, SIGINT}) {
    const pid_t pid = spawn({"synth", "random", "--n", "30000000", "-o", hdr.string()});
    ASSERT_GT(pid, 0);
    // Wait until the new data file is being written.
    bool writing = false;
    for (int k = 0; k < 2000 && !writing; ++k) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      for (const auto& e : fs::directory_iterator(s.dir))
        writing = writing || (!old.count(e.path().filename().string()) && fs::file_size(e.path()) > 0);
    }
    EXPECT_TRUE(writing) << "the writer never started";
    kill(pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "status " << status;
    std::set<std::string> oldNames;
    for (const auto& [n, bytes] : old) oldNames.insert(n);
    EXPECT_EQ(namesIn(s.dir), oldNames) << "signal " << sig;
    for (const auto& [n, bytes] : old) EXPECT_EQ(bytesOf(s.dir / n), bytes) << n;
  }
}
