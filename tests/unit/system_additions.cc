// The door from a law to the elastic operators, SystemAdditions, without
// anything of contact: a plane-strain square (E = 1000, nu = 0.25, 4 x 4 Q1
// cells, x held on the left side, y at the bottom, a traction (0.3, -2) on
// the top) with, at the top right vertex,
//   - a non-symmetric block B = [[k, s], [-s, 2k]] with a right-hand side,
//   - a force entry,
// and, at the top left vertex, a constraint line u_y = 0.5 u_x + g.
// Each operator and solver (the direct solver; AMG with GMRES, as the block
// is not symmetric; the matrix-free operator with multigrid GMRES) must
// solve the same system: the constraint line holds, the force balance
// K u - f + B u - b - F = 0 holds at every free dof (at the line's master
// through the line's weight), and the solvers agree.
// Then the line gets a test weight of its own, 0.8 (Petrov-Galerkin, as
// friction's slipping nodes): the master's equation becomes
// r_x + 0.8 r_y = F_x there (r = K u - f + B u - b), with the line still
// exact; the direct solver, AMG with GMRES and the matrix-free operator
// (GMRES on T^T K P, preconditioned by the multigrid of P^T K P) must
// agree.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/elastic_operator.h>
#include <signorini/elasticity/loads.h>
#include <signorini/elasticity/system_additions.h>
#include <signorini/mesh_adaptation/mesh_adaptation_factory.h>
#include <signorini/problem/parameters.h>

#include "checks.h"
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;
using checks::report;

