// The multigrid's meshes and transfer, on one process and on two (where
// most coarse cells of a process's finer cells are another's):
// coarsening_sequence gives the same meshes as deal.II's
// create_geometric_coarsening_sequence (cells per level) on a cube refined
// locally with hanging nodes; and LevelTransfer between each pair of levels
// carries a linear field (zero on the clamped face) exactly, zero at the
// constrained dofs, with its restriction the transpose of its prolongation: (P
// x, y) = (x, R y). The last pair is the p-step of a Q2 operator's multigrid:
// Q1 and Q2 on the finest mesh.

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/elasticity/coarsening_sequence.h>
#include <signorini/elasticity/level_transfer.h>

#include "checks.h"
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

using namespace dealii;
using namespace signorini;
using checks::first_process;
using checks::report;

namespace
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

  /** u = x (1, 2, 3): linear, zero on the face x = 0. */
  class Linear : public Function<3>
  {
  public:
    Linear()
      : Function<3>(3)
    {
    }
    double
    value(const Point<3> &p, const unsigned int component) const override
    {
      return p[0] * (component + 1.);
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize        mpi(argc, argv, 1);
  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  // Refined towards a corner three times: levels 1 to 4, hanging nodes.
  checks::corner_refined_cube(mesh, 1, 3, 0.6);

  const auto ours = coarsening_sequence(mesh);
  const auto dealii =
    MGTransferGlobalCoarseningTools::create_geometric_coarsening_sequence(mesh);
  if (first_process())
    std::cout << "levels: " << ours.size() << " (deal.II " << dealii.size()
              << ")\n";
  bool same = ours.size() == dealii.size();
  for (unsigned int level = 0; same && level < ours.size(); ++level)
    {
      if (first_process())
        std::cout << "  level " << level << ": "
                  << ours[level]->n_global_active_cells() << " cells\n";
      same = ours[level]->n_global_active_cells() ==
             dealii[level]->n_global_active_cells();
    }
  if (first_process())
    std::cout << "  same cells per level as deal.II: " << (same ? "yes" : "no")
              << '\n';

  const FESystem<3>                                       fe(FE_Q<3>(1), 3);
  const FESystem<3>                                       fe_q2(FE_Q<3>(2), 3);
  std::vector<std::unique_ptr<DoFHandler<3>>>             dofs;
  std::vector<std::unique_ptr<AffineConstraints<double>>> constraints;
  std::vector<const DoFHandler<3> *>                      dof_pointers;
  std::vector<const AffineConstraints<double> *>          constraint_pointers;
  for (unsigned int level = 0; level <= ours.size(); ++level)
    {
      const bool raised = level == ours.size();
      dofs.push_back(
        std::make_unique<DoFHandler<3>>(*ours[raised ? level - 1 : level]));
      dofs.back()->distribute_dofs(raised ? fe_q2 : fe);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(*dofs.back(), relevant);
      constraints.push_back(std::make_unique<AffineConstraints<double>>());
      constraints.back()->reinit(relevant);
      DoFTools::make_hanging_node_constraints(*dofs.back(),
                                              *constraints.back());
      VectorTools::interpolate_boundary_values(*dofs.back(),
                                               0,
                                               Functions::ZeroFunction<3>(3),
                                               *constraints.back());
      constraints.back()->close();
      dof_pointers.push_back(dofs.back().get());
      constraint_pointers.push_back(constraints.back().get());
    }
  const auto initialize = [&](const unsigned int level, VectorType &vector) {
    vector.reinit(dofs[level]->locally_owned_dofs(), MPI_COMM_WORLD);
  };
  // The linear field at every dof (interpolated on a vector with the
  // locally relevant dofs, which deal.II's interpolation writes to).
  const auto interpolate_linear = [&](const unsigned int level, VectorType &v) {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(*dofs[level], relevant);
    VectorType with_ghosts(dofs[level]->locally_owned_dofs(),
                           relevant,
                           MPI_COMM_WORLD);
    VectorTools::interpolate(*dofs[level], Linear(), with_ghosts);
    v.copy_locally_owned_data_from(with_ghosts);
  };
  LevelTransfer<3> transfer;
  transfer.reinit(dof_pointers, constraint_pointers, initialize);

  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const auto random_vector = [&](const unsigned int level, VectorType &v) {
    initialize(level, v);
    for (auto &entry : v)
      entry = uniform(random);
    for (const auto &line : constraints[level]->get_lines())
      if (v.in_local_range(line.index))
        v(line.index) = 0.;
  };
  for (unsigned int level = 1; level < dofs.size(); ++level)
    {
      if (first_process())
        std::cout << "levels " << level - 1 << " -> " << level << " ("
                  << dofs[level - 1]->n_dofs() << " -> "
                  << dofs[level]->n_dofs() << " dofs)\n";
      VectorType coarse, fine, exact;
      initialize(level - 1, coarse);
      initialize(level, fine);
      initialize(level, exact);
      interpolate_linear(level - 1, coarse);
      interpolate_linear(level, exact);
      for (const auto &line : constraints[level]->get_lines())
        if (exact.in_local_range(line.index))
          exact(line.index) = 0.;
      transfer.prolongate(level, fine, coarse);
      fine -= exact;
      report("linear field, max difference", fine.linfty_norm(), 1e-14);

      VectorType x, y, px, ry;
      random_vector(level - 1, x);
      random_vector(level, y);
      initialize(level, px);
      initialize(level - 1, ry);
      transfer.prolongate(level, px, x);
      transfer.restrict_and_add(level, ry, y);
      const double left = px * y, right = x * ry;
      report("(P x, y) - (x, R y), relative",
             std::abs(left - right) / std::abs(left),
             1e-13);
    }
}
