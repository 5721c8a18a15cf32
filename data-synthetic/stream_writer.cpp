#include <unistd.h>

#include <filesystem>
#include <regex>
#include <stdexcept>
#include <vector>

#include "data-synthetic/generators.h"
#include "data-synthetic/random_tensors.h"
#include "io/field/atomic_file.h"
#include "io/core/format_modules.h"
#include "io/core/input_files.h"

namespace tg::synth {
namespace {

// The pair is committed by its header alone. The data goes to a new file
// under a unique name, "STEM.RANDOM.raw", which only the new header names;
// the header is renamed over the old one last, so that a failure at any step
// leaves the old header and the old data as they were, and two writers at
// once each install a header over their own data. The rename exchanges the
// headers (io::AtomicFile::commitExchange), so each writer learns exactly
// which header it displaced, and removes that header's data file when it is
// one of ours ("STEM.RANDOM.raw" beside it) and the header now in place does
// not name it. Data a user's own header named is never removed.
void removeDisplacedData(const std::string& displaced, const std::filesystem::path& header) noexcept try {
  const std::regex ours(std::regex_replace(header.stem().string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                        R"(\.[A-Za-z0-9]{12}\.raw)");
  const std::vector<std::string> now = io::nrrdDataFiles(header.string());
  const std::string dir = header.has_parent_path() ? header.parent_path().string() : ".";
  for (const std::string& old : io::nrrdDataFiles(displaced)) {
    const std::filesystem::path p(old);
    if (!io::sameFile(p.has_parent_path() ? p.parent_path().string() : ".", dir) ||
        !std::regex_match(p.filename().string(), ours))
      continue;
    bool needed = false;
    for (const std::string& n : now) needed = needed || io::sameFile(n, old);
    if (!needed) unlink(old.c_str());
  }
} catch (const std::exception&) {
  // An unreadable header, displaced or current: keep every data file.
}

}  // namespace

void writeRandomNrrdStreaming(const std::string& nhdrPath, std::size_t n, std::uint64_t seed,
                              const util::ProgressSink& progress) {
  const std::filesystem::path hp(nhdrPath);
  if (hp.extension() != ".nhdr") throw std::runtime_error("writeRandomNrrdStreaming: " + nhdrPath + ": needs .nhdr");
  if (n == 0) throw std::runtime_error("writeRandomNrrdStreaming: " + nhdrPath + ": N must be positive");
  const GridDims dims = gridDims(n);
  // Before the data: a missing module must not cost the data's writing first.
  const io::TeemFormats& teem = io::teemFormats("writeRandomNrrdStreaming", nhdrPath);

  // Data first, in 1M-tensor chunks, each write checked.
  io::AtomicFile raw(io::AtomicFile::UniqueName{}, hp.parent_path().string(), hp.stem().string(), ".raw");
  try {
    RandomTensorStream rs(seed);
    constexpr std::size_t kChunk = 1 << 20;
    std::vector<float> buf(6 * kChunk);
    for (std::size_t done = 0; done < n;) {
      if (progress) progress("writing", double(done), double(n), "tensors");
      const std::size_t m = std::min(kChunk, n - done);
      for (std::size_t i = 0; i < m; ++i) rs.next(&buf[6 * i]);
      raw.write(buf.data(), sizeof(float) * 6 * m);
      done += m;
    }
  } catch (const std::exception& e) {
    throw std::runtime_error("writeRandomNrrdStreaming: " + nhdrPath + ": " + e.what());
  }

  // The header, by Teem, without data: it names the data file.
  io::AtomicFile header(nhdrPath);
  const std::size_t grid[3] = {dims.x, dims.y, dims.z};
  const std::int64_t size =
      teem.writeRawTensorHeader(nhdrPath, header.fd(), grid, std::filesystem::path(raw.target()).filename().string(),
                                "writeRandomNrrdStreaming");
  // From here a failure must remove the data itself: it is no longer
  // registered for removal, so that no signal can take it from under a
  // committed header (at worst it is left unnamed).
  raw.keep();
  try {
    header.commitExchange(size, [&](const std::string& displaced) { removeDisplacedData(displaced, hp); });
  } catch (...) {
    unlink(raw.target().c_str());
    throw;
  }
}

}  // namespace tg::synth
