// ContactSurface on small Q1 meshes made by Discretisation from a parameter
// text: the nodes on the contact boundary (count, positions in the order of
// their scalar dofs), their gaps and normals against a curved HeightObstacle,
// the lumped masses (h/2 at the ends of the contact boundary, h inside; in
// 3D the products of those), their sum (the contact boundary's length or
// area), a node whose normal displacement a Dirichlet condition fixes
// excluded (one fixed in the other component kept), active_set_signature
// and deformed_gap for an interpolated displacement; the nodes' frames
// (tangent_frame): orthonormal and right-handed for normals along the axes
// and oblique ones, and t = (-n_y, n_x) in 2D.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/mesh_adaptation/mesh_adaptation_factory.h>
#include <signorini/problem/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;

namespace
{
  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "  " << what << ": " << std::scientific << std::setprecision(1)
              << difference << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  template <int dim>
  std::string
  to_string(const Point<dim> &p)
  {
    std::ostringstream s;
    s << '(';
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << p[d];
    return s.str() + ')';
  }

  /** The rooms that ContactProblem::setup_system connects for the contact
   * surface: parameters, discretisation (make_grid as run.cc calls it),
   * obstacle, and the contact surface set up on the mesh. */
  template <int dim>
  struct Scene
  {
    Parameters<dim>                      parameters;
    std::unique_ptr<Discretisation<dim>> discretisation;
    std::unique_ptr<ObstacleSet<dim>>    obstacle;
    std::unique_ptr<ContactSurface<dim>> surface;

    explicit Scene(const std::string &text)
    {
      ParameterHandler prm;
      declare_parameters(prm, dim);
      prm.parse_input_from_string(text);
      parameters.parse_parameters(prm, {});
      discretisation = std::make_unique<Discretisation<dim>>(
        parameters.geometry,
        mesh_adaptation_factory(parameters.geometry,
                                parameters.refinement,
                                MPI_COMM_WORLD),
        parameters.boundary_conditions,
        MPI_COMM_WORLD);
      std::set<types::boundary_id> dirichlet_ids;
      for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
        dirichlet_ids.insert(id);
      discretisation->make_grid(
        {{"Boundary conditions/Dirichlet", dirichlet_ids},
         {"Boundary conditions/Traction boundary ids",
          parameters.boundary_conditions.traction_ids},
         {"Obstacle/Contact boundary ids", parameters.obstacle.contact_ids}});
      obstacle = create_obstacles(parameters.obstacle);
      surface =
        std::make_unique<ContactSurface<dim>>(parameters.obstacle.contact_ids,
                                              *obstacle);
      surface->setup(*discretisation);
    }
  };

  /** Prints the nodes and checks them against @p expected_positions (any
   * order), @p height (psi) and @p expected_mass (of a position). */
  template <int dim>
  void
  check_nodes(const Scene<dim>                        &scene,
              const std::vector<Point<dim>>           &expected_positions,
              const std::function<double(Point<dim>)> &height,
              const std::function<double(Point<dim>)> &expected_mass,
              const double                             expected_total)
  {
    const auto &nodes = scene.surface->nodes();
    std::cout << "  " << nodes.size() << " nodes (expected "
              << expected_positions.size() << "), in the order of their "
              << "scalar dofs:\n";
    double         worst_gap = 0., worst_normal = 0., worst_mass = 0.;
    double         total  = 0.;
    bool           sorted = true, scalar_last = true, owned = true;
    unsigned int   matched = 0;
    Tensor<1, dim> e;
    e[dim - 1] = 1.;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const auto &node = nodes[i];
        std::cout << "   dof " << node.scalar_dof << " at "
                  << to_string(node.position) << ": gap " << node.gap
                  << ", normal " << to_string(Point<dim>(node.normal))
                  << ", mass " << node.mass << '\n';
        if (i > 0 && nodes[i - 1].scalar_dof >= node.scalar_dof)
          sorted = false;
        scalar_last  = scalar_last && node.scalar_dof == node.dofs[dim - 1];
        owned        = owned && node.owned && !node.in_contact();
        worst_gap    = std::max(worst_gap,
                             std::abs(node.gap - (node.position[dim - 1] -
                                                  height(node.position))));
        worst_normal = std::max(worst_normal, (node.normal - e).norm());
        worst_mass =
          std::max(worst_mass,
                   std::abs(node.mass - expected_mass(node.position)));
        total += node.mass;
        for (const auto &p : expected_positions)
          if (p.distance(node.position) < 1e-12)
            ++matched;
      }
    std::cout << "  scalar dofs ascending: " << (sorted ? "yes" : "no")
              << ", scalar dof the last component's: "
              << (scalar_last ? "yes" : "no")
              << ", all owned and inactive: " << (owned ? "yes" : "no") << '\n';
    report("|nodes - expected|, |matched positions - expected|",
           std::max(
             std::abs(double(nodes.size()) - double(expected_positions.size())),
             std::abs(double(matched) - double(expected_positions.size()))),
           0.);
    report("max |gap - (last coordinate - psi)|", worst_gap, 1e-15);
    report("max |normal - e_last|", worst_normal, 0.);
    report("max |mass - expected|", worst_mass, 1e-15);
    std::cout << "  sum of masses " << total << ", expected " << expected_total
              << '\n';
    report("|sum of masses - expected|",
           std::abs(total - expected_total),
           1e-14);
  }

  const std::string rectangle = R"(
