// The axisymmetric model in (r, z) = (x, y), room by room: CellStiffness of
// a revolved Q1 cell (symmetric; the axial translation its only rigid mode;
// the energy of the uniform stretch u_r = r against (4 lambda + 4 mu) times
// the revolved volume; cell_internal_force equal to K u; the cache: a copy
// moved along the axis shares the matrix, one moved away from it does not,
// one scaled about it by s gets s K), the axis constraints u_r = 0 (a
// hanging node on the axis held through its masters), the check that the
// body does not cross the axis (naming the Geometry entry), and through
// Discretisation, ContactSurface and Loads on a cylinder: lumped masses
// 2 pi r_i h (2 pi h^2 / 6 on the axis) summing to the contact disk's area
// pi R^2, and a Traction resultant and a body force whose resultants are
// the whole revolution's.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/discretisation/axisymmetry.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/cell_stiffness.h>
#include <signorini/elasticity/loads.h>
#include <signorini/input/input_error.h>
#include <signorini/mesh_adaptation/mesh_adaptation_factory.h>
#include <signorini/postprocessing/balance.h>
#include <signorini/problem/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;

namespace
{
  // E = 2.6, nu = 0.3: mu = 1, lambda = 1.5.
  constexpr double E      = 2.6;
  constexpr double nu     = 0.3;
  constexpr double mu     = 1.;
  constexpr double lambda = 1.5;

  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "  " << what << ": " << std::scientific << std::setprecision(1)
              << difference << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  double
  max_abs(const FullMatrix<double> &a)
  {
    double m = 0.;
    for (unsigned int i = 0; i < a.m(); ++i)
      for (unsigned int j = 0; j < a.n(); ++j)
        m = std::max(m, std::abs(a(i, j)));
    return m;
  }

  /** One Q1 cell [r0, r0 + h] x [z0, z0 + h] with its dofs. */
  struct Cell
  {
    Triangulation<2> tria;
    DoFHandler<2>    dofs;

    Cell(const FiniteElement<2> &fe, double r0, double z0, double h)
    {
      GridGenerator::hyper_rectangle(tria,
                                     Point<2>(r0, z0),
                                     Point<2>(r0 + h, z0 + h));
      dofs.reinit(tria);
      dofs.distribute_dofs(fe);
    }
  };

  /** The nodal vector of the displacement @p u(x) on @p cell. */
  template <typename U>
  Vector<double>
  nodal(const FiniteElement<2>                    &fe,
        const DoFHandler<2>::active_cell_iterator &cell,
        const U                                   &u)
  {
    Vector<double> values(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto [component, index] = fe.system_to_component_index(i);
        (void)index;
        const unsigned int vertex = i / 2;
        values(i)                 = u(cell->vertex(vertex))[component];
      }
    return values;
  }

