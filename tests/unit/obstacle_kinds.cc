// The obstacle kinds beside the height: gap and outward normal of points
// outside, on and inside a plane, a sphere and a cylinder (body outside and
// inside), a flat-ended punch (under its end, at and beyond its rim, beside
// it), a signed-distance expression (a level set that is not a
// distance) and the solid of a geometry file (an OpenCASCADE disk and ball
// from .geo files Gmsh exports), each against its closed form; an
// ObstacleSet of two moved planes: the nearest obstacle, the one a boundary
// faces, the gap before the move; the subsections Obstacle / Obstacle 2
// parsed into that set.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <signorini/contact/cad_obstacle.h>
#include <signorini/contact/cylinder_obstacle.h>
#include <signorini/contact/distance_obstacle.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/contact/plane_obstacle.h>
#include <signorini/contact/punch_obstacle.h>
#include <signorini/contact/sphere_obstacle.h>
#include <signorini/output/obstacle_output.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

using namespace dealii;
using namespace signorini;

namespace
{
  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "    " << what << ": " << std::scientific
              << std::setprecision(1) << difference
              << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  template <int dim>
  std::string
  text(const Tensor<1, dim> &v)
  {
    std::ostringstream s;
    s << '(';
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << v[d];
    return s.str() + ')';
  }

  /** gap() of @p point against @p gap and @p normal, to @p tolerance. */
  template <int dim>
  void
  check(const Obstacle<dim>  &obstacle,
        const Point<dim>     &point,
        const double          gap,
        const Tensor<1, dim> &normal,
        const double          tolerance = 1e-14)
  {
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = 7. + d; // overwritten by gap()
    const double g = obstacle.gap(point, n);
    std::cout << "  point " << text<dim>(point) << ": gap " << g
              << ", expected " << gap << "; normal " << text(n) << ", expected "
              << text(normal) << '\n';
    report("|gap - expected|", std::abs(g - gap), tolerance);
    report("|normal - expected|", (n - normal).norm(), tolerance);
  }

  template <int dim>
  Tensor<1, dim>
  unit(const Tensor<1, dim> &v)
  {
    return v / v.norm();
  }

