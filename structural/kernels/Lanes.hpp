#pragma once
// Four doubles side by side for the explicit step's batched kernels (MembraneTriangleBatch): GCC's
// vector extension, which the baseline instruction set makes of two SSE2 operations and AVX2 of
// one. Included only by those kernels' source files, whose vectors live inside inlined bodies
// and never cross a call: GCC warns that a 32-byte vector returned without AVX changes the
// calling convention, which is why the warning is off where this is included; the helpers take
// vectors by reference (by value GCC notes the parameters' convention).
// useAvx2() (SimdCopies.hpp) picks the copy a kernel runs.
#include <cstdint>
#include <cstring>

#include "kernels/SimdCopies.hpp"

#pragma GCC diagnostic ignored "-Wpsabi"

namespace chute::kernels::lanes {

constexpr int kLanes = 4;
using V = double __attribute__((vector_size(32)));
using M = std::int64_t __attribute__((vector_size(32)));

[[gnu::always_inline]] inline V load(const double* p) {
  V v;
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

}  // namespace chute::kernels::lanes
