// The copy of the cell kernels the processor runs is the widest its
// features allow: AVX-512 where it has AVX512F, AVX2 with FMA where it has
// those (x86-64-v3), SSE2 otherwise. The choice by the processor's name
// (`arch=haswell`) gave SSE2 on every AMD processor and on Intel ones after
// Haswell without AVX-512. Whichever copy runs, CellMatrices::apply computes
// y = K x: in double precision to the round-off of a sum of n products
// (relative 1e-14 of sum |K_ij x_j|), in single precision (the matrix
// rounded to float) to that of floats (1e-5), for Q1's quadrilaterals (n = 8)
// and hexahedra (n = 24) and Q2's (n = 18 and 81, stored with their columns
// padded to 24 and 96 entries), for several matrices, each found by its key,
// and matrix() gives each entry back at its padded place.
// (tests/processor/ runs this and every test on the other copies.)

#include <signorini/elasticity/cell_matrices.h>

#include "checks.h"
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace signorini;

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
  if (chosen != expected)
    checks::failed();

  for (const unsigned int n : {8u, 24u, 18u, 81u})
    {
      CellMatrices matrices;
      matrices.reinit(n);
      double worst = 0., worst_single = 0.;
      bool   found = true, stored = true;
      for (unsigned int m = 0; m < 3; ++m)
        {
          // A symmetric matrix with entries of both signs and of sizes
          // from 1e-3 to 1e3, and a vector of both signs.
          std::vector<double> K(n * n);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j <= i; ++j)
              K[i * n + j] = K[j * n + i] =
                std::sin(1.3 * i + 0.7 * j + m) *
                std::pow(10.,
                         static_cast<double>((i * 7 + j * 3 + m) % 7) - 3.);
          const unsigned int index = matrices.add({1. + m, 0.5, 0., 2.}, K);
          found                    = found && index == m &&
                  matrices.find({1. + m, 0.5, 0., 2.}) == index;
          const double      *kept   = matrices.matrix(index);
          const unsigned int stride = matrices.column_stride();
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int i = 0; i < stride; ++i)
              stored =
                stored && kept[j * stride + i] == (i < n ? K[j * n + i] : 0.);
          std::vector<double> x(n), y(n);
          std::vector<float>  xf(n), yf(n);
          for (unsigned int j = 0; j < n; ++j)
            xf[j] = static_cast<float>(x[j] = std::cos(2.1 * j + m) * (j + 1));
          matrices.apply(index, x.data(), y.data());
          matrices.apply(index, xf.data(), yf.data());
          for (unsigned int i = 0; i < n; ++i)
            {
              long double exact = 0., size = 0.;
              for (unsigned int j = 0; j < n; ++j)
                {
                  exact += static_cast<long double>(K[j * n + i]) * x[j];
                  size +=
                    std::abs(static_cast<long double>(K[j * n + i]) * x[j]);
                }
              worst =
                std::max(worst,
                         static_cast<double>(std::abs(y[i] - exact) / size));
              worst_single =
                std::max(worst_single,
                         static_cast<double>(std::abs(yf[i] - exact) / size));
            }
        }
      std::cout << "n = " << n << ", 3 matrices:\n";
      checks::expect("each matrix found by its key", found);
      checks::expect("each entry stored at its place, zeros between", stored);
      checks::expect("a key not stored is not found",
                     matrices.find({9., 0.5, 0., 2.}) == CellMatrices::none);
      checks::report("max |K x - exact| / sum |K_ij x_j|, double",
                     worst,
                     1e-14);
      // (Not printed: its digits differ between the copies.)
      checks::expect("max |K x - exact| / sum |K_ij x_j|, float, below 1e-5",
                     worst_single <= 1e-5);
    }
}
