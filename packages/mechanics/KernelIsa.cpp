#include "mechanics/KernelIsa.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace contessa::mechanics {

namespace {

KernelIsa initialIsa() {
  const char* asked = std::getenv("CONTESSA_KERNEL_ISA");
  if (asked && std::strcmp(asked, "generic") == 0) return KernelIsa::Generic;
  if (asked && *asked && std::strcmp(asked, "avx2") != 0)
    std::fprintf(stderr, "contessa: warning: CONTESSA_KERNEL_ISA=%s is neither generic nor avx2; choosing by the processor\n",
                 asked);
  return avx2Available() ? KernelIsa::Avx2 : KernelIsa::Generic;
}

std::atomic<KernelIsa>& chosen() {
  static std::atomic<KernelIsa> isa{initialIsa()};
  return isa;
}

}  // namespace

bool avx2Available() {
#if CONTESSA_KERNEL_AVX2
  static const bool available = __builtin_cpu_supports("avx2");
  return available;
#else
  return false;
#endif
}

KernelIsa kernelIsa() { return chosen().load(std::memory_order_relaxed); }

bool setKernelIsa(KernelIsa isa) {
  if (isa == KernelIsa::Avx2 && !avx2Available()) return false;
  chosen().store(isa, std::memory_order_relaxed);
  return true;
}

}  // namespace contessa::mechanics
