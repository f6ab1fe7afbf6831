#pragma once
// The instruction set the hottest solid kernel runs on. Debian builds for generic x86-64 (SSE2: two
// doubles per operation), so the compiler never emits AVX2 on its own; the Hex8 Enhanced evaluation
// (EnhancedStrainElement.hpp, kDispatched) is therefore compiled twice, once as the rest of the program
// and once for AVX2 (GCC's target attribute, everything it calls inlined into it), and each evaluation
// picks one here at run time. The same binary runs on any x86-64 and operates on four doubles at once
// where the processor can (bench/README.md, issue 23 sixth round). Every law's 3D point loop is
// dispatched the same way (Material.hpp, MaterialLaw::atPointsAvx2; seventh round), since the kernel
// calls it virtually. The two give the same bits: Hex8.cpp and the laws' files are compiled without
// contraction into fused multiply-adds (CMakeLists.txt), and vectorisation keeps the order of every sum.
//
// CONTESSA_KERNEL_ISA=generic in the environment keeps the generic code on any processor (a run to
// compare against); CONTESSA_KERNEL_ISA=avx2 or unset chooses by the processor.
#if (defined(__x86_64__) || defined(_M_X64)) && defined(__GNUC__)
#define CONTESSA_KERNEL_AVX2 1
/// Compiles a function for AVX2 with every call inside it inlined (so that no helper is left
/// out of line in the generic instruction set, and no AVX2 helper can be shared with the generic code).
#define CONTESSA_TARGET_AVX2 __attribute__((target("avx2"), flatten))
#else
#define CONTESSA_KERNEL_AVX2 0
#define CONTESSA_TARGET_AVX2
#endif

namespace contessa::mechanics {

enum class KernelIsa { Generic, Avx2 };

/// Whether this build and this processor can run the AVX2 kernels.
bool avx2Available();

/// The instruction set the dispatched kernels use now: Avx2 where available, unless the environment
/// says CONTESSA_KERNEL_ISA=generic or setKernelIsa chose otherwise.
KernelIsa kernelIsa();

/// Chooses the instruction set (the unit tests run each dispatched kernel under both). False, and no
/// change, when Avx2 is asked for where it is not available.
bool setKernelIsa(KernelIsa isa);

}  // namespace contessa::mechanics