set Dimension = 2
subsection Geometry
  set Upper right corner = 2, 1
  set Subdivisions       = 4, 2
end
subsection Obstacle
  set Height               = -0.1 - 0.2*(x - 1)^2
  set Contact boundary ids = 2
end
)";

  double
  psi_2d(const Point<2> &p)
  {
    return -0.1 - 0.2 * (p[0] - 1) * (p[0] - 1);
  }

  /** h/2 at the ends of the bottom [0, 2], h = 0.5 inside. */
  double
  mass_2d(const Point<2> &p)
  {
    return (p[0] == 0. || p[0] == 2.) ? 0.25 : 0.5;
  }

  void
  rectangle_2d()
  {
    std::cout << "2D, [0, 2] x [0, 1] in 4 x 2 Q1 cells, contact boundary id "
                 "2 (y = 0), psi = -0.1 - 0.2 (x - 1)^2, Dirichlet 0: x:\n";
    Scene<2>              scene(rectangle + R"(
subsection Boundary conditions
  set Dirichlet = 0: x
end
)");
    std::vector<Point<2>> bottom;
    for (unsigned int i = 0; i <= 4; ++i)
      bottom.emplace_back(0.5 * i, 0.);
    check_nodes<2>(scene, bottom, psi_2d, mass_2d, 2.);
    const double tolerance = scene.surface->touching_tolerance();
    std::cout << "  touching tolerance " << tolerance << " = 1e-12 x "
              << tolerance / 1e-12 << " (diagonal sqrt(5) = " << std::sqrt(5.)
              << ")\n";
    report("|touching tolerance - 1e-12 sqrt(5)|",
           std::abs(tolerance - 1e-12 * std::sqrt(5.)),
           1e-26);

    // Active set signature: the count of active nodes and a hash of which.
    auto      &nodes     = scene.surface->nodes();
    const auto none      = scene.surface->active_set_signature();
    nodes[1].state       = NodeState::closed;
    nodes[3].state       = NodeState::closed;
    const auto one_three = scene.surface->active_set_signature();
    nodes[3].state       = NodeState::open;
    nodes[2].state       = NodeState::closed;
    const auto one_two   = scene.surface->active_set_signature();
    nodes[2].state       = NodeState::open;
    nodes[3].state       = NodeState::closed;
    const auto again     = scene.surface->active_set_signature();
    for (auto &node : nodes)
      node.state = NodeState::closed;
    const auto all = scene.surface->active_set_signature();
    std::cout << "  active_set_signature counts: none " << none.first
              << ", nodes {1, 3} " << one_three.first << ", {1, 2} "
              << one_two.first << ", all " << all.first << '\n';
    std::cout << "  hash of {1, 3} set again equal: "
              << (again.second == one_three.second ? "yes" : "no")
              << ", {1, 3} and {1, 2} differ: "
              << (one_two.second != one_three.second ? "yes" : "no")
              << ", none differs from all: "
              << (none.second != all.second ? "yes" : "no") << '\n';
    report("|counts - (0, 2, 2, 5)|",
           std::abs(double(none.first)) + std::abs(one_three.first - 2.) +
             std::abs(one_two.first - 2.) + std::abs(all.first - 5.),
           0.);
    for (auto &node : nodes)
      node.state = NodeState::open;

    // deformed_gap = gap + n.u for u = (0.3 + x, -0.05 - 0.1 x): only the
    // normal (y) component counts.
    const auto                   &discretisation = *scene.discretisation;
    TrilinosWrappers::MPI::Vector owned(discretisation.locally_owned_dofs(),
                                        discretisation.mpi_communicator());
    FunctionParser<2>             displacement(2);
    displacement.initialize("x,y", "0.3 + x; -0.05 - 0.1*x", {});
    VectorTools::interpolate(discretisation.mapping(),
                             discretisation.dof_handler(),
                             displacement,
                             owned);
    TrilinosWrappers::MPI::Vector u(discretisation.locally_owned_dofs(),
                                    discretisation.locally_relevant_dofs(),
                                    discretisation.mpi_communicator());
    u            = owned;
    double worst = 0.;
    std::cout << "  deformed gaps for u = (0.3 + x, -0.05 - 0.1 x):";
    for (const auto &node : nodes)
      {
        const double g = scene.surface->deformed_gap(node, u);
        const double expected =
          -psi_2d(node.position) - 0.05 - 0.1 * node.position[0];
        std::cout << ' ' << g;
        worst = std::max(worst, std::abs(g - expected));
        worst = std::max(worst,
                         std::abs(node.normal_displacement(u) -
                                  (-0.05 - 0.1 * node.position[0])));
      }
    std::cout << '\n';
    report("max |deformed gap - (-psi + u_y)|, |n.u - u_y|", worst, 1e-15);
  }

  void
  dirichlet_2d()
  {
    std::cout << "the same, Dirichlet 0: y (the corner (0, 0) fixed along "
                 "the normal):\n";
    Scene<2>              scene(rectangle + R"(
subsection Boundary conditions
  set Dirichlet = 0: y
end
)");
    std::vector<Point<2>> bottom;
    for (unsigned int i = 1; i <= 4; ++i)
      bottom.emplace_back(0.5 * i, 0.);
    // The corner's share of the boundary integral is not condensed onto its
    // neighbour: the sum falls short by h/2.
    check_nodes<2>(scene, bottom, psi_2d, mass_2d, 1.75);

    std::cout << "the same, Dirichlet 1: xy; 0: x (the corner (2, 0) fixed):\n";
    Scene<2> right(rectangle + R"(
subsection Boundary conditions
  set Dirichlet = 1: xy; 0: x
end
)");
    bottom.clear();
    for (unsigned int i = 0; i < 4; ++i)
      bottom.emplace_back(0.5 * i, 0.);
    check_nodes<2>(right, bottom, psi_2d, mass_2d, 1.75);
  }

  void
  box_3d()
  {
    std::cout << "3D, [0, 1] x [0, 1] x [0, 0.5] in 2 x 2 x 1 Q1 cells, "
                 "contact boundary id 4 (z = 0), psi = -0.1 + 0.1 x y, "
                 "Dirichlet 0: x:\n";
    Scene<3>              scene(R"(
set Dimension = 3
subsection Geometry
  set Lower left corner  = 0, 0, 0
  set Upper right corner = 1, 1, 0.5
  set Subdivisions       = 2, 2, 1
end
subsection Boundary conditions
  set Dirichlet = 0: x
end
subsection Obstacle
  set Height               = -0.1 + 0.1*x*y
  set Contact boundary ids = 4
end
)");
    std::vector<Point<3>> bottom;
    for (unsigned int i = 0; i <= 2; ++i)
      for (unsigned int j = 0; j <= 2; ++j)
        bottom.emplace_back(0.5 * i, 0.5 * j, 0.);
    const auto weight = [](const double x) {
      return (x == 0. || x == 1.) ? 0.25 : 0.5;
    };
    check_nodes<3>(
      scene,
      bottom,
      [](const Point<3> &p) { return -0.1 + 0.1 * p[0] * p[1]; },
      [&](const Point<3> &p) { return weight(p[0]) * weight(p[1]); },
      1.);
  }
  /** tangent_frame for normals along the axes and oblique ones: the
   * largest defect of orthonormality (and of t_1 x t_2 = n in 3D). */
  void
  frames()
  {
    std::cout << "Frames:\n";
    double worst = 0., rotation = 0.;
    for (const double angle : {0., 0.3, 1.5707963267948966, 2.5, -1.})
      {
        Tensor<1, 2> n;
        n[0]         = std::cos(angle);
        n[1]         = std::sin(angle);
        const auto t = tangent_frame(n)[0];
        worst = std::max({worst, std::abs(n * t), std::abs(t.norm() - 1.)});
        rotation =
          std::max({rotation, std::abs(t[0] + n[1]), std::abs(t[1] - n[0])});
      }
    report("2D: max |n.t|, ||t| - 1|", worst, 1e-15);
    report("2D: max |t - (-n_y, n_x)|", rotation, 0.);
    worst = 0.;
    for (const auto &direction :
         std::vector<std::array<double, 3>>{{{0, 0, 1}},
                                            {{0, 0, -1}},
                                            {{1, 0, 0}},
                                            {{0, -1, 0}},
                                            {{1, 2, 3}},
                                            {{-0.3, 0.1, -2}},
                                            {{1, 1, 1e-9}}})
      {
        Tensor<1, 3> n;
        for (unsigned int d = 0; d < 3; ++d)
          n[d] = direction[d];
        n /= n.norm();
        const auto t = tangent_frame(n);
        worst        = std::max({worst,
                                 std::abs(n * t[0]),
                                 std::abs(n * t[1]),
                                 std::abs(t[0] * t[1]),
                                 std::abs(t[0].norm() - 1.),
                                 std::abs(t[1].norm() - 1.),
                                 (cross_product_3d(t[0], t[1]) - n).norm()});
      }
    report("3D: max defect of orthonormality and of t1 x t2 = n", worst, 1e-15);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(10);
  rectangle_2d();
  dirichlet_2d();
  box_3d();
  frames();
}
