#ifndef signorini_input_parameters_h
#define signorini_input_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/obstacle.h>
#include <signorini/discretisation/geometry.h>
#include <signorini/elasticity/boundary_conditions.h>
#include <signorini/elasticity/linear_solver_parameters.h>
#include <signorini/elasticity/material.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>
#include <signorini/output/checkpoint.h>
#include <signorini/output/output_parameters.h>
#include <signorini/postprocessing/reference.h>

#include <string>
#include <vector>

namespace signorini
{
  /** Declares every entry of a signorini parameter file, `Dimension`
   * included. */
  void
  declare_parameters(dealii::ParameterHandler &prm);

  /** All parameters of a run in @p dim space dimensions. */
  template <int dim>
  struct Parameters
  {
    Geometry<dim>           geometry;
    Material                material;
    BoundaryConditions<dim> boundary_conditions;
    ObstacleParameters<dim> obstacle;
    ContactParameters       contact;
    LinearSolverParameters  linear_solver;
    Refinement              refinement;
    OutputParameters<dim>   output;
    Reference<dim>          reference;
    CheckpointParameters    checkpoint;

    /** Reads every component from @p prm; relative file names are looked
     * for in @p folders, in order. Throws InputError. */
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &folders);
  };
} // namespace signorini

#endif
