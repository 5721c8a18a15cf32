
#include <cstdio>
#include <limits>
#include <string>

#include "app/option_table.h"
#include "app/cli_common.h"
#include "app/commands.h"
#include "app/progress.h"
#include "data-synthetic/generators.h"
#include "io/writers.h"

namespace tg::app {
namespace {

constexpr const char* kKinds = "helix, boussinesq, extremes, extremes-tiny, extremes-huge, random";

bool isKind(const std::string& k) {
  for (const char* name : {"helix", "boussinesq", "extremes", "extremes-tiny", "extremes-huge", "random"})
    if (k == name) return true;
  return false;
}

bool endsWith(const std::string& s, const char* suffix) {
  const std::string x(suffix);
  return s.size() >= x.size() && s.compare(s.size() - x.size(), x.size(), x) == 0;
}

// Which files each KIND can be written to, checked before anything is
// generated: a point set has no grid for .nrrd or .vti, and only random
// streams .nhdr.
void checkSynthOutput(const std::string& kind, const std::string& out) {
  const bool gridded = kind == "helix" || kind == "boussinesq";
  for (const char* ext : {".vtk", ".vtu", ".vtp"})
    if (endsWith(out, ext)) return;
  if (gridded && (endsWith(out, ".vti") || endsWith(out, ".nrrd"))) return;
  if (kind == "random" && endsWith(out, ".nhdr")) return;
  const char* exts = gridded ? "is written as .vtk .vti .vtu .vtp or .nrrd"
                     : kind == "random" ? "is a point set: write .vtk .vtu .vtp or .nhdr (streamed)"
                                        : "is a point set: write .vtk .vtu or .vtp";
  throw UsageError("-o: \"" + out + "\": " + kind + " " + exts);
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
  long long n = 0, seed = 1;
  bool quiet = false;
  OptionTable ap(std::string("tensorglyph synth KIND -o OUT [--n N] [--seed S]\n  KIND: ") + kKinds +
           "\n  OUT: .vtk .vti .vtu .vtp, or .nrrd for gridded fields, or .nhdr for random (streamed)");
  using Args = OptionArgs;
  ap.arg("KIND").action([&](Args a) {
    if (!kind.empty()) throw UsageError("more than one KIND");
    kind = a[1];
  });
  ap.arg("-o OUT").help("output file").action([&](Args a) { out = a[1]; });
  ap.arg("--n N").help("size: grid side (helix, boussinesq) or glyph count (random)").action([&](Args a) {
    n = parseInt("--n", a[1], 0, 4000000000LL);
  });
  ap.arg("--seed S").help("random seed").action([&](Args a) { seed = parseInt("--seed", a[1], 0, std::numeric_limits<long long>::max()); });
  ap.arg("-q,--quiet").help("no progress line on a terminal's stderr").action([&](Args) { quiet = true; });
  parseCommandLine(ap, argc, argv);
  if (kind.empty() || out.empty()) throw UsageError(std::string("KIND and -o OUT are required; KIND is one of ") + kKinds);
  if (!isKind(kind)) throw UsageError("unknown KIND \"" + kind + "\"; choose " + kKinds);
  checkSynthOutput(kind, out);
  checkOutputPath("-o", out);
  TerminalProgress progress(quiet);
  const util::ProgressSink sink = progress.sink();
  // Only the streamed field counts its tensors; the others name their stage.
  if (sink) sink("generating", 0, 0, {});

  if (kind == "helix") {
    const int side = n ? int(std::min(n, 512LL)) : 32;
    const synth::Helix h = synth::helixPhantom(side, side, std::max(2, side / 2));
    writeField(h.field, out, h.measurementFrame, sink);
  } else if (kind == "boussinesq") {
    writeField(synth::boussinesq(n ? int(std::min(n, 512LL)) : 16, 0.3), out, nullptr, sink);
  } else if (kind == "extremes") {
    writeField(synth::extremesGallery(1.0, 1.0), out, nullptr, sink);
  } else if (kind == "extremes-tiny") {
    writeField(synth::extremesGallery(1e-20, 1e-6), out, nullptr, sink);
  } else if (kind == "extremes-huge") {
    writeField(synth::extremesGallery(1e20, 1e6), out, nullptr, sink);
  } else if (kind == "random") {
    const std::size_t count = n ? std::size_t(n) : 10000;
    if (endsWith(out, ".nhdr")) synth::writeRandomNrrdStreaming(out, count, std::uint64_t(seed), sink);
    else writeField(synth::randomField(count, std::uint64_t(seed)), out, nullptr, sink);
  } else {
    throw UsageError("unknown KIND \"" + kind + "\"; choose " + kKinds);
  }
  return 0;
}

}  // namespace tg::app
