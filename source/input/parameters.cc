#include <signorini/input/parameters.h>

namespace signorini
{
  using namespace dealii;

  void
  declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Dimension",
      "2",
      Patterns::Integer(2, 3),
      "Space dimension: 2 (plane strain or plane stress) or 3.");
    Geometry<2>::declare_parameters(prm);
    Material::declare_parameters(prm);
    BoundaryConditions<2>::declare_parameters(prm);
    Obstacle<2>::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
    Refinement::declare_parameters(prm);
    OutputParameters<2>::declare_parameters(prm);
    Reference<2>::declare_parameters(prm);
    CheckpointParameters::declare_parameters(prm);
  }

  template <int dim>
  void
  Parameters<dim>::parse_parameters(ParameterHandler               &prm,
                                    const std::vector<std::string> &folders)
  {
    geometry.parse_parameters(prm, folders);
    material.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    obstacle.parse_parameters(prm);
    contact.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    refinement.parse_parameters(prm);
    output.parse_parameters(prm);
    reference.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
  }

  template struct Parameters<2>;
  template struct Parameters<3>;
} // namespace signorini
