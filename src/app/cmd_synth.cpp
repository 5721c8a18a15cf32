
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "app/scale/option_table.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/progress.h"
#include "data-synthetic/generators.h"
#include "io/core/read_guard.h"
#include "io/core/writers.h"

namespace tg::app {
namespace {

constexpr const char* kKinds = "helix, boussinesq, kirsch, extremes, extremes-tiny, extremes-huge, random";

// What --n means for each KIND and the values it takes: the helix's grid
// side (its depth half that), the point load's cube side, the random field's
// tensor count; the galleries have a fixed size. The helix's top keeps its
// generation within a minute or so here (a nearest-point search per voxel).
struct KindSize {
  const char* kind;
  const char* meaning;  // "" for a fixed size
  long long lo, hi, byDefault;
};
constexpr KindSize kSizes[] = {
    {"helix", "the grid side", 2, 256, 32},
    {"boussinesq", "the grid side", 2, 512, 16},
    {"kirsch", "the grid side", 8, 4096, 64},
    {"extremes", "", 54, 54, 54},
    {"extremes-tiny", "", 54, 54, 54},
    {"extremes-huge", "", 54, 54, 54},
    {"random", "the tensor count", 1, 4000000000LL, 10000},
};

const KindSize* kindNamed(const std::string& k) {
  for (const KindSize& s : kSizes)
    if (k == s.kind) return &s;
  return nullptr;
}

std::uint64_t tensorsOf(const KindSize& s, long long n) {
  const auto side = std::uint64_t(n);
  if (std::string_view(s.kind) == "helix") return side * side * std::uint64_t(std::max(2LL, n / 2));
  if (std::string_view(s.kind) == "boussinesq") return side * side * side;
  if (std::string_view(s.kind) == "kirsch") return side * side;
  return side;
}

bool endsWith(const std::string& s, const char* suffix) {
  const std::string x(suffix);
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

// Which files each KIND can be written to, checked before anything is
// generated: a point set has no grid for .nrrd or .vti, and only random
// streams .nhdr.
void checkSynthOutput(const std::string& kind, const std::string& out) {
  const bool gridded = kind == "helix" || kind == "boussinesq" || kind == "kirsch";
  for (const char* ext : {".vtk", ".vtu", ".vtp"})
    if (endsWith(out, ext)) return;
  if (gridded && (endsWith(out, ".vti") || endsWith(out, ".nrrd"))) return;
  if (kind == "random" && endsWith(out, ".nhdr")) return;
  const char* exts = gridded ? "is written as .vtk .vti .vtu .vtp or .nrrd"
                     : kind == "random" ? "is a point set: write .vtk .vtu .vtp or .nhdr (streamed)"
                                        : "is a point set: write .vtk .vtu or .vtp";
  throw UsageError("-o: \"" + out + "\": " + kind + " " + exts);
}

// Peak bytes per tensor of generating a field and writing it whole, by the
// output's format (measured RSS with 1M tensors, rounded up): the field's
// samples, the writer's dataset, the encoded bytes. The streamed .nhdr
// holds one chunk at any size.
std::uint64_t bytesPerTensorWriting(const std::string& out) {
  if (endsWith(out, ".nhdr")) return 0;
  if (endsWith(out, ".nrrd")) return 96;
  if (endsWith(out, ".vti")) return 128;
  if (endsWith(out, ".vtk")) return 288;
  return 208;  // .vtu, .vtp
}

// --n within its KIND's range, and the field it asks for within the memory
// this machine allows, before anything is generated (UsageError otherwise).
// Returns the size to generate.
long long checkSynthSize(const KindSize& s, std::optional<long long> n, bool seedGiven, const std::string& out) {
  const std::string kind = s.kind;
  if (seedGiven && kind != "random") throw UsageError("--seed applies to random only; " + kind + " is not random");
  if (n && !*s.meaning)
    throw UsageError("--n does not apply to " + kind + ": its gallery has a fixed size (" + std::to_string(s.lo) +
                     " tensors)");
  if (n && (*n < s.lo || *n > s.hi))
    throw UsageError("--n " + std::to_string(*n) + ": " + kind + "'s --n is " + s.meaning + ", within " +
                     std::to_string(s.lo) + ".." + std::to_string(s.hi));
  const long long size = n.value_or(s.byDefault);
  // The streamed .nhdr is bounded by its disk, not by memory: 24 B a tensor.
  // A full disk is the disk's state, not the command line's: exit 1, the
  // file named, as when a write meets the end of the disk.
  if (endsWith(out, ".nhdr")) {
    const std::filesystem::path dir = std::filesystem::path(out).has_parent_path()
                                          ? std::filesystem::path(out).parent_path()
                                          : std::filesystem::path(".");
    std::error_code ec;
    const std::filesystem::space_info space = std::filesystem::space(dir, ec);
    const std::uint64_t bytes = tensorsOf(s, size) * 24;
    if (!ec && bytes > space.available)
      throw std::runtime_error(out + ": " + kind + " --n " + std::to_string(size) + " needs about " +
                               std::to_string(bytes >> 20) + " MiB on disk, more than the " +
                               std::to_string(space.available >> 20) + " MiB free there");
  }
  const long double need = (long double)tensorsOf(s, size) * bytesPerTensorWriting(out);
  const std::uint64_t budget = io::defaultMemoryBudget();
  if (need > (long double)budget)
    throw UsageError("--n " + std::to_string(size) + ": " + kind + " written as " + out.substr(out.rfind('.')) +
                     " needs about " + std::to_string(std::uint64_t(need / (1 << 20))) + " MiB, more than the " +
                     std::to_string(budget >> 20) + " MiB this machine allows" +
                     (kind == "random" ? "; .nhdr streams any size" : ""));
  return size;
}

void writeField(const io::TensorField& f, const std::string& out, const double* frame,
                const util::ProgressSink& progress) {
  if (progress) progress("writing", 0, 0, {});
  if (endsWith(out, ".nrrd")) {
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    io::writeNrrd(f, out, frame ? frame : identity);
  } else {
    io::writeVtk(f, out);
  }
}

}  // namespace

int cmdSynth(int argc, const char** argv) {
  std::string kind, out;
  std::optional<long long> n;
  long long seed = 1;
  bool quiet = false, seedGiven = false;
  OptionTable ap(std::string("tensorglyph synth KIND -o OUT [--n N] [--seed S]\n  KIND: ") + kKinds +
           "\n  OUT: .vtk .vti .vtu .vtp, or .nrrd for gridded fields, or .nhdr for random (streamed)");
  using Args = OptionArgs;
  ap.arg("KIND").action([&](Args a) {
    if (!kind.empty()) throw UsageError("more than one KIND");
    kind = a[1];
  });
  ap.arg("-o OUT").help("output file").action([&](Args a) { out = a[1]; });
  ap.arg("--n N").help("size: grid side (helix 2..256, default 32; boussinesq 2..512, default 16; kirsch 8..4096, default "
                       "64) or tensor count "
                       "(random 1..4e9, default 10000; beyond memory only as .nhdr)").action([&](Args a) {
    n = parseInt("--n", a[1]);
  });
  ap.arg("--seed S").help("random seed (random)").action([&](Args a) {
    seed = parseInt("--seed", a[1], 0, std::numeric_limits<long long>::max());
    seedGiven = true;
  });
  ap.arg("-q,--quiet").help("no progress line on a terminal's stderr").action([&](Args) { quiet = true; });
  parseCommandLine(ap, argc, argv);
  if (kind.empty() || out.empty()) throw UsageError(std::string("KIND and -o OUT are required; KIND is one of ") + kKinds);
  const KindSize* sized = kindNamed(kind);
  if (!sized) throw UsageError("unknown KIND \"" + kind + "\"; choose " + kKinds);
  checkSynthOutput(kind, out);
  checkOutputPath("-o", out);
  const long long size = checkSynthSize(*sized, n, seedGiven, out);
  TerminalProgress progress(quiet);
  const util::ProgressSink sink = progress.sink();
  // Only the streamed field counts its tensors; the others name their stage.
  if (sink) sink("generating", 0, 0, {});

  if (kind == "helix") {
    const int side = int(size);
    const synth::Helix h = synth::helixPhantom(side, side, std::max(2, side / 2));
    writeField(h.field, out, h.measurementFrame, sink);
  } else if (kind == "boussinesq") {
    writeField(synth::boussinesq(int(size), 0.3), out, nullptr, sink);
  } else if (kind == "kirsch") {
    writeField(synth::kirschPlate(int(size)), out, nullptr, sink);
  } else if (kind == "extremes") {
    writeField(synth::extremesGallery(1.0, 1.0), out, nullptr, sink);
  } else if (kind == "extremes-tiny") {
    writeField(synth::extremesGallery(1e-20, 1e-6), out, nullptr, sink);
  } else if (kind == "extremes-huge") {
    writeField(synth::extremesGallery(1e20, 1e6), out, nullptr, sink);
  } else if (kind == "random") {
    const auto count = std::size_t(size);
    if (endsWith(out, ".nhdr")) synth::writeRandomNrrdStreaming(out, count, std::uint64_t(seed), sink);
    else writeField(synth::randomField(count, std::uint64_t(seed)), out, nullptr, sink);
  } else {
    throw UsageError("unknown KIND \"" + kind + "\"; choose " + kKinds);
  }
  return 0;
}

}  // namespace tg::app
