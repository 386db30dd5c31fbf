#include "kernels/SimdCopies.hpp"

#include <cstdlib>
#include <string_view>

namespace chute::kernels {

bool avx2Available() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}

bool useAvx2() {
  static const bool use = [] {
    const char* want = std::getenv("CHUTE_SIMD");
    return avx2Available() && !(want && std::string_view(want) == "baseline");
  }();
  return use;
}

}  // namespace chute::kernels