  void
  two_dimensions()
  {
    std::cout << "plane through (1, 2) with normal (3, 4):\n";
    const PlaneObstacle<2> plane(Point<2>(1, 2), Tensor<1, 2>({3., 4.}), "P");
    const Tensor<1, 2>     n({0.6, 0.8});
    check<2>(plane, Point<2>(1, 2), 0., n);
    check<2>(plane, Point<2>(4, 6), 5., n);
    check<2>(plane, Point<2>(-2, 2), -1.8, n);

    std::cout << "circle of radius 2 around (0, -2), body outside:\n";
    const SphereObstacle<2> ball(Point<2>(0, -2), 2., false, "S");
    check<2>(ball, Point<2>(0, 1), 1., Tensor<1, 2>({0., 1.}));
    check<2>(ball, Point<2>(3, 2), 3., Tensor<1, 2>({0.6, 0.8}));
    check<2>(ball, Point<2>(1, -2), -1., Tensor<1, 2>({1., 0.}));
    std::cout << "the same circle as a cylinder, body inside (a bore):\n";
    const CylinderObstacle<2> bore(
      Point<2>(0, -2), Tensor<1, 2>(), 2., true, "C");
    check<2>(bore, Point<2>(0, 1), -1., Tensor<1, 2>({0., -1.}));
    check<2>(bore, Point<2>(1, -2), 1., Tensor<1, 2>({-1., 0.}));
    check<2>(bore, Point<2>(-1.2, -0.4), 0., Tensor<1, 2>({0.6, -0.8}));

    std::cout << "punch of radius 1 from above, its end at (2, 1) facing "
                 "down:\n";
    const PunchObstacle<2> strip(Point<2>(2, 1),
                                 Tensor<1, 2>({0., -2.}),
                                 1.,
                                 "F");
    const Tensor<1, 2>     down({0., -1.});
    check<2>(strip, Point<2>(2.5, 0.75), 0.25, down);
    check<2>(strip, Point<2>(3, 1), 0., down);
    check<2>(strip, Point<2>(1.5, 1.1), -0.1, down);
    check<2>(strip, Point<2>(6, -3), 5., Tensor<1, 2>({0.6, -0.8}));
    check<2>(strip, Point<2>(-0.5, 1), 1.5, Tensor<1, 2>({-1., 0.}));
    check<2>(strip, Point<2>(3.5, 3), 0.5, Tensor<1, 2>({1., 0.}));

    std::cout << "signed distance 2 (y - x^2) (a parabola, not a "
                 "distance):\n";
    FunctionParser<2> parabola(1);
    parabola.initialize("x,y", "2*(y - x^2)", {});
    const DistanceObstacle<2> level_set(parabola, "D");
    // At (1, 1.5): phi = 1, grad phi = (-4, 2), gap 1/sqrt(20).
    check<2>(level_set,
             Point<2>(1, 1.5),
             1. / std::sqrt(20.),
             unit(Tensor<1, 2>({-4., 2.})),
             1e-9);
    check<2>(level_set, Point<2>(0, 0), 0., Tensor<1, 2>({0., 1.}), 1e-9);

    std::cout << "geometry file: an OpenCASCADE disk of radius 2 around "
                 "(0, -2):\n";
    std::ofstream("disk.geo")
      << "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0, -2, 0, 2};\n";
    const CadObstacle<2> disk("disk.geo", false, "G");
    check<2>(disk, Point<2>(0, 1), 1., Tensor<1, 2>({0., 1.}), 1e-7);
    check<2>(disk, Point<2>(3, 2), 3., Tensor<1, 2>({0.6, 0.8}), 1e-7);
    check<2>(disk, Point<2>(1, -2), -1., Tensor<1, 2>({1., 0.}), 1e-7);
    check<2>(disk, Point<2>(1.2, -0.4), 0., Tensor<1, 2>({0.6, 0.8}), 1e-7);
    const CadObstacle<2> cup("disk.geo", true, "G");
    check<2>(cup, Point<2>(1, -2), 1., Tensor<1, 2>({-1., 0.}), 1e-7);
  }

  void
  three_dimensions()
  {
    std::cout << "sphere of radius 1 around (1, 1, 1), body inside (a "
                 "cup):\n";
    const SphereObstacle<3> cup(Point<3>(1, 1, 1), 1., true, "S");
    check<3>(cup, Point<3>(1, 1, 0.5), 0.5, Tensor<1, 3>({0., 0., 1.}));
    check<3>(cup, Point<3>(1, 3, 1), -1., Tensor<1, 3>({0., -1., 0.}));

    std::cout << "punch of radius 2, its end at the origin facing along "
                 "(1, 0, 0):\n";
    const PunchObstacle<3> punch(Point<3>(),
                                 Tensor<1, 3>({1., 0., 0.}),
                                 2.,
                                 "F");
    check<3>(punch, Point<3>(0.5, 1, 1), 0.5, Tensor<1, 3>({1., 0., 0.}));
    check<3>(punch, Point<3>(3, 0, 6), 5., Tensor<1, 3>({0.6, 0., 0.8}));
    check<3>(punch, Point<3>(-1, 0, -3), 1., Tensor<1, 3>({0., 0., -1.}));

    std::cout << "cylinder of radius 1 around the axis (1, 1, 0) through "
                 "the origin, body outside:\n";
    const CylinderObstacle<3> roller(
      Point<3>(), Tensor<1, 3>({1., 1., 0.}), 1., false, "C");
    const Tensor<1, 3> across = unit(Tensor<1, 3>({1., -1., 0.}));
    check<3>(roller, Point<3>(5, 5, 3), 2., Tensor<1, 3>({0., 0., 1.}));
    check<3>(roller,
             Point<3>(2 + std::sqrt(2.), 2 - std::sqrt(2.), 0),
             1.,
             across,
             1e-14);
    check<3>(roller, Point<3>(0, 0, 0.25), -0.75, Tensor<1, 3>({0., 0., 1.}));

    std::cout << "geometry file: an OpenCASCADE ball of radius 2 around "
                 "(0, 0, -2):\n";
    std::ofstream("ball.geo")
      << "SetFactory(\"OpenCASCADE\");\nSphere(1) = {0, 0, -2, 2};\n";
    const CadObstacle<3> ball("ball.geo", false, "G");
    check<3>(ball, Point<3>(0, 0, 1), 1., Tensor<1, 3>({0., 0., 1.}), 1e-7);
    check<3>(ball, Point<3>(0, 2, -2), 0., Tensor<1, 3>({0., 1., 0.}), 1e-7);
    check<3>(ball, Point<3>(0, 1, -2), -1., Tensor<1, 3>({0., 1., 0.}), 1e-7);
  }

