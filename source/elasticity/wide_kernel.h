// SIGNORINI_WIDE_KERNEL: one copy of a function per instruction set, chosen
// by the processor the program runs on (GCC's function multi-versioning):
// Debian's deal.II is compiled for the baseline x86-64, whose registers
// hold two doubles. The AVX2 copy is chosen by the processor's features
// (x86-64-v3: AVX2 and FMA), not by its name: `arch=haswell` asks whether
// the processor is a Haswell, so every AMD processor and every later Intel
// one without AVX-512 ran the two-double copy (an AMD EPYC, Zen 3: CG of
// the 1.49M-dof run 19.7 -> 17.1 s on one process, the whole run 49.5 ->
// 45.6 s). Private to source/elasticity.
#ifndef signorini_source_elasticity_wide_kernel_h
#define signorini_source_elasticity_wide_kernel_h

#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#  define SIGNORINI_AVX512 "avx512f"
#  define SIGNORINI_AVX2 "arch=x86-64-v3"
#  define SIGNORINI_WIDE_KERNEL \
    __attribute__((target_clones(SIGNORINI_AVX512, SIGNORINI_AVX2, "default")))
#else
#  define SIGNORINI_WIDE_KERNEL
#endif

#endif
