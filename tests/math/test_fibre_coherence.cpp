// The frame check's score (tensor/fibre_coherence.h) on a thin helical
// bundle, the shape that shows a mirror: as read it scores highest, and
// every flip or permutation of its tensors is undone by the reading that
// scores highest, clearly; the signed permutations' algebra.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tensor/fibre_coherence.h"

namespace {

using namespace tg::tensor;

struct Field {
  CoherenceGrid grid;
  std::vector<float> tensors;
  std::vector<std::uint32_t> ids;
};

// A tube of radius 1.6 voxels about a helix of 1.5 turns, its tensors along
// the tangent (FA 0.8); elsewhere isotropic. `sparse`: only the tube's
// voxels are samples (a mask). The grid's axes are `axes` (column k, WC).
Field helixBundle(const Mat3& axes, bool sparse) {
  Field f;
  const int n = 30;
  f.grid.dims = {n, n, n};
  f.grid.axesWC = axes;
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        // The helix lives in index space; its tangent is carried into WC.
        double best = 1e9, bt = 0;
        for (double t = 0; t <= 3 * pi; t += 0.03) {
          const double cx = 15 + 9 * std::cos(t) - i, cy = 15 + 9 * std::sin(t) - j, cz = 3 + 2.5 * t - k;
          const double d = cx * cx + cy * cy + cz * cz;
          if (d < best) best = d, bt = t;
        }
        double v[3] = {-9 * std::sin(bt), 9 * std::cos(bt), 2.5}, w[3];
        for (int r = 0; r < 3; ++r) w[r] = axes[3 * r] * v[0] + axes[3 * r + 1] * v[1] + axes[3 * r + 2] * v[2];
        const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        for (double& c : w) c /= len;
        const bool in = best <= 1.6 * 1.6;
        if (sparse && !in) continue;
        const double l1 = in ? 1.7e-3 : 0.7e-3, l2 = 0.7e-3;
        // D = l2 I + (l1 - l2) w wᵀ
        const double d = l1 - l2;
        f.tensors.insert(f.tensors.end(), {float(l2 + d * w[0] * w[0]), float(d * w[0] * w[1]), float(d * w[0] * w[2]),
                                           float(l2 + d * w[1] * w[1]), float(d * w[1] * w[2]),
                                           float(l2 + d * w[2] * w[2])});
        f.ids.push_back(std::uint32_t(i + n * (j + n * k)));
      }
  return f;
}

Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) c[std::size_t(3 * r + k)] += a[std::size_t(3 * r + j)] * b[std::size_t(3 * j + k)];
  return c;
}
Mat3 transposed(const Mat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

// M D Mᵀ for every tensor.
std::vector<float> turned(const std::vector<float>& t, const Mat3& m) {
  std::vector<float> out(t.size());
  for (std::size_t s = 0; s < t.size(); s += 6) {
    const double d[9] = {t[s], t[s + 1], t[s + 2], t[s + 1], t[s + 3], t[s + 4], t[s + 2], t[s + 4], t[s + 5]};
    double md[9] = {}, r[9] = {};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int k = 0; k < 3; ++k) md[3 * a + b] += m[std::size_t(3 * a + k)] * d[3 * k + b];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int k = 0; k < 3; ++k) r[3 * a + b] += md[3 * a + k] * m[std::size_t(3 * b + k)];
    const double six[6] = {r[0], r[1], r[2], r[4], r[5], r[8]};
    for (int k = 0; k < 6; ++k) out[s + std::size_t(k)] = float(six[k]);
  }
  return out;
}

std::vector<Mat3> candidatesIn(const Mat3& t) {
  std::vector<Mat3> c;
  for (const AxisMap& q : distinctAxisMaps()) c.push_back(mul(mul(t, axisMatrix(q)), transposed(t)));
  return c;
}

// Each mirror or permutation of the bundle's tensors (in the frame t) is
// undone by the reading that scores highest, 5 standard errors clear.
void expectEveryMirrorUndone(const Field& f, const Mat3& t) {
  const std::vector<AxisMap> maps = distinctAxisMaps();
  const std::vector<Mat3> cands = candidatesIn(t);
  const CoherenceScores asIs = fibreCoherence(f.grid, f.tensors, f.ids, cands);
  ASSERT_GE(asIs.fibreVoxels, 200u);
  for (std::size_t c = 1; c < cands.size(); ++c)
    EXPECT_LT(asIs.scores[c], asIs.scores[0]) << axisMapName(maps[c]) << " beats the bundle as made";
  for (std::size_t q = 1; q < maps.size(); ++q) {
    const std::vector<float> mirrored = turned(f.tensors, cands[q]);
    const CoherenceScores s = fibreCoherence(f.grid, mirrored, f.ids, cands);
    const std::size_t best = std::size_t(std::max_element(s.scores.begin(), s.scores.end()) - s.scores.begin());
    // The reading that undoes q: its matrix is q's inverse (transpose).
    const Mat3 undo = transposed(cands[q]);
    double err = 0;
    for (std::size_t k = 0; k < 9; ++k) err = std::max(err, std::abs(cands[best][k] - undo[k]));
    EXPECT_LT(err, 1e-9) << axisMapName(maps[q]) << ": best " << axisMapName(maps[best]);
    EXPECT_GT(s.scores[best] - s.scores[0], 5 * s.pairedSe[best]) << axisMapName(maps[q]);
  }
}

