#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <signorini/contact/obstacle.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  Obstacle<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Obstacle");
    prm.declare_entry("Height",
                      "0",
                      Patterns::Anything(),
                      "Surface of the rigid obstacle [mm]: y = psi(x) in 2D, "
                      "z = psi(x, y) in 3D, a muparser expression, e.g. "
                      "'-0.15' (flat) or '-sqrt(4 - x^2)' (cylinder).");
    prm.declare_entry("Contact boundary ids",
                      "2",
                      Patterns::Anything(),
                      "Boundary ids (','-separated) that may touch the "
                      "obstacle.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Obstacle<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Obstacle");
    height = parse_function<dim - 1>(prm.get("Height"), 1, "Obstacle/Height");
    contact_ids = parse::boundary_ids(prm.get("Contact boundary ids"),
                                      "Obstacle/Contact boundary ids");
    prm.leave_subsection();
  }

  template <int dim>
  double
  Obstacle<dim>::gap(const Point<dim> &p) const
  {
    Point<dim - 1> horizontal;
    for (unsigned int d = 0; d < dim - 1; ++d)
      horizontal[d] = p[d];
    return p[dim - 1] - height->value(horizontal);
  }

  template <int dim>
  void
  Obstacle<dim>::write_vtu(std::ostream &out, const BoundingBox<dim> &box) const
  {
    Point<dim - 1>            lower, upper;
    std::vector<unsigned int> subdivisions(dim - 1, dim == 2 ? 400 : 80);
    for (unsigned int d = 0; d < dim - 1; ++d)
      {
        const double margin = 0.1 * box.side_length(d);
        lower[d]            = box.lower_bound(d) - margin;
        upper[d]            = box.upper_bound(d) + margin;
      }
    Triangulation<dim - 1> flat;
    GridGenerator::subdivided_hyper_rectangle(flat, subdivisions, lower, upper);
    Triangulation<dim - 1, dim> surface;
    GridGenerator::flatten_triangulation(flat, surface);
    GridTools::transform(
      [this](const Point<dim> &p) {
        Point<dim - 1> horizontal;
        for (unsigned int d = 0; d < dim - 1; ++d)
          horizontal[d] = p[d];
        Point<dim> q = p;
        q[dim - 1]   = height->value(horizontal);
        return q;
      },
      surface);
    GridOut().write_vtu(surface, out);
  }

  template struct Obstacle<2>;
  template struct Obstacle<3>;
} // namespace signorini
