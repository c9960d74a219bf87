// LocalConstraints::distribute() against deal.II's AffineConstraints::
// distribute() on a cube refined towards a corner (hanging nodes), with
// inhomogeneous Dirichlet lines and lines tying a vertex's components as the
// held contact nodes do, on the partitioner of a MatrixFree of the mesh (the
// fast path: every master is owned or a ghost) and on a partitioner without
// ghosts (on two processes some masters are then another's: deal.II's
// distribute() is used); each with a vector given without and with its
// ghost values up to date (which distribute() keeps up to date). The same
// entries to round-off, on one process and on two.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/elasticity/local_constraints.h>

#include "checks.h"
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace dealii;
using namespace signorini;
using checks::first_process;
using checks::report;

namespace
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

  /** Fills the owned entries of @p vector with values that differ. */
  void
  fill(VectorType &vector)
  {
    for (const auto i : vector.locally_owned_elements())
      vector(i) = std::sin(0.37 * i) + 0.01 * i;
  }

  /** The largest difference of the owned entries after both distribute()s
   * of a vector of @p partitioner, given with its ghost values up to date if
   * @p ghosted (then also of its ghost entries against deal.II's, and 1 if
   * they were not kept up to date); @p general: whether LocalConstraints
   * fell back to deal.II's on some process. */
  double
  difference(
    const AffineConstraints<double>                          &constraints,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
    const bool                                                ghosted,
    bool                                                     &general)
  {
    LocalConstraints local;
    local.reinit(constraints, partitioner);
    general = local.falls_back();
    VectorType ours(partitioner), theirs(partitioner);
    fill(ours);
    theirs = ours;
    if (ghosted)
      ours.update_ghost_values();
    local.distribute(ours);
    constraints.distribute(theirs);
    double ghost_difference = 0.;
    if (ghosted)
      {
        theirs.update_ghost_values();
        if (!ours.has_ghost_elements())
          ghost_difference = 1.;
        for (unsigned int i = 0; i < partitioner->n_ghost_indices(); ++i)
          {
            const auto k     = partitioner->locally_owned_size() + i;
            ghost_difference = std::max(ghost_difference,
                                        std::abs(ours.local_element(k) -
                                                 theirs.local_element(k)));
          }
        ours.zero_out_ghost_values();
        theirs.zero_out_ghost_values();
      }
    theirs -= ours;
    return std::max(theirs.linfty_norm(),
                    Utilities::MPI::max(ghost_difference, MPI_COMM_WORLD));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize        mpi(argc, argv, 1);
  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  checks::corner_refined_cube(mesh, 2, 2, 0.5);
  const FESystem<3> fe(FE_Q<3>(1), 3);
  DoFHandler<3>     dofs(mesh);
  dofs.distribute_dofs(fe);
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dofs, relevant);

  AffineConstraints<double> constraints;
  constraints.reinit(relevant);
  // Held vertices on the face z = 1: u_z = 0.2 u_x - 0.1 u_y - 0.05.
  for (const auto &cell : dofs.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto v : cell->vertex_indices())
        if (std::abs(cell->vertex(v)[2] - 1.) < 1e-12)
          {
            const auto z = cell->vertex_dof_index(v, 2);
            if (constraints.is_constrained(z))
              continue;
            constraints.add_line(z);
            constraints.add_entry(z, cell->vertex_dof_index(v, 0), 0.2);
            constraints.add_entry(z, cell->vertex_dof_index(v, 1), -0.1);
            constraints.set_inhomogeneity(z, -0.05);
          }
  AffineConstraints<double> hanging;
  hanging.reinit(relevant);
  DoFTools::make_hanging_node_constraints(dofs, hanging);
  // A Dirichlet value that is not zero and differs from dof to dof.
  FunctionParser<3> boundary(3);
  boundary.initialize("x,y,z", "x + 1; 2 * y; 3 * z", {});
  VectorTools::interpolate_boundary_values(dofs, 0, boundary, hanging);
  hanging.close();
  constraints.merge(hanging, AffineConstraints<double>::left_object_wins);
  constraints.close();
  const auto n_lines =
    Utilities::MPI::sum(constraints.n_constraints(), MPI_COMM_WORLD);
  if (first_process())
    std::cout << "constraint lines (with those of ghost dofs): " << n_lines
              << '\n';

  MatrixFree<3, double>                          matrix_free;
  typename MatrixFree<3, double>::AdditionalData data;
  data.mapping_update_flags = update_gradients;
  matrix_free.reinit(MappingQ1<3>(), dofs, hanging, QGauss<1>(2), data);
  // Without ghosts, some masters are another process's.
  const std::shared_ptr<const Utilities::MPI::Partitioner> owned_only =
    std::make_shared<Utilities::MPI::Partitioner>(dofs.locally_owned_dofs(),
                                                  MPI_COMM_WORLD);
  const std::vector<
    std::pair<std::string, std::shared_ptr<const Utilities::MPI::Partitioner>>>
    partitioners = {{"matrix-free partitioner",
                     matrix_free.get_vector_partitioner()},
                    {"partitioner without ghosts", owned_only}};
  for (const auto &[name, partitioner] : partitioners)
    for (const bool ghosted : {false, true})
      {
        bool general = false;
        report(name + (ghosted ? ", ghost values up to date" : "") +
                 ", max difference",
               difference(constraints, partitioner, ghosted, general),
               1e-14);
        if (first_process() && !ghosted)
          std::cout << "  deal.II's distribute used: "
                    << (general ? "yes" : "no") << '\n';
      }
}
