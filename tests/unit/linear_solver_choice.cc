// What Linear solver/Type = automatic solves the assembled system with
// (LinearSolverParameters::resolved_type): direct in 2D on one process below
// 100,000 dofs, amg cg from there, in 3D and on several processes; direct
// and amg cg as given; matrix-free's remedy as automatic.

#include <signorini/elasticity/linear_solver_parameters.h>

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
  using Type = LinearSolverParameters::Type;
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
            std::cout << "  " << dim << "D, " << processes << " process"
                      << (processes > 1 ? "es" : "") << ", " << dofs
                      << " dofs: "
                      << name(parameters.resolved_type(dim, processes, dofs))
                      << '\n';
    }
}
