#ifndef signorini_problem_parameters_h
#define signorini_problem_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/friction_parameters.h>
#include <signorini/contact/obstacle.h>
#include <signorini/discretisation/boundary_conditions.h>
#include <signorini/discretisation/geometry.h>
#include <signorini/elasticity/linear_solver_parameters.h>
#include <signorini/elasticity/material.h>
#include <signorini/input/parameter_file.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>
#include <signorini/output/checkpoint.h>
#include <signorini/output/output_parameters.h>
#include <signorini/postprocessing/reference.h>
#include <signorini/problem/load_history.h>

#include <string>
#include <vector>

namespace signorini
{
  /** The space dimension of a parameter file that does not set
   * `Dimension`. */
  constexpr unsigned int default_dimension = 2;

  /** Declares every entry of a signorini parameter file, `Dimension`
   * included, with the defaults of @p dim space dimensions. */
  void
  declare_parameters(dealii::ParameterHandler &prm, const unsigned int dim);

  /** The value of `Dimension` in @p input. Throws an InputError for the
   * first error of @p input, as reading all entries would. */
  unsigned int
  read_dimension(const ParameterFile &input);

  /** All parameters of a run in @p dim space dimensions. */
  template <int dim>
  struct Parameters
  {
    Geometry<dim>           geometry;
    Material                material;
    BoundaryConditions<dim> boundary_conditions;
    ObstacleParameters<dim> obstacle;
    ContactParameters       contact;
    FrictionParameters      friction;
    LinearSolverParameters  linear_solver;
    Refinement              refinement;
    LoadHistory             load_history;
    OutputParameters<dim>   output;
    Reference<dim>          reference;
    CheckpointParameters    checkpoint;

    /** The parameter set as read, every entry in ShortPRM form, the mesh
     * file named by its absolute path: what parameters.prm holds and
     * checkpoints compare. */
    std::string text;

    /** Reads every component from @p prm, which holds the entries of a
     * parameter file declared by declare_parameters() for @p dim; relative
     * file names are looked for in @p folders, in order. Throws
     * InputError. */
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &folders);
  };
} // namespace signorini

#endif
