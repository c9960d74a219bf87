#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>

#include <signorini/elasticity/level_transfer.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  LevelTransfer<dim>::clear()
  {
    cellwise.clear();
    distributed.resize(0, 0);
    embeddings.clear();
    initialize = nullptr;
  }

  template <int dim>
  void
  LevelTransfer<dim>::reinit(
    const std::vector<const DoFHandler<dim> *>           &dofs,
    const std::vector<const AffineConstraints<double> *> &constraints,
    const std::function<void(const unsigned int, VectorType &)> &initialize_vector)
  {
    clear();
    initialize     = initialize_vector;
    const auto top = dofs.size() - 1;
    on_one_process =
      Utilities::MPI::n_mpi_processes(dofs[top]->get_communicator()) == 1;
    if (!on_one_process)
      {
        distributed.resize(0, top);
        for (unsigned int level = 1; level <= top; ++level)
          distributed[level].reinit_geometric_transfer(*dofs[level],
                                                       *dofs[level - 1],
                                                       *constraints[level],
                                                       *constraints[level - 1]);
        return;
      }

    const auto &fe = dofs[top]->get_fe();
    dofs_per_cell  = fe.n_dofs_per_cell();
    embeddings.reinit(dofs_per_cell);
    const unsigned int  n = dofs_per_cell;
    std::vector<double> columns(n * n), transposed(n * n);
    for (unsigned int child = 0; child < GeometryInfo<dim>::max_children_per_cell;
         ++child)
      {
        const auto &matrix = fe.get_prolongation_matrix(child);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              columns[j * n + i]    = matrix(i, j);
              transposed[i * n + j] = matrix(i, j);
            }
        embeddings.add({double(child)}, columns);
      }
    for (unsigned int child = 0; child < GeometryInfo<dim>::max_children_per_cell;
         ++child)
      {
        const auto &matrix = fe.get_prolongation_matrix(child);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            transposed[i * n + j] = matrix(i, j);
        embeddings.add({double(child + GeometryInfo<dim>::max_children_per_cell)},
                       transposed);
      }

    cellwise.resize(top + 1);
    for (unsigned int level = 1; level <= top; ++level)
      setup_pair(level,
                 *dofs[level - 1],
                 *dofs[level],
                 *constraints[level - 1],
                 *constraints[level]);
  }

  template <int dim>
  void
  LevelTransfer<dim>::setup_pair(const unsigned int               level,
                                 const DoFHandler<dim>           &coarse,
                                 const DoFHandler<dim>           &fine,
                                 const AffineConstraints<double> &coarse_constraints,
                                 const AffineConstraints<double> &fine_constraints)
  {
    auto &pair              = cellwise[level];
    pair.coarse_constraints = &coarse_constraints;
    initialize(level - 1, pair.coarse_values);
    VectorType fine_vector;
    initialize(level, fine_vector);
    const auto &coarse_partitioner = *pair.coarse_values.get_partitioner();
    const auto &fine_partitioner   = *fine_vector.get_partitioner();

    const unsigned int n = dofs_per_cell;
    std::vector<types::global_dof_index> coarse_indices(n), fine_indices(n);
    const auto add = [&](const typename DoFHandler<dim>::cell_iterator &child,
                         const unsigned int embedding) {
      child->get_dof_indices(fine_indices);
      for (unsigned int i = 0; i < n; ++i)
        {
          pair.fine_dofs.push_back(
            fine_partitioner.global_to_local(fine_indices[i]));
          pair.coarse_dofs.push_back(
            coarse_partitioner.global_to_local(coarse_indices[i]));
        }
      pair.embedding.push_back(embedding);
    };
    const auto &fine_mesh = fine.get_triangulation();
    for (const auto &cell : coarse.active_cell_iterators())
      {
        cell->get_dof_indices(coarse_indices);
        const auto same = fine_mesh.create_cell_iterator(cell->id());
        const typename DoFHandler<dim>::cell_iterator there(&fine_mesh,
                                                            same->level(),
                                                            same->index(),
                                                            &fine);
        if (there->is_active())
          add(there, identity);
        else
          for (unsigned int child = 0; child < there->n_children(); ++child)
            add(there->child(child), child);
      }

    pair.fine_weights.assign(fine_vector.locally_owned_size(), 0.);
    for (const unsigned int i : pair.fine_dofs)
      pair.fine_weights[i] += 1.;
    for (auto &weight : pair.fine_weights)
      weight = weight > 0. ? 1. / weight : 0.;
    for (const auto &line : fine_constraints.get_lines())
      {
        const unsigned int i = fine_partitioner.global_to_local(line.index);
        pair.fine_weights[i] = 0.;
        pair.fine_constrained.push_back(i);
      }
  }

  template <int dim>
  void
  LevelTransfer<dim>::prolongate(const unsigned int to_level,
                                 VectorType        &dst,
                                 const VectorType  &src) const
  {
    if (!on_one_process)
      {
        distributed[to_level].prolongate_and_add(dst = 0., src);
        return;
      }
    const auto &pair   = cellwise[to_level];
    auto       &coarse = pair.coarse_values;
    coarse.copy_locally_owned_data_from(src);
    // The coarse level's hanging nodes from their masters, its Dirichlet
    // dofs zero (homogeneous).
    const auto &partitioner = *coarse.get_partitioner();
    for (const auto &line : pair.coarse_constraints->get_lines())
      {
        double value = 0.;
        for (const auto &[master, weight] : line.entries)
          value += weight * coarse.local_element(
                              partitioner.global_to_local(master));
        coarse.local_element(partitioner.global_to_local(line.index)) = value;
      }
    const unsigned int n = dofs_per_cell;
    double             x[3 * 8], y[3 * 8];
    for (unsigned int c = 0; c < pair.embedding.size(); ++c)
      {
        const unsigned int *coarse_dofs = &pair.coarse_dofs[c * n];
        const unsigned int *fine_dofs   = &pair.fine_dofs[c * n];
        for (unsigned int i = 0; i < n; ++i)
          x[i] = coarse.local_element(coarse_dofs[i]);
        if (pair.embedding[c] == identity)
          for (unsigned int i = 0; i < n; ++i)
            dst.local_element(fine_dofs[i]) = x[i];
        else
          {
            embeddings.apply(pair.embedding[c], x, y);
            for (unsigned int i = 0; i < n; ++i)
              dst.local_element(fine_dofs[i]) = y[i];
          }
      }
    for (const unsigned int i : pair.fine_constrained)
      dst.local_element(i) = 0.;
  }

  template <int dim>
  void
  LevelTransfer<dim>::restrict_and_add(const unsigned int from_level,
                                       VectorType        &dst,
                                       const VectorType  &src) const
  {
    if (!on_one_process)
      {
        distributed[from_level].restrict_and_add(dst, src);
        return;
      }
    const auto &pair   = cellwise[from_level];
    auto       &coarse = pair.coarse_values;
    coarse             = 0.;
    const unsigned int n = dofs_per_cell;
    double             x[3 * 8], y[3 * 8];
    for (unsigned int c = 0; c < pair.embedding.size(); ++c)
      {
        const unsigned int *coarse_dofs = &pair.coarse_dofs[c * n];
        const unsigned int *fine_dofs   = &pair.fine_dofs[c * n];
        for (unsigned int i = 0; i < n; ++i)
          x[i] = src.local_element(fine_dofs[i]) *
                 pair.fine_weights[fine_dofs[i]];
        if (pair.embedding[c] == identity)
          for (unsigned int i = 0; i < n; ++i)
            coarse.local_element(coarse_dofs[i]) += x[i];
        else
          {
            embeddings.apply(pair.embedding[c] +
                               GeometryInfo<dim>::max_children_per_cell,
                             x,
                             y);
            for (unsigned int i = 0; i < n; ++i)
              coarse.local_element(coarse_dofs[i]) += y[i];
          }
      }
    // The transpose of resolving the coarse constraints: a hanging node's
    // sum to its masters, constrained dofs zero.
    const auto &partitioner = *coarse.get_partitioner();
    for (const auto &line : pair.coarse_constraints->get_lines())
      {
        const unsigned int i = partitioner.global_to_local(line.index);
        const double value   = coarse.local_element(i);
        for (const auto &[master, weight] : line.entries)
          coarse.local_element(partitioner.global_to_local(master)) +=
            weight * value;
        coarse.local_element(i) = 0.;
      }
    dst += coarse;
  }

  template class LevelTransfer<2>;
  template class LevelTransfer<3>;
} // namespace signorini
