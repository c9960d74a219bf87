#ifndef signorini_contact_obstacle_h
#define signorini_contact_obstacle_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <ostream>
#include <set>

namespace signorini
{
  /**
   * The rigid obstacle: subsection `Obstacle`. Its surface is the graph of a
   * height function, y = psi(x) in 2D and z = psi(x, y) in 3D, and the body
   * approaches it from above (along -y, -z). Only the boundary ids listed in
   * `Contact boundary ids` may touch it.
   */
  template <int dim>
  struct Obstacle
  {
    std::unique_ptr<dealii::FunctionParser<dim - 1>> height;
    std::set<dealii::types::boundary_id>             contact_ids;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** The initial gap of the point @p p: its height above the obstacle
     * (negative if it starts inside). */
    double
    gap(const dealii::Point<dim> &p) const;

    /** Writes the surface over the horizontal extent of @p box (enlarged by
     * a tenth on each side) as a VTU mesh. */
    void
    write_vtu(std::ostream &out, const dealii::BoundingBox<dim> &box) const;
  };
} // namespace signorini

#endif
