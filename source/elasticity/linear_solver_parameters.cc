#include <signorini/elasticity/linear_solver_parameters.h>

#include <algorithm>

namespace signorini
{
  using namespace dealii;

  void
  LinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "automatic",
                      Patterns::Selection("automatic|direct|amg cg"),
                      "direct: sparse LU (Trilinos Amesos MUMPS); amg cg: "
                      "conjugate gradients with algebraic multigrid (Trilinos "
                      "ML); automatic: direct in 2D on one process, amg cg "
                      "in 3D and on several processes, the faster choice as "
                      "measured (see README).");
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0.),
                      "amg cg: residual reduction relative to the right-hand "
                      "side.");
    prm.declare_entry("Newton tolerance",
                      "1e-4",
                      Patterns::Double(0.),
                      "amg cg: residual reduction, relative to the "
                      "right-hand side, of the Newton steps taken while the "
                      "active set still changes (an inexact Newton method), "
                      "and by a factor of 10 at least; once an update "
                      "leaves the active set as it was, the next step is "
                      "solved to Tolerance.");
    prm.declare_entry("Maximum iterations",
                      "2000",
                      Patterns::Integer(1),
                      "amg cg: iterations allowed per solve.");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse_parameters(ParameterHandler  &prm,
                                           const unsigned int dim,
                                           const unsigned int n_processes)
  {
    prm.enter_subsection("Linear solver");
    const std::string name              = prm.get("Type");
    const bool        direct_by_default = dim == 2 && n_processes == 1;
    type      = name == "direct" || (name == "automatic" && direct_by_default) ?
                  Type::direct :
                  Type::amg_cg;
    tolerance = prm.get_double("Tolerance");
    max_iterations   = prm.get_integer("Maximum iterations");
    newton_tolerance = std::max(prm.get_double("Newton tolerance"), tolerance);
    prm.leave_subsection();
  }

} // namespace signorini
