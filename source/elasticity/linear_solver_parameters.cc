#include <signorini/elasticity/linear_solver_parameters.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>

#include <algorithm>

namespace signorini
{
  using namespace dealii;

  void
  LinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    const LinearSolverParameters defaults;
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      types().name(defaults.type),
                      types().pattern(),
                      types().documentation());
    prm.declare_entry("Tolerance",
                      entry_text::of(defaults.tolerance),
                      Patterns::Double(0.),
                      "amg cg: residual reduction relative to the right-hand "
                      "side.");
    prm.declare_entry("Newton tolerance",
                      entry_text::of(defaults.newton_tolerance),
                      Patterns::Double(0.),
                      "amg cg: residual reduction, relative to the "
                      "right-hand side, of the Newton steps taken while the "
                      "active set still changes (an inexact Newton method), "
                      "and by a factor of 10 at least; once an update "
                      "leaves the active set as it was, the next step is "
                      "solved to Tolerance.");
    prm.declare_entry("Maximum iterations",
                      entry_text::of(defaults.max_iterations),
                      Patterns::Integer(1),
                      "amg cg: iterations allowed per solve.");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type           = types().value(prm.get("Type"), "Linear solver/Type");
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    newton_tolerance =
      std::max(parse::in_range(prm.get_double("Newton tolerance"),
                               parse::Range::closed_open(0., 1.),
                               "Linear solver/Newton tolerance",
                               "a residual reduction"),
               tolerance);
    prm.leave_subsection();
    parse::in_range(tolerance,
                    parse::Range::open(0., 1.),
                    "Linear solver/Tolerance",
                    "a residual reduction");
  }

  LinearSolverParameters::Type
  LinearSolverParameters::resolved_type(
    const unsigned int            dim,
    const unsigned int            n_processes,
    const types::global_dof_index n_dofs) const
  {
    if (type != Type::automatic && type != Type::matrix_free)
      return type;
    return dim == 2 && n_processes == 1 && n_dofs < direct_below ?
             Type::direct :
             Type::amg_cg;
  }
} // namespace signorini
