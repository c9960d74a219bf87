#ifndef signorini_discretisation_boundary_conditions_h
#define signorini_discretisation_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/component_mask.h>

#include <signorini/input/time_vector.h>

#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * Loads and supports: subsection `Boundary conditions`.
   *
   * - `Dirichlet = 0: xy; 1: y` fixes the listed displacement components on
   *   each boundary id (`all` for every component) to `Prescribed
   *   displacement`.
   * - `Traction` acts on the boundary ids in `Traction boundary ids`; or,
   *   with `Traction resultant`, a uniform traction whose resultant is that
   *   force on every mesh, however faceted its curved boundaries.
   * - `Body force` acts in the whole body.
   *
   * Functions are muparser expressions of x, y[, z] and the pseudo-time t
   * of the load history, one per component separated by ';', or one
   * expression for all components; their time is set by the problem
   * (FunctionTime::set_time) for each load step. The traction resultant's
   * components are numbers or expressions of t.
   */
  template <int dim>
  struct BoundaryConditions
  {
    std::vector<std::pair<dealii::types::boundary_id, dealii::ComponentMask>>
                                                 dirichlet;
    std::unique_ptr<dealii::FunctionParser<dim>> prescribed_displacement;
    std::set<dealii::types::boundary_id>         traction_ids;
    std::unique_ptr<dealii::FunctionParser<dim>> traction;
    /** The force [N] the uniform traction adds up to, if given, as a
     * function of t. */
    std::optional<TimeVector<dim>>               traction_resultant;
    std::unique_ptr<dealii::FunctionParser<dim>> body_force;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
