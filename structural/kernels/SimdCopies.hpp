#pragma once
// Which copy the explicit step's batched kernels run (MembraneTriangleBatch):
// each is built once for the baseline instruction set and once for AVX2, and both give the same
// bits (neither fuses a multiply and an add).
namespace chute::kernels {
// Whether the processor has AVX2.
bool avx2Available();
// The AVX2 copies where the processor has AVX2, unless the environment's CHUTE_SIMD is
// "baseline" (for measuring what they give, docs/performance.md). Read once.
bool useAvx2();
}  // namespace chute::kernels
