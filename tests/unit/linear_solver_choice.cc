// What Linear solver/Type = automatic solves the assembled system with
// (LinearSolverParameters::resolved_type): direct in 2D on one process below
// 100,000 dofs, amg cg from there, in 3D and on several processes; direct
// and amg cg as given; matrix-free's remedy as automatic. Each choice is
// checked against that rule, written out here.

#include <signorini/elasticity/linear_solver_parameters.h>

#include "checks.h"
#include <iostream>
#include <string>
#include <utility>

using namespace signorini;

namespace
{
  std::string
  name(const LinearSolverParameters::Type type)
  {
    switch (type)
      {
        case LinearSolverParameters::Type::direct:
          return "direct";
        case LinearSolverParameters::Type::amg_cg:
          return "amg cg";
        default:
          return "other";
      }
  }
} // namespace

int
main()
{
  using Type             = LinearSolverParameters::Type;
  unsigned int n_checked = 0, n_right = 0;
  for (const auto &[type, label] : {std::pair{Type::automatic, "automatic"},
                                    std::pair{Type::matrix_free, "matrix-free"},
                                    std::pair{Type::direct, "direct"},
                                    std::pair{Type::amg_cg, "amg cg"}})
    {
      LinearSolverParameters parameters;
      parameters.type = type;
      std::cout << label << ":\n";
      for (const unsigned int dim : {2u, 3u})
        for (const unsigned int processes : {1u, 2u})
          for (const unsigned int dofs : {99999u, 100000u})
            {
              const auto chosen =
                parameters.resolved_type(dim, processes, dofs);
              // The rule: automatic (and the matrix-free path's remedy)
              // solve directly in 2D on one process below 100,000 dofs.
              const bool small = dim == 2 && processes == 1 && dofs < 100000;
              const Type expected =
                (type == Type::automatic || type == Type::matrix_free) ?
                  (small ? Type::direct : Type::amg_cg) :
                  type;
              ++n_checked;
              n_right += chosen == expected;
              std::cout << "  " << dim << "D, " << processes << " process"
                        << (processes > 1 ? "es" : "") << ", " << dofs
                        << " dofs: " << name(chosen)
                        << (chosen == expected ?
                              "" :
                              " (FAILED: the rule says " + name(expected) + ")")
                        << '\n';
            }
    }
  checks::expect("each of the " + std::to_string(n_checked) +
                   " choices is the rule's",
                 n_right == n_checked);
}
