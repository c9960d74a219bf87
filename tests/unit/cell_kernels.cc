// The copy of the cell kernels the processor runs is the widest its
// features allow: AVX-512 where it has AVX512F, AVX2 with FMA where it has
// those (x86-64-v3), SSE2 otherwise. The choice by the processor's name
// (`arch=haswell`) gave SSE2 on every AMD processor and on Intel ones after
// Haswell without AVX-512.

#include <signorini/elasticity/cell_matrices.h>

#include <iostream>
#include <string>

int
main()
{
  std::string expected = "default";
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f"))
    expected = "avx512f";
  else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
           __builtin_cpu_supports("bmi2"))
    expected = "x86-64-v3";
#endif
  const std::string chosen = signorini::cell_kernel_instruction_set();
  std::cout << "the cell kernels' copy is the widest the processor's "
               "features allow: "
            << (chosen == expected ?
                  "yes" :
                  "no (" + chosen + " instead of " + expected + ")")
            << '\n';
}
