#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <signorini/contact/height_obstacle.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  HeightObstacle<dim>::HeightObstacle(const Function<dim - 1> &height)
    : height(height)
  {
  }

  template <int dim>
  double
  HeightObstacle<dim>::height_at(const Point<dim> &point) const
  {
    Point<dim - 1> horizontal;
    for (unsigned int d = 0; d < dim - 1; ++d)
      horizontal[d] = point[d];
    return height.value(horizontal);
  }

  template <int dim>
  double
  HeightObstacle<dim>::gap(const Point<dim> &point,
                           Tensor<1, dim>   &normal) const
  {
    normal          = Tensor<1, dim>();
    normal[dim - 1] = 1.;
    return point[dim - 1] - height_at(point);
  }

  template <int dim>
  std::string
  HeightObstacle<dim>::entry() const
  {
    return "Obstacle/Height";
  }

  template <int dim>
  void
  HeightObstacle<dim>::write_vtu(std::ostream           &out,
                                 const BoundingBox<dim> &box) const
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
        Point<dim> q = p;
        q[dim - 1]   = height_at(p);
        return q;
      },
      surface);
    GridOut().write_vtu(surface, out);
  }

  template class HeightObstacle<2>;
  template class HeightObstacle<3>;
} // namespace signorini
