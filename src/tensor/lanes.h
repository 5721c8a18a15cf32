#pragma once
// One source for scalar and SIMD maths: kernels written as templates on T
// run on T = double (one tensor) or T = Lanes4 (four tensors at once, GCC's
// vector extension). Comparisons give masks, `c ? a : b` blends, and `&&`,
// `||`, `!` combine masks in both cases, so a kernel has no branches and
// one text serves both. Only the functions below differ by type.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>

namespace tg::tensor {

using Lanes4 = double __attribute__((vector_size(32)));

// On a function that runs lane kernels: GCC builds an AVX2 clone (a Lanes4
// op is one instruction) next to the baseline x86-64 one and picks at load
// time, so the binary still runs on any x86-64. Elsewhere Lanes4 is lowered
// to what the target has.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define TG_LANE_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TG_LANE_CLONES
#endif
inline constexpr std::size_t kLanes = 4;

template <class T>
[[gnu::always_inline]] inline T splat(double x) {
  if constexpr (std::is_same_v<T, double>) return x;
  else return T{} + x;
}

// Lane by lane: GCC emits one vsqrtpd for the loop under AVX.
template <class T>
[[gnu::always_inline]] inline T lsqrt(T x) {
  if constexpr (std::is_same_v<T, double>) {
    return std::sqrt(x);
  } else {
    T r;
    for (std::size_t i = 0; i < kLanes; ++i) r[i] = __builtin_sqrt(x[i]);
    return r;
  }
}

template <class T>
[[gnu::always_inline]] inline T labs(T x) {
  return x < splat<T>(0.0) ? -x : x;
}
template <class T>
[[gnu::always_inline]] inline T lmin(T a, T b) {
  return b < a ? b : a;
}
template <class T>
[[gnu::always_inline]] inline T lmax(T a, T b) {
  return a < b ? b : a;
}

// Four consecutive doubles, and back (unaligned). Templates, so that a file
// that includes this header without using them makes no AVX-typed function.
template <class T = Lanes4>
[[gnu::always_inline]] inline T load4(const double* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class T = Lanes4>
[[gnu::always_inline]] inline void store4(double* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

template <class T>
struct V3 {
  T x, y, z;
};
template <class T>
[[gnu::always_inline]] inline V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
[[gnu::always_inline]] inline T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
[[gnu::always_inline]] inline V3<T> mul(const V3<T>& a, T s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class T, class M>
[[gnu::always_inline]] inline V3<T> blend(M m, const V3<T>& a, const V3<T>& b) {
  return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}

}  // namespace tg::tensor
