#pragma once
// A gridded tensor field's fibre coherence under alternative readings of its
// frame: one tensor cannot show a mirror, but its neighbours can. After
// Schilling et al. 2019 ("A fiber coherence index for quality control of
// B-table orientation in diffusion MRI scans", MRI 58), who pick among the
// flips and permutations of a b-table the one whose fibres connect best.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "tensor/axis_map.h"

namespace tg::tensor {

struct CoherenceGrid {
  std::array<int, 3> dims{0, 0, 0};
  Mat3 axesWC{1, 0, 0, 0, 1, 0, 0, 0, 1};  // column k: one step along index k, in WC
};

struct CoherenceParams {
  // Voxels at or above this FA are fibre voxels; 0: Otsu's threshold of the
  // examined voxels' FA (the zero background left out), at least kFaFloor.
  double faMin = 0;
  // A neighbour's principal axis within this angle of a voxel's is aligned.
  double maxAngleDeg = 30;
  // Voxels examined for fibre voxels, spread evenly over the samples: the
  // cost is bounded whatever the field's size.
  std::size_t maxExamined = 30000;
  // Of the fibre voxels found, at most this many (evenly spread) are scored:
  // they are what the check costs.
  std::size_t maxSeeds = 2000;
  // Neighbours 1..reach steps out each way along the axis.
  int reach = 2;
};
inline constexpr double kFaFloor = 0.2;
// A voxel's score reads voxels up to `reach` (2) steps out: blocks of 5
// voxels a side share few of them.
inline constexpr int kBlock = 5;

struct CoherenceScores {
  std::vector<double> scores;  // one per candidate, in [0, 1]
  // The standard error of scores[c] - scores[0], paired by voxel, with
  // blocks of voxels as the samples: the larger of kBlock^3's and (2 kBlock)^3's.
  std::vector<double> pairedSe;
  std::size_t blocks = 0, coarseBlocks = 0;  // the blocks of each size holding scored fibre voxels
  std::size_t fibreVoxels = 0;       // the fibre voxels scored: what the scores are over
  std::size_t fibreVoxelsFound = 0;  // of the examined voxels, those at or above faMin
  double faMin = 0;              // the threshold used
};

// For each fibre voxel (FA >= faMin) and each candidate M (orthogonal,
// applied to the WC tensors as M D Mᵀ): its principal axis e, turned by M,
// points along ±Me at the grid's nearest steps r = 1..reach voxels out
// (Me in index space, scaled to r along its largest component, rounded);
// each of those 2·reach neighbours scores 1 when it is a sample, a fibre
// voxel, and its own principal axis lies within maxAngleDeg of e. A
// voxel's score is the mean over them, a candidate's the mean over voxels. M keeps the angles between
// axes, so only where they point changes: a mirrored field's fibres point
// out of their bundles. tensors: 6 floats (xx xy xz yy yz zz, WC) per
// sample; ids: each sample's voxel index (i fastest); increasing.
CoherenceScores fibreCoherence(const CoherenceGrid& grid, std::span<const float> tensors,
                               std::span<const std::uint32_t> ids, std::span<const Mat3> candidates,
                               const CoherenceParams& p = {});

// FA of xx xy xz yy yz zz from its invariants (no eigensolve).
double fractionalAnisotropy(const float t[6]);
// Otsu's threshold of values in [0, 1], on 64 bins; 0 for an empty list.
double otsuThreshold(std::span<const double> values);

}  // namespace tg::tensor
