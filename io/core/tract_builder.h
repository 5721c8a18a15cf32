#pragma once
// Streamlines gathered a point at a time by the tract readers
// (io/core/tract_reader.h): a streamline with a point that is NaN/Inf, or beyond
// single precision, is dropped whole and counted, as meshes drop such cells.
#include <cfloat>
#include <cmath>
#include <string>

#include "io/field/tensor_field.h"
#include "io/core/tract_reader.h"

namespace tg::io {

class TractBuilder {
 public:
  TractBuilder(TractData& out, std::string who) : out_(out), who_(std::move(who)) {
    if (out_.starts.empty()) out_.starts.push_back(0);
  }
  void point(double x, double y, double z) {
    if (!(std::abs(x) <= double(FLT_MAX) && std::abs(y) <= double(FLT_MAX) && std::abs(z) <= double(FLT_MAX)))
      bad_ = true;  // also NaN
    if (bad_) return;
    if (out_.pointCount() >= kMaxTractPoints)
      throw InputError(who_ + ": more than " + std::to_string(kMaxTractPoints) + " points, the limit");
    float* p = out_.positionsWC.extend(3);
    p[0] = float(x);
    p[1] = float(y);
    p[2] = float(z);
  }
  // Ends the streamline begun after the last end; `keepEmpty`: one of no
  // points still counts (a .trk's, as nibabel keeps it).
  void end(bool keepEmpty) {
    const std::uint64_t begin = out_.starts[out_.starts.size() - 1];
    if (bad_) {
      out_.positionsWC.resize(3 * begin);
      ++out_.skippedNonFinite;
    } else if (out_.pointCount() > begin || keepEmpty) {
      out_.starts.push_back(out_.pointCount());
    }
    bad_ = false;
  }
  bool open() const { return bad_ || out_.pointCount() > out_.starts[out_.starts.size() - 1]; }

 private:
  TractData& out_;
  std::string who_;
  bool bad_ = false;
};

}  // namespace tg::io
