// AtomicFile (io/field/atomic_file.h) and the input-file list (io/core/input_files.h).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "io/field/atomic_file.h"
#include "io/core/input_files.h"
#include "io/field/tensor_field.h"

namespace fs = std::filesystem;
using tg::io::AtomicFile;

namespace {

fs::path freshDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("tg_atomic_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::set<std::string> namesIn(const fs::path& dir) {
  std::set<std::string> s;
  for (const auto& e : fs::directory_iterator(dir)) s.insert(e.path().filename().string());
  return s;
}

}  // namespace

TEST(AtomicFile, CommitReplacesTheTargetWithNormalPermissions) {
  const fs::path d = freshDir("commit");
  const mode_t old = umask(022);
  {
    AtomicFile f((d / "out.csv").string());
    EXPECT_EQ(fs::path(f.tempPath()).parent_path(), d);
    EXPECT_EQ(fs::path(f.tempPath()).extension(), ".csv");
    f.write("abc", 3);
    EXPECT_FALSE(fs::exists(d / "out.csv"));
    f.commit(3);
  }
  umask(old);
  EXPECT_EQ(slurp(d / "out.csv"), "abc");
  struct stat st {};
  ASSERT_EQ(stat((d / "out.csv").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u) << "0666 less the umask, not mkstemp's 0600";
  EXPECT_EQ(namesIn(d), std::set<std::string>{"out.csv"});
  fs::remove_all(d);
}

// A target named to the file system's limit (255 bytes) is written: its
// temporary name, 18 bytes longer, was refused ("File name too long"). A
// unique name is cut to the limit too, between UTF-8 characters.
TEST(AtomicFile, NamesUpToTheLimitAreWritten) {
  const fs::path d = freshDir("long");
  const std::string stem(251, 'n');
  {
    AtomicFile f((d / (stem + ".png")).string());
    EXPECT_EQ(fs::path(f.tempPath()).extension(), ".png");
    f.write("abc", 3);
    f.commit(3);
  }
  EXPECT_EQ(namesIn(d), std::set<std::string>{stem + ".png"});
  std::string wide;
  while (wide.size() < 250) wide += "\xc3\xa4";  // a 2-byte character, 125 times
  std::string kept;
  {
    AtomicFile f(AtomicFile::UniqueName{}, d.string(), wide, ".raw");
    f.write("abc", 3);
    f.keep();
    kept = fs::path(f.tempPath()).filename().string();
  }
  EXPECT_LE(kept.size(), 255u);
  EXPECT_EQ(fs::path(kept).extension(), ".raw");
  EXPECT_EQ(kept.compare(0, 200, wide, 0, 200), 0);
  const std::size_t random = kept.size() - 4 - 12;  // where the random part begins
  EXPECT_EQ(random % 2, 0u) << "cut inside a character";
  EXPECT_EQ(slurp(d / kept), "abc");
  fs::remove_all(d);
}

TEST(AtomicFile, AbandonedOrShortFilesLeaveNothing) {
  const fs::path d = freshDir("abandon");
  std::ofstream(d / "keep.txt") << "old";
  {
    AtomicFile f((d / "keep.txt").string());
    f.write("new", 3);
  }  // no commit: removed, the old file intact
  EXPECT_EQ(slurp(d / "keep.txt"), "old");
  {
    AtomicFile f((d / "keep.txt").string());
    f.write("new", 3);
    EXPECT_THROW(f.commit(4), std::runtime_error);  // a short file is never committed
  }
  EXPECT_EQ(slurp(d / "keep.txt"), "old");
  EXPECT_EQ(namesIn(d), std::set<std::string>{"keep.txt"});
  fs::remove_all(d);
}

// The old scheme's names were ".STEM.tmpPID-N.EXT": links planted at every one
// of them (and the new names are random) never lead a write elsewhere, and a
// target that is itself a link is replaced, not written through.
TEST(AtomicFile, PlantedLinksAreNeverFollowed) {
  const fs::path d = freshDir("links");
  const fs::path victim = d / "victim.txt";
  std::ofstream(victim) << "precious";
  for (int k = 0; k < 50; ++k)
    fs::create_symlink(victim, d / (".out.tmp" + std::to_string(getpid()) + "-" + std::to_string(k) + ".png"));
  fs::create_symlink(victim, d / "out.png");
  std::set<std::string> temps;
  for (int k = 0; k < 20; ++k) {
    AtomicFile f((d / "out.png").string());
    temps.insert(f.tempPath());
    EXPECT_FALSE(fs::is_symlink(f.tempPath()));
    f.write("image", 5);
    f.commit();
  }
  EXPECT_EQ(temps.size(), 20u) << "temporary names must not repeat";
  EXPECT_EQ(slurp(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(d / "out.png"));
  EXPECT_EQ(slurp(d / "out.png"), "image");
  fs::remove_all(d);
}

TEST(AtomicFile, ExchangeReportsTheDisplacedFile) {
  const fs::path d = freshDir("exchange");
  std::string seen;
  {
    AtomicFile first((d / "h.txt").string());
    first.write("one", 3);
    first.commitExchange(3, [&](const std::string&) { seen = "called without a target"; });
  }
  EXPECT_EQ(seen, "");
  {
    AtomicFile second((d / "h.txt").string());
    second.write("two", 3);
    second.commitExchange(3, [&](const std::string& displaced) { seen = slurp(displaced); });
  }
  EXPECT_EQ(seen, "one");
  EXPECT_EQ(slurp(d / "h.txt"), "two");
  EXPECT_EQ(namesIn(d), std::set<std::string>{"h.txt"});
  fs::remove_all(d);
}

TEST(AtomicFile, UniqueNamesAreKept) {
  const fs::path d = freshDir("unique");
  std::string path;
  {
    AtomicFile f(AtomicFile::UniqueName{}, d.string(), "p", ".raw");
    path = f.target();
    EXPECT_EQ(f.tempPath(), path);
    f.write("data", 4);
    f.keep();
  }
  EXPECT_EQ(slurp(path), "data");
  EXPECT_EQ(fs::path(path).filename().string().size(), std::string("p.123456789012.raw").size());
  fs::remove_all(d);
}

// Every data file form a NRRD header can give, relative to the header.
TEST(InputFiles, NrrdDataFilesInEveryForm) {
  const fs::path d = freshDir("inputs");
  const std::string head = "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 2 2 4\nencoding: raw\nendian: little\n";
  std::ofstream(d / "one.nhdr") << head << "data file: sub/one.raw\n";
  std::ofstream(d / "abs.nhdr") << head << "data file: /elsewhere/a.raw\n";
  std::ofstream(d / "list.nhdr") << head << "data file: LIST\na.raw\nb.raw\nc.raw\nd.raw\n";
  std::ofstream(d / "fmt.nhdr") << head << "data file: s%03d.raw 1 7 2\n";
  std::ofstream(d / "kv.nhdr") << head << "data file:=not a field\n# data file: nor this\n\n";
  std::ofstream(d / "bad.nhdr") << head << "data file: x%d%s.raw 0 3 1\n";
  const std::string D = d.string() + "/";
  using V = std::vector<std::string>;
  EXPECT_EQ(tg::io::nrrdDataFiles(D + "one.nhdr"), V{D + "sub/one.raw"});
  EXPECT_EQ(tg::io::nrrdDataFiles(D + "abs.nhdr"), V{"/elsewhere/a.raw"});
  EXPECT_EQ(tg::io::nrrdDataFiles(D + "list.nhdr"), (V{D + "a.raw", D + "b.raw", D + "c.raw", D + "d.raw"}));
  EXPECT_EQ(tg::io::nrrdDataFiles(D + "fmt.nhdr"), (V{D + "s001.raw", D + "s003.raw", D + "s005.raw", D + "s007.raw"}));
  EXPECT_EQ(tg::io::nrrdDataFiles(D + "kv.nhdr"), V{});
  EXPECT_THROW(tg::io::nrrdDataFiles(D + "bad.nhdr"), tg::io::InputError);
  EXPECT_EQ(tg::io::filesReadBy(D + "one.nhdr"), (V{D + "one.nhdr", D + "sub/one.raw"}));
  // A FIFO where the header names its data must not block the listing.
  ASSERT_EQ(mkfifo((d / "fifo.raw").c_str(), 0600), 0);
  std::ofstream(d / "fifo.nhdr") << head << "data file: fifo.raw\n";
  EXPECT_EQ(tg::io::nrrdDataFiles(D + "fifo.nhdr"), V{D + "fifo.raw"});
  fs::remove_all(d);
}

TEST(InputFiles, SameFileSeesLinks) {
  const fs::path d = freshDir("same");
  std::ofstream(d / "a") << "x";
  fs::create_hard_link(d / "a", d / "h");
  fs::create_symlink(d / "a", d / "s");
  fs::create_directories(d / "sub");
  EXPECT_TRUE(tg::io::sameFile((d / "a").string(), (d / "h").string()));
  EXPECT_TRUE(tg::io::sameFile((d / "a").string(), (d / "s").string()));
  EXPECT_TRUE(tg::io::sameFile((d / "missing").string(), (d / "sub/../missing").string()));
  EXPECT_FALSE(tg::io::sameFile((d / "a").string(), (d / "missing").string()));
  std::ofstream(d / "b") << "x";
  EXPECT_FALSE(tg::io::sameFile((d / "a").string(), (d / "b").string()));
  fs::remove_all(d);
}

// A FIFO, a device or a directory at the target would be replaced by the
// rename (as root, /dev/null too): refused when the file is made, and again
// at commit for one made at the target while writing; nothing stays behind.
TEST(AtomicFile, NonRegularTargetsAreRefusedAndKept) {
  const fs::path d = freshDir("fifo");
  const fs::path fifo = d / "out.png";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directories(d / "dir.png");
  for (const auto& [target, said] : {std::pair{fifo, "is a FIFO"}, std::pair{d / "dir.png", "is a directory"}}) {
    try {
      AtomicFile f(target.string());
      ADD_FAILURE() << target << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(said), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(tg::io::unwritableTarget("/dev/null").rfind("is a device", 0), 0u);
  EXPECT_EQ(tg::io::unwritableTarget((d / "missing.png").string()), "");
  const fs::path late = d / "late.png";
  {
    AtomicFile f(late.string());
    f.write("x", 1);
    ASSERT_EQ(mkfifo(late.c_str(), 0600), 0);
    EXPECT_THROW(f.commit(1), std::runtime_error);
  }
  struct stat st {};
  ASSERT_EQ(stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  ASSERT_EQ(stat(late.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(namesIn(d), (std::set<std::string>{"out.png", "dir.png", "late.png"}));
  fs::remove_all(d);
}

// "data file: LIST" with a million names: Teem's parser (quadratic in the
// names) took minutes, in the parent that protects inputs from -o; the
// listing is linear and refuses past 100000 with the count. The bounds are
// a hundred times what the linear listing takes here.
TEST(InputFiles, AListOfAMillionNamesIsRefusedInLinearTime) {
  const fs::path d = freshDir("list");
  const std::string head = "NRRD0004\ntype: float\ndimension: 4\nsizes: 6 4 4 4\nencoding: raw\ndata file: LIST 3\n";
  auto write = [&](const fs::path& p, int names, const char* end) {
    std::ofstream out(p);
    out << head;
    for (int k = 0; k < names; ++k) out << "d" << k << ".raw" << end;
  };
  write(d / "million.nhdr", 1000000, "\n");
  write(d / "limit.nhdr", 100000, "\r\n");
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  try {
    tg::io::nrrdDataFiles((d / "million.nhdr").string());
    ADD_FAILURE() << "a million data files were listed";
  } catch (const tg::io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1000000 data files; at most 100000 are accepted"), std::string::npos)
        << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 20.0);
  t0 = Clock::now();
  const auto listed = tg::io::nrrdDataFiles((d / "limit.nhdr").string());
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 5.0);
  ASSERT_EQ(listed.size(), 100000u);
  EXPECT_EQ(listed.back(), (d / "d99999.raw").string());  // "\r\n" ends a name as Teem ends it
  // Teem's own forms of a LIST: an empty line names nothing, the last line
  // needs no newline, "-" is no file.
  std::ofstream(d / "forms.nhdr") << head << "a.raw\n\n-\nb.raw";
  EXPECT_EQ(tg::io::nrrdDataFiles((d / "forms.nhdr").string()),
            (std::vector<std::string>{(d / "a.raw").string(), (d / "b.raw").string()}));
  fs::remove_all(d);
}