  void
  test_cell_stiffness()
  {
    std::cout << "revolved Q1 cell, E = " << E << ", nu = " << nu
              << " (lambda = 1.5, mu = 1)\n";
    const FESystem<2> fe(FE_Q<2>(1), 2);
    Material          material;
    material.young_modulus = E;
    material.poisson_ratio = nu;
    material.plane_state   = Material::PlaneState::axisymmetric;
    const QGauss<2> rule(2);

    for (const double r0 : {0., 0.75})
      {
        const double h = 0.5;
        std::cout << " the cell [" << r0 << ", " << r0 + h << "] x [0.25, "
                  << 0.25 + h << "]\n";
        CellStiffness<2> stiffness(material);
        Cell             one(fe, r0, 0.25, h);
        FEValues<2>      fe_values(fe, rule, elastic_update_flags(material));
        const auto       cell      = one.dofs.begin_active();
        const FullMatrix<double> K = stiffness.matrix(cell, fe_values);

        double asymmetry = 0.;
        for (unsigned int i = 0; i < K.m(); ++i)
          for (unsigned int j = 0; j < K.n(); ++j)
            asymmetry = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
        report("max |K - K^T| / max|K|", asymmetry / max_abs(K), 0.);

        // Rigid motions of a body of revolution: the axial translation
        // alone; a radial translation stretches the hoops.
        Vector<double> Ku(K.m());
        const auto     axial =
          nodal(fe, cell, [](const Point<2> &) { return Point<2>(0., 1.); });
        K.vmult(Ku, axial);
        report("|K (0, 1)| / max|K|", Ku.linfty_norm() / max_abs(K), 1e-15);
        const auto radial =
          nodal(fe, cell, [](const Point<2> &) { return Point<2>(1., 0.); });
        const double radial_energy = K.matrix_norm_square(radial);
        std::cout << "  (1, 0).K(1, 0) = " << radial_energy
                  << (radial_energy > 0 ? " > 0 (ok)" : " (FAILED)") << '\n';

        // u = (r, 0): eps_rr = eps_hoop = 1, sigma : eps = 4 lambda + 4 mu,
        // over the revolved volume 2 pi h^2 (r0 + h / 2).
        const auto stretch =
          nodal(fe, cell, [](const Point<2> &x) { return Point<2>(x[0], 0.); });
        const double exact =
          (4. * lambda + 4. * mu) * 2. * numbers::PI * h * h * (r0 + h / 2.);
        std::cout << "  u = (r, 0): u.K u = " << K.matrix_norm_square(stretch)
                  << ", (4 lambda + 4 mu) 2 pi h^2 (r0 + h/2) = " << exact
                  << '\n';
        report("|u.K u - exact| / exact",
               std::abs(K.matrix_norm_square(stretch) - exact) / exact,
               1e-14);

        // cell_internal_force of a displacement against K u.
        TrilinosWrappers::MPI::Vector u(complete_index_set(one.dofs.n_dofs()),
                                        MPI_COMM_SELF);
        std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
        cell->get_dof_indices(dof_indices);
        Vector<double> u_cell(fe.n_dofs_per_cell());
        for (unsigned int i = 0; i < u_cell.size(); ++i)
          {
            u_cell(i)         = std::sin(1. + 3. * i);
            u(dof_indices[i]) = u_cell(i);
          }
        fe_values.reinit(cell);
        Vector<double> internal(fe.n_dofs_per_cell());
        const double   energy =
          cell_internal_force(material, fe_values, u, internal);
        K.vmult(Ku, u_cell);
        Ku -= internal;
        report("|internal force - K u| / max|K|",
               Ku.linfty_norm() / max_abs(K),
               1e-14);
        report("|strain energy - u.K u / 2| / (u.K u / 2)",
               std::abs(energy - 0.5 * K.matrix_norm_square(u_cell)) /
                 (0.5 * K.matrix_norm_square(u_cell)),
               1e-14);

        // The cache: along the axis a copy, away from it another matrix,
        // scaled about it by 2 twice the matrix.
        Cell       moved(fe, r0, -3., h);
        const auto hit = stiffness.cached(moved.dofs.begin_active());
        std::cout << "  moved along the axis: cached "
                  << (hit ? "yes (ok)" : "no (FAILED)") << '\n';
        if (hit)
          {
            FullMatrix<double> d(*hit);
            d.add(-1., K);
            report("max |K(moved) - K| / max|K|", max_abs(d) / max_abs(K), 0.);
          }
        Cell outward(fe, r0 + 0.5, 0.25, h);
        std::cout << "  moved away from the axis: cached "
                  << (stiffness.cached(outward.dofs.begin_active()) ?
                        "yes (FAILED)" :
                        "no (ok)")
                  << '\n';
        Cell       scaled(fe, 2. * r0, 0.5, 2. * h);
        const auto twice = stiffness.cached(scaled.dofs.begin_active());
        std::cout << "  scaled about the axis by 2: cached "
                  << (twice ? "yes (ok)" : "no (FAILED)") << '\n';
        if (twice)
          {
            FullMatrix<double> computed;
            FEValues<2> scaled_values(fe, rule, elastic_update_flags(material));
            scaled_values.reinit(scaled.dofs.begin_active());
            stiffness.compute(scaled_values, computed);
            FullMatrix<double> d(*twice);
            d.add(-1., computed);
            report("max |cached - computed| / max|computed|",
                   max_abs(d) / max_abs(computed),
                   1e-15);
            d = *twice;
            d.add(-2., K);
            report("max |cached - 2 K| / max|2 K|",
                   max_abs(d) / (2. * max_abs(K)),
                   1e-15);
          }
      }
  }

