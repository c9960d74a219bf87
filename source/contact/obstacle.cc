#include <signorini/contact/height_obstacle.h>
#include <signorini/contact/obstacle.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ObstacleParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    const ObstacleParameters<dim> defaults;
    prm.enter_subsection("Obstacle");
    prm.declare_entry("Height",
                      defaults.height_expression,
                      Patterns::Anything(),
                      "Surface of the rigid obstacle [mm]: y = psi(x) in 2D, "
                      "z = psi(x, y) in 3D, a muparser expression, e.g. "
                      "'-0.15' (flat) or '-sqrt(4 - x^2)' (cylinder).");
    prm.declare_entry("Contact boundary ids",
                      entry_text::of(
                        std::vector<unsigned int>(defaults.contact_ids.begin(),
                                                  defaults.contact_ids.end())),
                      Patterns::Anything(),
                      "Boundary ids (','-separated) that may touch the "
                      "obstacle.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ObstacleParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Obstacle");
    height_expression = prm.get("Height");
    height = parse_function<dim - 1>(height_expression, 1, "Obstacle/Height");
    contact_ids = parse::boundary_ids(prm.get("Contact boundary ids"),
                                      "Obstacle/Contact boundary ids");
    prm.leave_subsection();
  }

  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const ObstacleParameters<dim> &parameters)
  {
    return std::make_unique<HeightObstacle<dim>>(*parameters.height);
  }

  template struct ObstacleParameters<2>;
  template struct ObstacleParameters<3>;
  template std::unique_ptr<Obstacle<2>>
  create_obstacle(const ObstacleParameters<2> &);
  template std::unique_ptr<Obstacle<3>>
  create_obstacle(const ObstacleParameters<3> &);
} // namespace signorini
