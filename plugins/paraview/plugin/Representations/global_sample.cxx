#include "global_sample.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <tuple>
#include <vector>

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

#include "io/field/tensor_field.h"

namespace tg::paraview {
namespace {

using tensor::GlyphRecord;

// The records of every rank, in rank order: sent as bytes (the record is
// plain data).
std::vector<GlyphRecord> gather(std::span<const GlyphRecord> mine, vtkMultiProcessController* c) {
  const int ranks = c->GetNumberOfProcesses();
  const vtkIdType myBytes = vtkIdType(mine.size() * sizeof(GlyphRecord));
  const auto n = static_cast<std::size_t>(ranks);
  std::vector<vtkIdType> counts(n), offsets(n);
  c->AllGather(&myBytes, counts.data(), 1);
  vtkIdType total = 0;
  for (int r = 0; r < ranks; ++r) {
    offsets[std::size_t(r)] = total;
    total += counts[std::size_t(r)];
  }
  std::vector<char> bytes(std::size_t(total) + 1);
  c->AllGatherV(reinterpret_cast<const char*>(mine.data()), bytes.data(), myBytes, counts.data(), offsets.data());
  std::vector<GlyphRecord> all(std::size_t(total) / sizeof(GlyphRecord));
  if (!all.empty()) std::memcpy(all.data(), bytes.data(), all.size() * sizeof(GlyphRecord));
  return all;
}

auto key(const GlyphRecord& g) {
  return std::tie(g.posWC[0], g.posWC[1], g.posWC[2], g.eigenvalues[0], g.eigenvalues[1], g.eigenvalues[2]);
}

bool samePosition(const GlyphRecord& a, const GlyphRecord& b) {
  return a.posWC[0] == b.posWC[0] && a.posWC[1] == b.posWC[1] && a.posWC[2] == b.posWC[2];
}

}  // namespace

tensor::MagnitudeSample globalMagnitudeSample(const tensor::GlyphSet& local, double gridSpacing,
                                              vtkMultiProcessController* controller) {
  std::vector<GlyphRecord> records;
  double maxAbs = local.maxAbsEigenvalue, grid = gridSpacing;
  const std::span<const GlyphRecord> mine(local.glyphs.data(), local.glyphs.size());
  if (controller && controller->GetNumberOfProcesses() > 1) {
    records = gather(mine, controller);
    const double sent[2] = {-local.maxAbsEigenvalue, gridSpacing};
    double lows[2];
    controller->AllReduce(sent, lows, 2, vtkCommunicator::MIN_OP);
    maxAbs = -lows[0];
    grid = lows[1];
  } else {
    records.assign(mine.begin(), mine.end());
  }
  std::sort(records.begin(), records.end(), [](const GlyphRecord& a, const GlyphRecord& b) { return key(a) < key(b); });
  records.erase(std::unique(records.begin(), records.end(), samePosition), records.end());
  double spacing = std::isfinite(grid) && grid > 0.0 ? grid : 0.0;
  if (spacing <= 0.0) {
    std::vector<float> positions;
    positions.reserve(3 * records.size());
    for (const GlyphRecord& g : records) positions.insert(positions.end(), g.posWC, g.posWC + 3);
    spacing = io::estimateSampleSpacing(positions);
  }
  tensor::GlyphSet all;
  all.glyphs = util::MappedArray<GlyphRecord>(std::span<const GlyphRecord>(records));
  all.maxAbsEigenvalue = maxAbs;
  return tensor::sampleMagnitudes(all, spacing);
}

}  // namespace tg::paraview
