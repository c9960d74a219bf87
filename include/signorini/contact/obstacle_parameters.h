#ifndef signorini_contact_obstacle_parameters_h
#define signorini_contact_obstacle_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <signorini/input/time_vector.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace signorini
{
  /** Subsections `Obstacle`, `Obstacle 2`, ..., up to this many. */
  constexpr unsigned int max_obstacles = 4;

  /**
   * One rigid obstacle of the scene as its subsection describes it: its
   * kind and the entries of that kind, checked (required entries given,
   * entries of other kinds not given, no zero normal or axis).
   */
  template <int dim>
  struct ObstacleDescription
  {
    enum class Type
    {
      none,
      height,
      plane,
      sphere,
      cylinder,
      punch,
      signed_distance,
      geometry_file
    };

    /** The subsection, `Obstacle` or `Obstacle N`, and N (1 for
     * `Obstacle`). */
    std::string  section = "Obstacle";
    unsigned int number  = 1;
    Type         type    = Type::height;

    /** height: psi [mm] of x (2D) or x, y (3D). */
    std::string                                      height_expression = "0";
    std::unique_ptr<dealii::FunctionParser<dim - 1>> height;
    /** plane: a point of the plane [mm] and its outward unit normal;
     * punch: the outward unit normal of its flat end. */
    dealii::Point<dim>     point;
    dealii::Tensor<1, dim> normal;
    /** sphere, cylinder, punch: center (of the flat end for a punch) [mm],
     * unit axis (cylinder in 3D), radius [mm]. */
    dealii::Point<dim>     center;
    dealii::Tensor<1, dim> axis;
    double                 radius = 0.;
    /** sphere, cylinder, geometry file: the body lies inside the obstacle's
     * surface (a shaft in a bore, a ball in a cup). */
    bool body_inside = false;
    /** signed distance: the expression [mm] of x, y[, z]. */
    std::string                                  distance_expression;
    std::unique_ptr<dealii::FunctionParser<dim>> distance;
    /** geometry file: the file, with its folder. */
    std::string geometry_file;
    /** The obstacle's rigid translation from where its entries put it
     * [mm], a function of the pseudo-time t of the load history. */
    TimeVector<dim> displacement;

    /** "SECTION/NAME", for messages. */
    std::string
    entry(const std::string &name) const;

    /** The entry that places the obstacle (`Obstacle 2/Center`, ...). */
    std::string
    placing_entry() const;

    /** Whether the body may start inside the obstacle: an obstacle height
     * may be given pressed into the body (step-42's convention). */
    bool
    may_start_inside() const;
  };

  /**
   * The rigid obstacles and where they may touch the body: subsections
   * `Obstacle` (the first obstacle, and the contact boundary ids) and
   * `Obstacle 2` ... `Obstacle 4` (further obstacles, absent unless their
   * Type is set). An obstacle is a height function (HeightObstacle), a
   * plane, a sphere, a cylinder, a signed-distance expression or the solid
   * of a geometry file.
   */
  template <int dim>
  struct ObstacleParameters
  {
    /** The obstacles whose Type is not none, in the order of their
     * subsections. */
    std::vector<ObstacleDescription<dim>> obstacles;
    std::set<dealii::types::boundary_id>  contact_ids = {2};

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Reads every subsection; a geometry file is looked for in @p folders,
     * in order. Throws InputError. */
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &folders = {"."});
  };
} // namespace signorini

#endif
