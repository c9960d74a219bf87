#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/numerics/solution_transfer.h>

#include <signorini/mesh_adaptation/hanging_node_refinement.h>
#include <signorini/mesh_adaptation/partition_balance.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  HangingNodeRefinement<dim>::HangingNodeRefinement(
    const Refinement  &refinement,
    const unsigned int initial_refinement,
    const bool         simplex,
    const MPI_Comm     comm)
    : refinement(refinement)
    , initial_refinement(initial_refinement)
    , simplex(simplex)
    , comm(comm)
  {
  }

  template <int dim>
  std::unique_ptr<Triangulation<dim>>
  HangingNodeRefinement<dim>::create_mesh(const Triangulation<dim> &coarse_mesh)
  {
    std::unique_ptr<Triangulation<dim>> triangulation;
    if (simplex)
      triangulation = std::make_unique<Triangulation<dim>>();
    else
      triangulation =
        std::make_unique<parallel::distributed::Triangulation<dim>>(
          comm,
          typename Triangulation<dim>::MeshSmoothing(
            Triangulation<dim>::smoothing_on_refinement |
            Triangulation<dim>::smoothing_on_coarsening));
    triangulation->copy_triangulation(coarse_mesh);
    triangulation->refine_global(initial_refinement);
    return triangulation;
  }

  template <int dim>
  std::vector<typename HangingNodeRefinement<dim>::VectorType>
  HangingNodeRefinement<dim>::adapt(
    std::unique_ptr<Triangulation<dim>>   &triangulation,
    const DoFHandler<dim>                 &dof_handler,
    const Vector<float>                   &indicators,
    const std::function<void()>           &setup_system,
    const std::vector<const VectorType *> &vectors)
  {
    auto *distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> *>(
        triangulation.get());

    if (refinement.strategy == Refinement::Strategy::global)
      for (const auto &cell : triangulation->active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_refine_flag();
    if (refinement.strategy == Refinement::Strategy::kelly)
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        *distributed,
        indicators,
        refinement.refine_fraction,
        refinement.coarsen_fraction);

    std::vector<VectorType> carried;
    if (distributed)
      {
        parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
          dof_handler);
        triangulation->prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(vectors);
        execute_refinement(*distributed, refinement.imbalance_tolerance);
        setup_system();
        carried.assign(vectors.size(),
                       VectorType(dof_handler.locally_owned_dofs(), comm));
        std::vector<VectorType *> out;
        for (auto &vector : carried)
          out.push_back(&vector);
        transfer.interpolate(out);
      }
    else
      {
        SolutionTransfer<dim, VectorType> transfer(dof_handler);
        std::vector<VectorType>           old_vectors;
        for (const auto *vector : vectors)
          old_vectors.push_back(*vector);
        triangulation->prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(old_vectors);
        triangulation->execute_coarsening_and_refinement();
        setup_system();
        carried.assign(vectors.size(),
                       VectorType(dof_handler.locally_owned_dofs(), comm));
        transfer.interpolate(old_vectors, carried);
      }
    return carried;
  }

  template class HangingNodeRefinement<2>;
  template class HangingNodeRefinement<3>;
} // namespace signorini
