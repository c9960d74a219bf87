#ifndef signorini_parameters_h
#define signorini_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/boundary_conditions.h>
#include <signorini/checkpoint.h>
#include <signorini/contact_parameters.h>
#include <signorini/geometry.h>
#include <signorini/linear_solver.h>
#include <signorini/material.h>
#include <signorini/obstacle.h>
#include <signorini/output_parameters.h>
#include <signorini/reference.h>
#include <signorini/refinement.h>

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
    Obstacle<dim>           obstacle;
    ContactParameters       contact;
    LinearSolver            linear_solver;
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
