#include "app/frame_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace tg::app {
namespace {

using tensor::Mat3;
using tensor::multiply;

constexpr Mat3 kIdentity{1, 0, 0, 0, 1, 0, 0, 0, 1};


Mat3 transpose(const Mat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

bool near(const Mat3& a, const Mat3& b) {
  for (std::size_t k = 0; k < 9; ++k)
    if (std::abs(a[k] - b[k]) > 1e-6) return false;
  return true;
}

// How reading q differs from the one applied, in words.
std::string difference(const tensor::AxisMap& q) {
  std::string negated, moved;
  for (std::size_t r = 0; r < 3; ++r) {
    if (q.sign[r] < 0) negated = std::string(1, char('x' + r)) + " negated";
    if (q.from[r] != int(r)) moved = "axes read as " + tensor::axisMapName(q);
  }
  return moved.empty() ? negated : moved;
}

std::string score(double s) {
  char b[16];
  std::snprintf(b, sizeof b, "%.2f", s);
  return b;
}

// CPU time, not wall time: what the check costs whatever else the machine runs.
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// A reading's option, short: "-x,y,z", "frame voxel", "x,y,z" for none.
std::string label(const std::string& option) {
  const std::string axes = "--tensor-axes ";
  if (option.starts_with(axes)) return option.substr(axes.size());
  if (option.starts_with("--")) return option.substr(2);
  return "x,y,z";
}

}  // namespace

FrameCheck checkFrame(const io::TensorField& f, const io::ReadOptions& read) {
  FrameCheck c;
  c.asRead = {"as read", "", 0, 0};
  if (!f.grid) {
    c.skipped = "the samples are not on a grid";
    return c;
  }
  if (f.unselected > 0) {
    c.skipped = "--slice, --stride or --roi left voxels out, and their neighbourhoods with them";
    return c;
  }
  const double start = threadCpuMs();
  const io::GridInfo& g = *f.grid;
  tensor::CoherenceGrid grid;
  for (std::size_t k = 0; k < 3; ++k) {
    grid.dims[k] = g.dims[k];
    for (std::size_t r = 0; r < 3; ++r) grid.axesWC[3 * r + k] = g.directions[3 * r + k] * g.spacing[k];
  }
  const Mat3 t = f.tensorToWC.value_or(kIdentity), tt = transpose(t);
  const tensor::AxisMap given = read.tensorAxes.empty() ? tensor::AxisMap{} : *tensor::axisMapNamed(read.tensorAxes);
  std::vector<FrameReading> readings;
  std::vector<Mat3> candidates;
  for (const tensor::AxisMap& q : tensor::distinctAxisMaps()) {
    const tensor::AxisMap whole = tensor::compose(given, q);
    readings.push_back({q == tensor::AxisMap{} ? "as read" : "--tensor-axes " + tensor::axisMapName(whole),
                        difference(q), 0, 0});
    candidates.push_back(multiply(multiply(t, tensor::axisMatrix(q)), tt));
  }
  // Another frame is named by --frame, also where it equals a flip.
  for (const io::FrameChoice& other : f.otherFrames) {
    const Mat3 m = multiply(other.tensorToWC.value_or(kIdentity), tt);
    const std::string option = "--frame " + other.name, what = "the " + other.name + " frame";
    auto same = std::find_if(candidates.begin() + 1, candidates.end(), [&](const Mat3& x) { return near(x, m); });
    if (same != candidates.end()) {
      readings[std::size_t(same - candidates.begin())] = {option, what, 0, 0};
    } else {
      readings.push_back({option, what, 0, 0});
      candidates.push_back(m);
    }
  }
  const tensor::CoherenceScores s = tensor::fibreCoherence(grid, {f.tensors.data(), f.tensors.size()},
                                                           {f.ids.data(), f.ids.size()}, candidates);
  for (std::size_t k = 0; k < readings.size(); ++k) readings[k].score = s.scores[k];
  for (std::size_t k = 0; k < readings.size(); ++k) readings[k].z = s.pairedSe[k] > 0 ? (s.scores[k] - s.scores[0]) / s.pairedSe[k] : 0;
  c.fibreVoxels = s.fibreVoxels;
  c.blocks = s.blocks;
  c.coarseBlocks = s.coarseBlocks;
  c.faMin = s.faMin;
  c.asRead = readings[0];
  c.alternatives.assign(readings.begin() + 1, readings.end());
  std::stable_sort(c.alternatives.begin(), c.alternatives.end(),
                   [](const FrameReading& a, const FrameReading& b) { return a.score > b.score; });
  std::vector<double> all{c.asRead.score};
  for (const FrameReading& r : c.alternatives) all.push_back(r.score);
  std::sort(all.begin(), all.end());
  c.median = (all[(all.size() - 1) / 2] + all[all.size() / 2]) / 2;
  const FrameReading& best = c.alternatives.front();
  if (bigEnough(c) && best.score >= c.asRead.score + kClearMargin && best.score >= c.median + kStandOut)
    c.better = best;
  c.milliseconds = threadCpuMs() - start;
  return c;
}

bool bigEnough(const FrameCheck& c) { return c.fibreVoxels >= kMinFibreVoxels && c.blocks >= kMinBlocks; }

std::string frameWarning(const FrameCheck& c) {
  if (!c.better) return "";
  return "the tensors look mirrored or permuted: their fibres cohere " + score(c.better->score) + " with " +
         c.better->what + ", " + score(c.asRead.score) + " as read; give " + c.better->option +
         " (`tensorglyph info` lists every reading)";
}

std::string frameCheckReport(const FrameCheck& c) {
  if (!c.skipped.empty()) return "frame check: not run: " + c.skipped + "\n";
  char head[192];
  std::snprintf(head, sizeof head,
                "frame check: fibre coherence over %zu fibre voxels (FA >= %.2f) in %zu blocks of 5^3 and %zu of 10^3 voxels, "
                "in %.1f ms of CPU\n",
                c.fibreVoxels, c.faMin, c.blocks, c.coarseBlocks, c.milliseconds);
  std::string out = head;
  out += "  as read: " + score(c.asRead.score) + "\n";
  std::string all;
  for (const FrameReading& r : c.alternatives)
    all += (all.empty() ? "" : ", ") + label(r.option) + " " + score(r.score);
  out += "  others (--tensor-axes AXES, --frame NAME): " + all + "\n";
  char z[96];
  const double bestZ = c.alternatives.front().z;
  std::snprintf(z, sizeof z, "  best other: %.2f standard errors %s as read (paired by voxel, the blocks as samples)\n", std::abs(bestZ),
                bestZ < 0 ? "below" : "above");
  out += z;
  out += "  median reading: " + score(c.median) + "\n";
  if (c.better) out += "  verdict: " + c.better->option + " reads the fibres clearly better (" + c.better->what + ")\n";
  else if (!bigEnough(c))
    out += "  verdict: too small a field to tell (a verdict needs " + std::to_string(kMinFibreVoxels) +
           " fibre voxels in " + std::to_string(kMinBlocks) + " blocks)\n";
  else out += "  verdict: no alternative reads the fibres clearly better\n";
  return out;
}

}  // namespace tg::app
