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
  double z = 0;  // (score - as read's) / its standard error, paired by voxel
};

struct FrameCheck {
  // Empty when it ran; else why not ("the field has no grid").
  std::string skipped;
  std::size_t fibreVoxels = 0;
  double faMin = 0;
  FrameReading asRead;
  std::vector<FrameReading> alternatives;  // best first
  // The best alternative when it scores clearly higher (kClearMargin, kClearRatio).
  std::optional<FrameReading> better;
  double milliseconds = 0;  // the CPU time the check took
};

// Clearly higher: by at least kClearMargin, and by kClearZ standard errors
// of the difference (paired by voxel), over at least kMinFibreVoxels fibre
// voxels. Measured (frame check tests): correct phantoms' best other reading
// scores 0.05-0.14 lower, mirrored ones' correct reading 0.09-0.26 higher,
// at 7 to 28 standard errors.
inline constexpr double kClearMargin = 0.05;
inline constexpr double kClearZ = 5;
inline constexpr std::size_t kMinFibreVoxels = 200;

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