  void
  obstacle_set()
  {
    std::cout << "Obstacle (floor y = 0) and Obstacle 2 (plate y = 1 moved "
                 "by (0, -0.25)) from their subsections:\n";
    ParameterHandler prm;
    ObstacleParameters<2>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Obstacle\n"
                                "  set Type = plane\n"
                                "  set Point = 0, 0\n"
                                "  set Normal = 0, 1\n"
                                "end\n"
                                "subsection Obstacle 2\n"
                                "  set Type = plane\n"
                                "  set Point = 0, 1\n"
                                "  set Normal = 0, -2\n"
                                "  set Displacement = 0, -0.25\n"
                                "end\n");
    ObstacleParameters<2> parameters;
    parameters.parse_parameters(prm);
    const auto set = create_obstacles(parameters);
    std::cout << "  " << set->size() << " obstacles, numbers " << set->number(0)
              << ' ' << set->number(1) << ", entries " << set->entry() << '\n';
    Tensor<1, 2> normal;
    const double gap = set->gap(1, Point<2>(0.5, 0.5), normal);
    std::cout << "  plate, moved: gap " << gap << ", normal " << text(normal)
              << "; before its move: " << set->initial_gap(1, Point<2>(0, 0.5))
              << '\n';
    report("|gap - 0.25|", std::abs(gap - 0.25), 1e-15);
    report("|initial gap - 0.5|",
           std::abs(set->initial_gap(1, Point<2>(0, 0.5)) - 0.5),
           1e-15);
    std::cout << "  nearest to (0, 0.2): obstacle "
              << set->nearest(Point<2>(0, 0.2)) << ", to (0, 0.6): obstacle "
              << set->nearest(Point<2>(0, 0.6)) << '\n';
    report("wrong nearest",
           (set->nearest(Point<2>(0, 0.2)) == 0 ? 0. : 1.) +
             (set->nearest(Point<2>(0, 0.6)) == 1 ? 0. : 1.),
           0.);
    // A boundary point nearer the plate whose outward normal points down
    // faces the floor.
    const unsigned int faced =
      set->facing(Point<2>(0, 0.6), Tensor<1, 2>({0., -1.}));
    std::cout << "  a point at (0, 0.6) with outward normal (0, -1) faces "
                 "obstacle "
              << faced << '\n';
    report("wrong facing", faced == 0 ? 0. : 1., 0.);
    std::ostringstream vtu;
    write_obstacles_vtu(vtu,
                        *set,
                        BoundingBox<2>({Point<2>(0, 0), Point<2>(1, 1)}));
    std::cout << "  write_vtu: "
              << (vtu.str().find("Name=\"obstacle\"") != std::string::npos ?
                    "a point field named obstacle" :
                    "no field named obstacle (FAILED)")
              << ", " << vtu.str().substr(vtu.str().find("NumberOfCells"), 18)
              << '\n';
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  two_dimensions();
  three_dimensions();
  obstacle_set();
}