namespace
{
  const std::string scene = R"(
set Dimension = 2
subsection Geometry
  set Upper right corner = 1, 1
  set Subdivisions       = 4, 4
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.25
end
subsection Boundary conditions
  set Dirichlet             = 0: x; 2: y
  set Traction boundary ids = 3
  set Traction              = 0.3; -2
end
subsection Linear solver
  set Tolerance = 1e-12
)";

  constexpr double k = 200., s = 150., g = 0.001, test_weight = 0.8;

  /** The displacement of the scene with the additions, by the linear
   * solver @p type, with the line's own test weight if
   * @p petrov_galerkin; prints the checks. */
  std::map<types::global_dof_index, double>
  solve(const std::string &type, const bool petrov_galerkin = false)
  {
    using VectorType = TrilinosWrappers::MPI::Vector;
    Parameters<2>    parameters;
    ParameterHandler prm;
    declare_parameters(prm, 2);
    prm.parse_input_from_string(scene + "  set Type = " + type + "\nend\n");
    parameters.parse_parameters(prm, {});
    ConditionalOStream pcout(std::cout, false);
    TimerOutput       timer(pcout, TimerOutput::never, TimerOutput::wall_times);
    const MPI_Comm    comm = MPI_COMM_WORLD;
    Discretisation<2> discretisation(
      parameters.geometry,
      mesh_adaptation_factory(parameters.geometry, parameters.refinement, comm),
      parameters.boundary_conditions,
      comm);
    discretisation.make_grid({});
    Loads<2> loads(parameters.boundary_conditions, discretisation);
    auto     elastic_operator =
      create_elastic_operator(discretisation,
                              parameters.material,
                              parameters.boundary_conditions,
                              loads,
                              parameters.linear_solver,
                              false,
                              false,
                              pcout,
                              timer);
    elastic_operator->reinit();
    elastic_operator->assemble_load();

    // The dofs of the top corners.
    std::array<types::global_dof_index, 2> right{}, left{};
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < 2; ++d)
          {
            if (cell->vertex(v).distance(Point<2>(1, 1)) < 1e-12)
              right[d] = cell->vertex_dof_index(v, d);
            if (cell->vertex(v).distance(Point<2>(0, 1)) < 1e-12)
              left[d] = cell->vertex_dof_index(v, d);
          }

    SystemAdditions<2>        additions;
    SystemAdditions<2>::Block block;
    block.rows         = right;
    block.columns      = right;
    block.matrix[0][0] = k;
    block.matrix[0][1] = s;
    block.matrix[1][0] = -s;
    block.matrix[1][1] = 2 * k;
    block.rhs          = {0.05, -0.1};
    additions.blocks.push_back(block);
    additions.has_blocks = true;
    additions.forces.push_back({right[0], 0.2});
    additions.has_forces = true;
    // u_y = 0.5 u_x + g at the top left vertex (u_x is free there).
    additions.constraints.push_back({left[1], {{left[0], 0.5}}, g, false, {}});
    const double weight = petrov_galerkin ? test_weight : 0.5;
    if (petrov_galerkin)
      {
        additions.constraints.back().petrov_galerkin = true;
        additions.constraints.back().test_entries    = {{left[0], weight}};
        additions.has_test_weights                   = true;
        additions.forces.push_back({left[0], 0.1});
      }
    Tensor<1, 2> direction;
    direction[0] = -0.5 / std::sqrt(1.25);
    direction[1] = 1. / std::sqrt(1.25);
    additions.constraint_springs.push_back({left, direction, left[1]});
    additions.symmetric = false;
    additions.key       = {{1, 1}, 0.};

    VectorType u(discretisation.locally_owned_dofs(),
                 discretisation.locally_relevant_dofs(),
                 comm);
    elastic_operator->solve(additions, u, true);

    // The balance: K u - f + B u - b - F at the free dofs; the line's
    // dof's residual goes to its master with the weight 0.5.
    VectorType residual(discretisation.locally_owned_dofs(), comm);
    elastic_operator->residual(u, residual);
    std::map<types::global_dof_index, double> r;
    for (const auto i : discretisation.locally_owned_dofs())
      r[i] = residual(i);
    for (unsigned int a = 0; a < 2; ++a)
      {
        for (unsigned int b = 0; b < 2; ++b)
          r[right[a]] += block.matrix[a][b] * u(right[b]);
        r[right[a]] -= block.rhs[a];
      }
    r[right[0]] -= 0.2;
    r[left[0]] += weight * r[left[1]];
    if (petrov_galerkin)
      r[left[0]] -= 0.1;
    r[left[1]]   = 0.;
    double worst = 0.;
    for (const auto &[i, value] : r)
      if (!discretisation.constraints().is_constrained(i))
        worst = std::max(worst, std::abs(value));
    const double load = elastic_operator->load().l2_norm();

    std::cout << type << (petrov_galerkin ? ", test weight 0.8" : "")
              << ": solved in";
    for (const auto &[section, time] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      if (section.rfind("Solve: ", 0) == 0)
        std::cout << " '" << section << "'";
    std::cout << '\n';
    report("|u_y - 0.5 u_x - g| at the top left vertex",
           std::abs(u(left[1]) - 0.5 * u(left[0]) - g),
           1e-14);
    report(petrov_galerkin ?
             "max |K u - f + B u - b - F| / |f| at the free dofs, the "
             "master's by the test weight" :
             "max |K u - f + B u - b - F| / |f| at the free dofs",
           worst / load,
           1e-9);
    std::map<types::global_dof_index, double> values;
    for (const auto i : discretisation.locally_owned_dofs())
      values[i] = u(i);
    return values;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       direct = solve("direct");
  double                           size   = 0.;
  for (const auto &[i, value] : direct)
    size = std::max(size, std::abs(value));
  for (const std::string type : {"amg cg", "matrix-free"})
    {
      const auto other = solve(type);
      double     worst = 0.;
      for (const auto &[i, value] : direct)
        worst = std::max(worst, std::abs(value - other.at(i)));
      report("max |u - u_direct| / max |u_direct|", worst / size, 1e-9);
    }
  const auto pg_direct = solve("direct", true);
  for (const std::string type : {"amg cg", "matrix-free"})
    {
      const auto other = solve(type, true);
      double     worst = 0.;
      for (const auto &[i, value] : pg_direct)
        worst = std::max(worst, std::abs(value - other.at(i)));
      report("test weight: max |u - u_direct| / max |u_direct|",
             worst / size,
             1e-9);
    }
  std::cout << "max |u_direct| = " << std::setprecision(6) << size << '\n';
}
