#ifndef signorini_contact_obstacle_h
#define signorini_contact_obstacle_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <ostream>
#include <set>
#include <string>

namespace signorini
{
  /**
   * A rigid obstacle: for a point of the body, how far it is from the
   * obstacle's surface and in which direction the surface faces it.
   *
   * The normal n is the obstacle's outward unit normal (pointing from the
   * obstacle towards the body). A displacement u of the point changes its
   * gap g to g + n.u; the body may not penetrate, g + n.u >= 0, and the
   * obstacle pushes back along n.
   */
  template <int dim>
  class Obstacle
  {
  public:
    virtual ~Obstacle() = default;

    /** The gap of @p point [mm] (negative inside the obstacle) and, in
     * @p normal, the obstacle's outward unit normal there. */
    virtual double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const = 0;

    /** The parameter entry that describes the obstacle, for messages. */
    virtual std::string
    entry() const = 0;

    /** Writes the obstacle's surface around @p box (the body's bounding box)
     * as a VTU mesh for ParaView. */
    virtual void
    write_vtu(std::ostream &out, const dealii::BoundingBox<dim> &box) const = 0;
  };

  /**
   * The rigid obstacle and where it may touch the body: subsection
   * `Obstacle`. Its surface is the graph of a height function, y = psi(x)
   * in 2D and z = psi(x, y) in 3D (HeightObstacle); only the boundary ids in
   * `Contact boundary ids` may touch it.
   */
  template <int dim>
  struct ObstacleParameters
  {
    /** The expression of psi [mm] of x (2D) or x, y (3D). */
    std::string height_expression = "0";
    /** psi, parsed. */
    std::unique_ptr<dealii::FunctionParser<dim - 1>> height;
    std::set<dealii::types::boundary_id>             contact_ids = {2};

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /** The obstacle that @p parameters describe. */
  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const ObstacleParameters<dim> &parameters);
} // namespace signorini

#endif