TEST(FibreCoherence, EveryFlipAndPermutationOfAHelicalBundleIsUndoneByTheBestReading) {
  expectEveryMirrorUndone(helixBundle({1, 0, 0, 0, 1, 0, 0, 0, 1}, false), {1, 0, 0, 0, 1, 0, 0, 0, 1});
}

TEST(FibreCoherence, OnAnObliqueAnisotropicGridInAVoxelFrameAndMasked) {
  // The grid rotated 30 degrees about z and 20 about x, voxels 2 x 2.2 x 2.5;
  // the stored frame is its orthogonal part, so flips act on voxel axes.
  const double a = 0.5235987755982988, b = 0.3490658503988659;
  const Mat3 rz{std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1};
  const Mat3 rx{1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b)};
  const Mat3 q = mul(rz, rx);
  const Mat3 axes = mul(q, Mat3{2, 0, 0, 0, 2.2, 0, 0, 0, 2.5});
  expectEveryMirrorUndone(helixBundle(axes, true), q);
}

TEST(FibreCoherence, AUniformFieldCannotTellAndAnEmptyOneScoresNothing) {
  // One tensor everywhere: every neighbour is aligned whichever way a
  // reading points (but at the grid's faces), so no reading is clearly better.
  Field f;
  f.grid.dims = {12, 12, 12};
  for (std::uint32_t v = 0; v < 12 * 12 * 12; ++v) {
    f.tensors.insert(f.tensors.end(), {1.7e-3f, 0, 0, 0.3e-3f, 0, 0.3e-3f});
    f.ids.push_back(v);
  }
  const std::vector<Mat3> cands = candidatesIn({1, 0, 0, 0, 1, 0, 0, 0, 1});
  const CoherenceScores s = fibreCoherence(f.grid, f.tensors, f.ids, cands);
  for (std::size_t c = 1; c < cands.size(); ++c) EXPECT_LE(s.scores[c], s.scores[0] + 1e-12);
  const CoherenceScores none = fibreCoherence(f.grid, {}, {}, cands);
  EXPECT_EQ(none.fibreVoxels, 0u);
  EXPECT_EQ(none.scores, std::vector<double>(cands.size(), 0.0));
}

TEST(AxisMaps, NamesRoundTripComposeAsMatricesAndTheTwentyFourDiffer) {
  const std::vector<AxisMap> maps = distinctAxisMaps();
  ASSERT_EQ(maps.size(), 24u);
  EXPECT_EQ(maps[0], AxisMap{});
  for (const AxisMap& m : maps) {
    EXPECT_EQ(axisMapNamed(axisMapName(m)), m) << axisMapName(m);
    for (const AxisMap& n : maps) {
      EXPECT_EQ(axisMatrix(compose(m, n)), mul(axisMatrix(n), axisMatrix(m)));
      // v and -v are one axis: P and -P read the same tensors, so none may be another's negative.
      Mat3 neg = axisMatrix(n);
      for (double& x : neg) x = -x;
      if (!(m == n)) {
        EXPECT_NE(axisMatrix(m), axisMatrix(n));
      }
      EXPECT_NE(axisMatrix(m), neg);
    }
  }
  EXPECT_EQ(axisMapNamed("+x,-z,y"), (AxisMap{{0, 2, 1}, {1, -1, 1}}));
  for (const char* bad : {"", "x,y", "x,x,z", "x,y,z,", "x y z", "a,b,c", "--x,y,z", "x,y,w", "X,Y,Z"})
    EXPECT_FALSE(axisMapNamed(bad)) << bad;
}

TEST(FibreCoherence, OtsuSplitsTwoModesAndFaFromInvariantsMatchesTheEigenvalues) {
  std::vector<double> v;
  for (int k = 0; k < 500; ++k) v.push_back(0.1 + 0.0001 * k);
  for (int k = 0; k < 300; ++k) v.push_back(0.7 + 0.0001 * k);
  const double t = otsuThreshold(v);
  EXPECT_GT(t, 0.15);
  EXPECT_LT(t, 0.7);
  EXPECT_EQ(otsuThreshold({}), 0.0);
  const float d[6] = {1.7e-3f, 0, 0, 0.3e-3f, 0, 0.2e-3f};
  const double l1 = 1.7e-3, l2 = 0.3e-3, l3 = 0.2e-3, md = (l1 + l2 + l3) / 3;
  const double fa = std::sqrt(1.5 * ((l1 - md) * (l1 - md) + (l2 - md) * (l2 - md) + (l3 - md) * (l3 - md)) /
                              (l1 * l1 + l2 * l2 + l3 * l3));
  EXPECT_NEAR(fractionalAnisotropy(d), fa, 1e-6);
  const float zero[6] = {};
  EXPECT_EQ(fractionalAnisotropy(zero), 0.0);
}

}  // namespace
