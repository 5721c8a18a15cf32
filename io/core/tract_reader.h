#pragma once
// Tractography for the scene's context (render/tract_item.h): streamlines
// from MRtrix .tck, TrackVis .trk (our own strict readers: no C++ library
// for them is packaged) and VTK polylines (.vtk, .vtp, read by VTK in its
// module). Every read runs in the guarded child (io/core/read_guard.h). Points
// come back in world coordinates (RAS+ mm for .tck and .trk, as
// nibabel.streamlines gives them): a .trk's voxmm points are taken to world
// by its header's vox_to_ras, voxel order and voxel size (trkToWorld).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/core/read_guard.h"
#include "util/mapped_array.h"

namespace tg::io {

// More points than this are refused before any of ours are allocated: 16
// bytes each on the GPU, 1 GiB at the limit.
inline constexpr std::uint64_t kMaxTractPoints = std::uint64_t(1) << 26;

struct TractData {
  std::string path;
  std::string description;  // what was read, e.g. "MRtrix tracks, 12 streamlines, 3400 points"
  util::MappedArray<float> positionsWC;  // 3 per point, the streamlines one after another
  // Streamline k is points starts[k] .. starts[k + 1] - 1; one more entry
  // than streamlines, the last the point count (nibabel's offsets, closed).
  util::MappedArray<std::uint64_t> starts;
  // Streamlines with a NaN/Inf point (or one beyond single precision once
  // in world coordinates): none of their points is kept.
  std::size_t skippedNonFinite = 0;
  // What the user should hear beyond the points (a .trk header that
  // records no vox_to_ras, taken as the identity as nibabel does); "" if none.
  std::string warning;
  std::size_t pointCount() const { return positionsWC.size() / 3; }
  std::size_t streamlineCount() const { return starts.empty() ? 0 : starts.size() - 1; }
};

// .tck .trk, and the polylines of a .vtk or .vtp; throws InputError
// "readTracts: path: problem". Read in a child process.
TractData readTracts(const std::string& path);
// The same without the child process (the fuzzers, the tests); `memoryBudget`
// 0: no bound beyond kMaxTractPoints.
TractData readTractsInProcess(const std::string& path, std::uint64_t memoryBudget = 0);
// Why a file of this name cannot be read as tracts (its extension), or "".
std::string tractExtensionProblem(const std::string& path);

// The readers of our own, in whichever process calls them: `promise`
// (may be empty) hears the memory they will take once the header is checked.
TractData readTck(const std::string& path, std::uint64_t memoryBudget, const PromiseFn& promise = {});
TractData readTrk(const std::string& path, std::uint64_t memoryBudget, const PromiseFn& promise = {});

// A .trk header's voxmm-to-RAS+ transform, row-major 4x4, as nibabel's
// get_affine_trackvis_to_rasmm makes it: voxmm to voxel (voxel sizes), the
// half-voxel shift from corner to centre, the header's voxel order to the
// order vox_to_ras implies (flips and swaps over `dims`), then vox_to_ras.
// `ok` false with `problem` saying why (a singular
// vox_to_ras, a voxel order that is not one letter per axis).
struct TrkTransform {
  bool ok = false;
  std::string problem;
  std::array<double, 16> voxmmToRas{};
};
TrkTransform trkToWorld(const float voxToRas[16], const char voxelOrder[4], const std::int16_t dims[3],
                        const float voxelSizes[3]);

}  // namespace tg::io
