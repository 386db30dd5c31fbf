#pragma once
// GCC's vector extension for the explicit step's batched kernels (MembraneTriangleBatch,
// CableBatch): four doubles and four 64-bit masks (all bits set: true), with the loads, stores
// and lane-wise functions they share. On the baseline instruction set each operation is made of
// two SSE2 ones, on AVX2 of one. Internal to those kernels' .cpp files.
#include <cstdint>
#include <cstring>

// GCC warns that a 32-byte vector returned without AVX changes the calling convention; these
// vectors live only inside the kernels' inlined bodies and their helpers, never across a call
// (the helpers take them by reference: by value GCC notes the parameters' convention).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace chute::kernels::lanes {

constexpr int kLanes = 4;
using V = double __attribute__((vector_size(8 * kLanes)));
using M = std::int64_t __attribute__((vector_size(8 * kLanes)));

[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline M loadMask(const std::int64_t* p) {
  M v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store(double* p, const V& v) {
  std::memcpy(p, &v, sizeof v);
}
[[gnu::always_inline]] inline V all(double s) {
  return V{s, s, s, s};
}
[[gnu::always_inline]] inline V sqrt(const V& a) {
  V r;
  for (int l = 0; l < kLanes; ++l) r[l] = __builtin_sqrt(a[l]);
  return r;
}
[[gnu::always_inline]] inline V abs(const V& a) {
  V r;
  for (int l = 0; l < kLanes; ++l) r[l] = __builtin_fabs(a[l]);
  return r;
}

}  // namespace chute::kernels::lanes