  void
  test_axis_constraints()
  {
    std::cout << "axis constraints on [0, 1]^2 in 2 x 2 cells, the cell at "
                 "the axis' bottom refined (a hanging node on the axis)\n";
    const FESystem<2> fe(FE_Q<2>(1), 2);
    Triangulation<2>  tria;
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {2, 2},
                                              Point<2>(),
                                              Point<2>(1., 1.));
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] < 0.5 && cell->center()[1] < 0.5)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    DoFHandler<2> dofs(tria);
    dofs.distribute_dofs(fe);
    const IndexSet            all = complete_index_set(dofs.n_dofs());
    AffineConstraints<double> constraints(all);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    const unsigned int hanging = constraints.n_constraints();
    axisymmetry::add_axis_constraints(dofs, all, 1e-12, constraints);
    const unsigned int axis = constraints.n_constraints() - hanging;
    constraints.close();
    // Vertices on the axis: y = 0, 0.25, 0.5, 1 (0.75 hangs; it is one of
    // the hanging nodes).
    std::cout << "  " << hanging << " hanging-node lines, " << axis
              << " axis lines (expected 4)\n";
    report("|axis lines - 4|", std::abs(double(axis) - 4.), 0.);

    Vector<double> u(dofs.n_dofs());
    for (unsigned int i = 0; i < u.size(); ++i)
      u(i) = 1. + std::sin(1. + i);
    constraints.distribute(u);
    double on_axis = 0., elsewhere = 1.;
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v)[0] == 0.)
          {
            on_axis =
              std::max(on_axis, std::abs(u(cell->vertex_dof_index(v, 0))));
            elsewhere =
              std::min(elsewhere, std::abs(u(cell->vertex_dof_index(v, 1))));
          }
    report("max |u_r| on the axis after distribute", on_axis, 0.);
    std::cout << "  u_z on the axis left free: "
              << (elsewhere > 0 ? "yes (ok)" : "no (FAILED)") << '\n';
  }

  void
  test_side_of_axis()
  {
    std::cout << "bodies that cross the axis\n";
    const auto try_geometry = [](const std::string &what,
                                 Geometry<2>        geometry) {
      Triangulation<2> mesh;
      geometry.create_coarse_mesh(mesh, MPI_COMM_SELF);
      try
        {
          axisymmetry::check_side_of_axis(mesh, geometry, 1e-10);
          std::cout << "  " << what << ": accepted\n";
        }
      catch (const InputError &error)
        {
          std::cout << "  " << what << ": " << error.entry << ": "
                    << error.what() << '\n';
        }
    };
    Geometry<2> rectangle;
    rectangle.lower_left  = Point<2>(0., 0.);
    rectangle.upper_right = Point<2>(1., 1.);
    try_geometry("rectangle from x = 0", rectangle);
    rectangle.lower_left = Point<2>(-1e-14, 0.);
    try_geometry("rectangle from x = -1e-14 (round-off)", rectangle);
    rectangle.lower_left = Point<2>(-0.25, 0.);
    try_geometry("rectangle from x = -0.25", rectangle);
    Geometry<2> disk;
    disk.type   = Geometry<2>::Type::quarter_disk;
    disk.center = Point<2>(0., 1.);
    try_geometry("quarter disk about x = 0", disk);
    disk.center = Point<2>(-0.5, 1.);
    try_geometry("quarter disk about x = -0.5", disk);
    disk.type   = Geometry<2>::Type::half_ball;
    disk.center = Point<2>(0., 1.);
    try_geometry("half disk about x = 0", disk);
  }

  /** A cylinder of radius 2 and height 1 in 4 x 2 cells, axisymmetric,
   * with @p extra entries, through Discretisation. */
  struct Cylinder
  {
    Parameters<2>                      parameters;
    std::unique_ptr<Discretisation<2>> discretisation;

    explicit Cylinder(const std::string &extra)
    {
      ParameterHandler prm;
      declare_parameters(prm, 2);
      prm.parse_input_from_string("subsection Geometry\n"
                                  " set Upper right corner = 2, 1\n"
                                  " set Subdivisions = 4, 2\n"
                                  "end\n"
                                  "subsection Material\n"
                                  " set Plane state = axisymmetric\n"
                                  "end\n" +
                                  extra);
      parameters.parse_parameters(prm, {});
      discretisation = std::make_unique<Discretisation<2>>(
        parameters.geometry,
        mesh_adaptation_factory(parameters.geometry,
                                parameters.refinement,
                                MPI_COMM_WORLD),
        parameters.boundary_conditions,
        MPI_COMM_WORLD,
        parameters.material.axisymmetric());
      std::set<types::boundary_id> dirichlet_ids;
      for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
        dirichlet_ids.insert(id);
      discretisation->make_grid(
        {{"Boundary conditions/Dirichlet", dirichlet_ids},
         {"Boundary conditions/Traction boundary ids",
          parameters.boundary_conditions.traction_ids},
         {"Obstacle/Contact boundary ids", parameters.obstacle.contact_ids}});
    }
  };

  void
  test_masses_and_loads()
  {
    const double pi = numbers::PI;
    std::cout << "a cylinder r <= 2, 0 <= z <= 1 in 4 x 2 cells (h = 0.5), "
                 "contact boundary z = 0\n";
    Cylinder    cylinder("subsection Boundary conditions\n"
                         " set Dirichlet = 3: y\n"
                         "end\n"
                         "subsection Obstacle\n"
                         " set Contact boundary ids = 2\n"
                         " set Height = -0.1\n"
                         "end\n");
    const auto &discretisation = *cylinder.discretisation;
    std::cout << "  weight at (0.5, 0.3): "
              << discretisation.weight(Point<2>(0.5, 0.3)) << " (pi)\n";
    report("|weight - pi|",
           std::abs(discretisation.weight(Point<2>(0.5, 0.3)) - pi),
           0.);
    const auto        obstacle = create_obstacles(cylinder.parameters.obstacle);
    ContactSurface<2> surface(cylinder.parameters.obstacle.contact_ids,
                              *obstacle);
    surface.setup(discretisation);
    const double h     = 0.5;
    double       worst = 0., total = 0.;
    for (const auto &node : surface.nodes())
      {
        const double r = node.position[0];
        // Both faces' halves: 2 pi r h inside; 2 pi h^2 / 6 on the axis,
        // pi h (r - h / 3) at the rim.
        const double expected = r == 0. ? 2. * pi * h * h / 6. :
                                r == 2. ? pi * h * (r - h / 3.) :
                                          2. * pi * r * h;
        std::cout << "   node at r = " << r << ": mass " << node.mass
                  << ", expected " << expected << '\n';
        worst = std::max(worst, std::abs(node.mass - expected));
        total += node.mass;
      }
    report("max |mass - expected|", worst, 1e-14);
    std::cout << "  sum of masses " << total
              << ", the disk's area 4 pi = " << 4. * pi << '\n';
    report("|sum - 4 pi| / 4 pi", std::abs(total - 4. * pi) / (4. * pi), 1e-15);

    std::cout << "the same cylinder pulled by a Traction resultant (0, 3) on "
                 "its top and weighing 0.25 N/mm^3, held at z = 0\n";
    Cylinder                      loaded("subsection Boundary conditions\n"
                                         " set Dirichlet = 2: y\n"
                                         " set Traction boundary ids = 3\n"
                                         " set Traction resultant = 0, 3\n"
                                         " set Body force = 0; -0.25\n"
                                         "end\n");
    Loads<2>                      loads(loaded.parameters.boundary_conditions,
                   *loaded.discretisation);
    const auto                   &dofs = loaded.discretisation->dof_handler();
    TrilinosWrappers::MPI::Vector load(dofs.locally_owned_dofs(),
                                       MPI_COMM_WORLD);
    loads.assemble(load);
    TrilinosWrappers::MPI::Vector u(dofs.locally_owned_dofs(), MPI_COMM_WORLD);
    const auto   balance  = evaluate_balance(*loaded.discretisation,
                                          loads,
                                          loaded.parameters.material,
                                          u);
    const double expected = 3. - 0.25 * 4. * pi;
    std::cout << "  applied axial force " << balance.applied_force[1]
              << ", expected 3 - 0.25 x 4 pi = " << expected << '\n';
    report("|applied - expected| / |expected|",
           std::abs(balance.applied_force[1] - expected) / std::abs(expected),
           1e-14);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(10);
  test_cell_stiffness();
  test_axis_constraints();
  test_side_of_axis();
  test_masses_and_loads();
}
