#pragma once
// The frame check: a gridded field's fibre coherence (tensor/fibre_coherence.h)
// as read and under each alternative reading of its frame (the flips and
// permutations --tensor-axes gives, and the other frames --frame names), so
// that a mirrored field is named on stderr and `info` prints the scores.
#include <optional>
#include <string>
#include <vector>

#include "io/core/readers.h"
#include "tensor/fibre_coherence.h"

namespace tg::app {

struct FrameReading {
  std::string option;  // what gives it: "--frame voxel", "--tensor-axes -x,y,z", "as read"
  std::string what;    // how it differs from the reading applied: "x negated", "the voxel frame"
  double score = 0;
  double z = 0;  // (score - as read's) / its standard error (tensor::CoherenceScores::pairedSe)
};

struct FrameCheck {
  // Empty when it ran; else why not ("the field has no grid").
  std::string skipped;
  std::size_t fibreVoxels = 0;
  std::size_t blocks = 0, coarseBlocks = 0;  // tensor::CoherenceScores's
  double faMin = 0;
  FrameReading asRead;
  std::vector<FrameReading> alternatives;  // best first
  double median = 0;  // of every reading's score, as read included
  // The best alternative when it scores clearly higher (kClearMargin, kStandOut).
  std::optional<FrameReading> better;
  double milliseconds = 0;  // the CPU time the check took
};

// Clearly higher: by at least kClearMargin above as read and kStandOut
// above the median reading, over at least kMinFibreVoxels fibre voxels in
// kMinBlocks blocks (tensor::kBlock). A mirror makes one reading, the one
// that undoes it, cohere well above the readings as a whole; a field that
// cannot tell leaves its best reading near the median. Measured (docs/
// conventions.md, "Frame check"): in 480 smooth random fibre fields with no
// mirror (6x10x10 to 12x40x40 voxels, smoothing 1-4 voxels) the best stood at
// most 0.065 above the median over 20 blocks or more (0.10 over 8); the
// real helices mirrored, 0.13-0.23. The standard errors are reported, not
// used: in those fields a best reading came out 6-8 of them above as read,
// as the fields' few bundles are few independent samples.
inline constexpr double kClearMargin = 0.05;
inline constexpr double kStandOut = 0.1;
inline constexpr std::size_t kMinFibreVoxels = 200;
inline constexpr std::size_t kMinBlocks = 20;
bool bigEnough(const FrameCheck& c);

// Runs on the loaded samples (before releaseSamples): gridded fields read
// without a slice, stride or ROI (a thinned neighbourhood says nothing), with
// `read` the options they were read with.
FrameCheck checkFrame(const io::TensorField& f, const io::ReadOptions& read);
// The one stderr line for FrameCheck::better ("" when none), without the
// "tensorglyph COMMAND: FILE: " prefix.
std::string frameWarning(const FrameCheck& c);
// `info`'s lines, each ending in a newline.
std::string frameCheckReport(const FrameCheck& c);

}  // namespace tg::app
