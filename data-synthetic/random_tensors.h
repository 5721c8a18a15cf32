#pragma once
// Reproducible random positive-definite tensors, one at a time.
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace tg::synth {

// A grid of exactly N samples, s x s x N/s², as close to a cube as the
// divisors of N allow (1e8 -> 400 x 400 x 625).
struct GridDims {
  std::size_t x, y, z;
};
inline GridDims gridDims(std::size_t count) {
  std::size_t s = std::max<std::size_t>(1, std::size_t(std::cbrt(double(count))));
  while (s > 1 && count % (s * s) != 0) --s;
  return {s, s, count / (s * s)};
}

class RandomTensorStream {
 public:
  explicit RandomTensorStream(std::uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 1) {}
  // xx xy xz yy yz zz of R diag(l) Rᵀ: R uniform on SO(3) (Shoemake's
  // quaternion method), l uniform in [0.1, 1].
  void next(float out[6]) {
    const double u1 = uniform(), u2 = 2 * M_PI * uniform(), u3 = 2 * M_PI * uniform();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3), w = b * std::cos(u3);
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    const double l[3] = {0.1 + 0.9 * uniform(), 0.1 + 0.9 * uniform(), 0.1 + 0.9 * uniform()};
    auto m = [&](int i, int j) { return float(r[i][0] * l[0] * r[j][0] + r[i][1] * l[1] * r[j][1] + r[i][2] * l[2] * r[j][2]); };
    out[0] = m(0, 0);
    out[1] = m(0, 1);
    out[2] = m(0, 2);
    out[3] = m(1, 1);
    out[4] = m(1, 2);
    out[5] = m(2, 2);
  }

 private:
  double uniform() {  // splitmix64 -> [0, 1)
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
  std::uint64_t state_;
};

}  // namespace tg::synth
