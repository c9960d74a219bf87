#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_tools.h>
#include <deal.II/lac/full_matrix.h>

#include <signorini/elasticity/level_transfer.h>

#include <algorithm>
#include <map>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The active cell of @p mesh that is the cell @p id or an ancestor of
     * it (an artificial one where this process does not know the mesh
     * there). */
    template <int dim>
    typename Triangulation<dim>::cell_iterator
    active_cell_at(const Triangulation<dim> &mesh, const CellId &id)
    {
      auto cell = mesh.create_cell_iterator(
        CellId(id.get_coarse_cell_id(), std::vector<std::uint8_t>()));
      for (const auto child : id.get_child_indices())
        {
          if (!cell->has_children())
            break;
          cell = cell->child(child);
        }
      return cell;
    }

    /** y = R x, or R^T x if @p transpose, R given by its nonzero entries
     * (finer dof, coarse dof, weight); y has @p n_out entries. */
    template <typename Entries>
    void
    apply_raise(const Entries     &raise,
                const bool         transpose,
                const double      *x,
                double            *y,
                const unsigned int n_out)
    {
      std::fill(y, y + n_out, 0.);
      for (const auto &[fine, coarse, weight] : raise)
        if (transpose)
          y[coarse] += weight * x[fine];
        else
          y[fine] += weight * x[coarse];
    }
  } // namespace

  template <int dim>
  void
  LevelTransfer<dim>::clear()
  {
    cellwise.clear();
    distributed.resize(0, 0);
    embeddings.clear();
    initialize = nullptr;
    by_dealii  = false;
  }

  template <int dim>
  void
  LevelTransfer<dim>::reinit(
    const std::vector<const DoFHandler<dim> *>           &dofs,
    const std::vector<const AffineConstraints<double> *> &constraints,
    const std::function<void(const unsigned int, VectorType &)>
      &initialize_vector)
  {
    clear();
    initialize     = initialize_vector;
    const auto top = dofs.size() - 1;

    // The geometric steps are between levels of the coarsest's element.
    const auto        &fe = dofs[0]->get_fe();
    const unsigned int n  = fe.n_dofs_per_cell();
    embeddings.reinit(n);
    constexpr unsigned int children = GeometryInfo<dim>::max_children_per_cell;
    std::vector<double>    columns(n * n);
    for (const bool transpose : {false, true})
      for (unsigned int child = 0; child < children; ++child)
        {
          const auto &matrix = fe.get_prolongation_matrix(child);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              (transpose ? columns[i * n + j] : columns[j * n + i]) =
                matrix(i, j);
          embeddings.add({double(child + (transpose ? children : 0))}, columns);
        }

    cellwise.resize(top + 1);
    for (unsigned int level = 1; level <= top; ++level)
      {
        auto       &pair   = cellwise[level];
        const auto &coarse = dofs[level - 1]->get_fe();
        const auto &finer  = dofs[level]->get_fe();
        pair.n_fine        = finer.n_dofs_per_cell();
        pair.n_coarse      = coarse.n_dofs_per_cell();
        AssertThrow(pair.n_fine <= max_cell_dofs,
                    ExcMessage("a level transfer of degree above 2"));
        if (finer.degree != coarse.degree)
          {
            FullMatrix<double> interpolation(pair.n_fine, pair.n_coarse);
            FETools::get_interpolation_matrix(coarse, finer, interpolation);
            for (unsigned int i = 0; i < pair.n_fine; ++i)
              for (unsigned int j = 0; j < pair.n_coarse; ++j)
                if (std::abs(interpolation(i, j)) > 1e-14)
                  pair.raise.push_back({i, j, interpolation(i, j)});
          }
      }
    bool nested = true;
    for (unsigned int level = 1; level <= top; ++level)
      nested = nested && setup_pair(level,
                                    *dofs[level - 1],
                                    *dofs[level],
                                    *constraints[level - 1],
                                    *constraints[level]);
    if (nested)
      return;

    cellwise.clear();
    by_dealii = true;
    distributed.resize(0, top);
    for (unsigned int level = 1; level <= top; ++level)
      if (dofs[level]->get_fe().degree != dofs[level - 1]->get_fe().degree)
        distributed[level].reinit_polynomial_transfer(*dofs[level],
                                                      *dofs[level - 1],
                                                      *constraints[level],
                                                      *constraints[level - 1]);
      else
        distributed[level].reinit_geometric_transfer(*dofs[level],
                                                     *dofs[level - 1],
                                                     *constraints[level],
                                                     *constraints[level - 1]);
  }

  template <int dim>
  bool
  LevelTransfer<dim>::setup_pair(
    const unsigned int               level,
    const DoFHandler<dim>           &coarse,
    const DoFHandler<dim>           &fine,
    const AffineConstraints<double> &coarse_constraints,
    const AffineConstraints<double> &fine_constraints)
  {
    const MPI_Comm     comm = fine.get_communicator();
    auto              &pair = cellwise[level];
    const unsigned int n    = pair.n_coarse;
    VectorType         fine_vector;
    initialize(level, fine_vector);
    const auto &fine_partitioner = *fine_vector.get_partitioner();
    const auto &coarse_mesh      = coarse.get_triangulation();

    // The owned finer cells; their coarse cells' dofs where this process
    // has those cells, else asked of the others below.
    std::vector<types::global_dof_index> coarse_indices;
    std::vector<types::global_dof_index> indices(n), fine_indices(pair.n_fine);
    std::vector<CellId::binary_type>     asked;
    std::vector<unsigned int>            asked_for;
    bool                                 consistent = true;
    // The embedding of a finer cell at @p fine_level in a coarse cell at
    // @p coarse_level.
    const auto embedding_of = [&](const CellId      &id,
                                  const unsigned int fine_level,
                                  const unsigned int coarse_level) {
      if (coarse_level == fine_level)
        return identity;
      if (coarse_level + 1 == fine_level)
        {
          const auto path = id.get_child_indices();
          return static_cast<unsigned int>(path[path.size() - 1]);
        }
      consistent = false;
      return identity;
    };
    // Reserved whole: grown an entry at a time, the tables would hold up to
    // twice their size.
    unsigned int n_cells = 0;
    for (const auto &cell : fine.active_cell_iterators())
      n_cells += cell->is_locally_owned() ? 1 : 0;
    pair.fine_dofs.reserve(n_cells * pair.n_fine);
    pair.embedding.reserve(n_cells);
    coarse_indices.reserve(n_cells * n);
    for (const auto &cell : fine.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(fine_indices);
          for (const auto index : fine_indices)
            pair.fine_dofs.push_back(fine_partitioner.in_local_range(index) ?
                                       fine_partitioner.global_to_local(index) :
                                       none);
          const auto there = active_cell_at(coarse_mesh, cell->id());
          if (there->is_active() && !there->is_artificial())
            {
              const typename DoFHandler<dim>::active_cell_iterator coarse_cell(
                &coarse_mesh, there->level(), there->index(), &coarse);
              coarse_cell->get_dof_indices(indices);
              pair.embedding.push_back(
                embedding_of(cell->id(), cell->level(), there->level()));
            }
          else
            {
              asked.push_back(cell->id().template to_binary<dim>());
              asked_for.push_back(pair.embedding.size());
              std::fill(indices.begin(),
                        indices.end(),
                        numbers::invalid_dof_index);
              pair.embedding.push_back(identity);
            }
          coarse_indices.insert(coarse_indices.end(),
                                indices.begin(),
                                indices.end());
        }

    // Answers: per asked cell, its number, the coarse cell's level and dofs.
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        const unsigned int me        = Utilities::MPI::this_mpi_process(comm);
        const auto         all_asked = Utilities::MPI::all_gather(comm, asked);
        std::map<unsigned int, std::vector<types::global_dof_index>> answers;
        for (unsigned int rank = 0; rank < all_asked.size(); ++rank)
          if (rank != me)
            for (unsigned int k = 0; k < all_asked[rank].size(); ++k)
              {
                const auto there =
                  active_cell_at(coarse_mesh, CellId(all_asked[rank][k]));
                if (!there->is_active() || !there->is_locally_owned())
                  continue;
                const typename DoFHandler<dim>::active_cell_iterator
                  coarse_cell(&coarse_mesh,
                              there->level(),
                              there->index(),
                              &coarse);
                coarse_cell->get_dof_indices(indices);
                auto &answer = answers[rank];
                answer.push_back(k);
                answer.push_back(there->level());
                answer.insert(answer.end(), indices.begin(), indices.end());
              }
        unsigned int answered = 0;
        for (const auto &[rank, answer] :
             Utilities::MPI::some_to_some(comm, answers))
          for (std::size_t at = 0; at < answer.size(); at += n + 2)
            {
              const unsigned int k     = answer[at];
              const unsigned int patch = asked_for[k];
              const CellId       id(asked[k]);
              pair.embedding[patch] =
                embedding_of(id, id.get_child_indices().size(), answer[at + 1]);
              std::copy(answer.begin() + at + 2,
                        answer.begin() + at + 2 + n,
                        coarse_indices.begin() + patch * n);
              ++answered;
            }
        consistent = consistent && answered == asked.size();
      }
    else
      consistent = consistent && asked.empty();
    if (Utilities::MPI::min(consistent ? 1 : 0, comm) == 0)
      return false;

    // A coarse cell's dofs once for the finer cells in a row that it
    // holds (siblings are consecutive among the active cells).
    {
      std::size_t kept = 0;
      for (std::size_t c = 0; c < pair.embedding.size(); ++c)
        if (c == 0 || !std::equal(coarse_indices.begin() + c * n,
                                  coarse_indices.begin() + (c + 1) * n,
                                  coarse_indices.begin() + kept - n))
          {
            std::copy(coarse_indices.begin() + c * n,
                      coarse_indices.begin() + (c + 1) * n,
                      coarse_indices.begin() + kept);
            kept += n;
            pair.embedding[c] |= new_patch;
          }
      coarse_indices.resize(kept);
      coarse_indices.shrink_to_fit();
    }

    // The coarse values: owned, and the other dofs the patches or the
    // owned constraints read.
    const IndexSet                      &owned = coarse.locally_owned_dofs();
    std::vector<types::global_dof_index> other;
    for (const auto index : coarse_indices)
      if (!owned.is_element(index))
        other.push_back(index);
    for (const auto &line : coarse_constraints.get_lines())
      if (owned.is_element(line.index))
        for (const auto &entry : line.entries)
          if (!owned.is_element(entry.first))
            other.push_back(entry.first);
    std::sort(other.begin(), other.end());
    other.erase(std::unique(other.begin(), other.end()), other.end());
    IndexSet ghosts(coarse.n_dofs());
    ghosts.add_indices(other.begin(), other.end());
    pair.coarse_values.reinit(owned, ghosts, comm);
    const auto &coarse_partitioner = *pair.coarse_values.get_partitioner();
    pair.coarse_dofs.resize(coarse_indices.size());
    for (std::size_t i = 0; i < coarse_indices.size(); ++i)
      pair.coarse_dofs[i] =
        coarse_partitioner.global_to_local(coarse_indices[i]);
    for (const auto &line : coarse_constraints.get_lines())
      if (owned.is_element(line.index))
        {
          std::vector<std::pair<unsigned int, double>> entries;
          for (const auto &[master, weight] : line.entries)
            entries.emplace_back(coarse_partitioner.global_to_local(master),
                                 weight);
          pair.coarse_lines.emplace_back(
            coarse_partitioner.global_to_local(line.index), entries);
        }

    pair.fine_weights.assign(fine_vector.locally_owned_size(), 0.);
    for (const unsigned int i : pair.fine_dofs)
      if (i != none)
        pair.fine_weights[i] += 1.;
    for (auto &weight : pair.fine_weights)
      weight = weight > 0. ? 1. / weight : 0.;
    for (const auto &line : fine_constraints.get_lines())
      if (fine_partitioner.in_local_range(line.index))
        {
          const unsigned int i = fine_partitioner.global_to_local(line.index);
          pair.fine_weights[i] = 0.;
          pair.fine_constrained.push_back(i);
        }
    return true;
  }

  template <int dim>
  void
  LevelTransfer<dim>::prolongate(const unsigned int to_level,
                                 VectorType        &dst,
                                 const VectorType  &src) const
  {
    if (by_dealii)
      {
        dst = 0.;
        distributed[to_level].prolongate_and_add(dst, src);
        return;
      }
    const auto &pair   = cellwise[to_level];
    auto       &coarse = pair.coarse_values;
    coarse.copy_locally_owned_data_from(src);
    coarse.update_ghost_values();
    // The coarse level's hanging nodes from their masters, its Dirichlet
    // dofs zero (homogeneous); then their values where others read them.
    for (const auto &[dof, entries] : pair.coarse_lines)
      {
        double value = 0.;
        for (const auto &[master, weight] : entries)
          value += weight * coarse.local_element(master);
        coarse.local_element(dof) = value;
      }
    coarse.update_ghost_values();

    const unsigned int n = pair.n_coarse, n_fine = pair.n_fine;
    double             x[max_cell_dofs], y[max_cell_dofs];
    std::size_t        next = 0;
    for (unsigned int c = 0; c < pair.embedding.size(); ++c)
      {
        const unsigned int  embedding = pair.embedding[c] & ~new_patch;
        const unsigned int *fine_dofs = &pair.fine_dofs[c * n_fine];
        if (pair.embedding[c] & new_patch)
          {
            for (unsigned int i = 0; i < n; ++i)
              x[i] = coarse.local_element(pair.coarse_dofs[next + i]);
            next += n;
          }
        const double *values = x;
        if (!pair.raise.empty())
          {
            apply_raise(pair.raise, false, x, y, n_fine);
            values = y;
          }
        else if (embedding != identity)
          {
            embeddings.apply(embedding, x, y);
            values = y;
          }
        for (unsigned int i = 0; i < n_fine; ++i)
          if (fine_dofs[i] != none)
            dst.local_element(fine_dofs[i]) = values[i];
      }
    for (const unsigned int i : pair.fine_constrained)
      dst.local_element(i) = 0.;
    coarse.zero_out_ghost_values();
  }

  template <int dim>
  void
  LevelTransfer<dim>::restrict_and_add(const unsigned int from_level,
                                       VectorType        &dst,
                                       const VectorType  &src) const
  {
    if (by_dealii)
      {
        distributed[from_level].restrict_and_add(dst, src);
        return;
      }
    const auto &pair   = cellwise[from_level];
    auto       &coarse = pair.coarse_values;
    coarse             = 0.;
    coarse.zero_out_ghost_values();
    const unsigned int     n = pair.n_coarse, n_fine = pair.n_fine;
    constexpr unsigned int children = GeometryInfo<dim>::max_children_per_cell;
    double                 x[max_cell_dofs], y[max_cell_dofs];
    const unsigned int    *coarse_dofs = nullptr;
    std::size_t            next        = 0;
    for (unsigned int c = 0; c < pair.embedding.size(); ++c)
      {
        const unsigned int  embedding = pair.embedding[c] & ~new_patch;
        const unsigned int *fine_dofs = &pair.fine_dofs[c * n_fine];
        if (pair.embedding[c] & new_patch)
          {
            coarse_dofs = &pair.coarse_dofs[next];
            next += n;
          }
        for (unsigned int i = 0; i < n_fine; ++i)
          x[i] = fine_dofs[i] == none ? 0. :
                                        src.local_element(fine_dofs[i]) *
                                          pair.fine_weights[fine_dofs[i]];
        const double *values = x;
        if (!pair.raise.empty())
          {
            apply_raise(pair.raise, true, x, y, n);
            values = y;
          }
        else if (embedding != identity)
          {
            embeddings.apply(embedding + children, x, y);
            values = y;
          }
        for (unsigned int i = 0; i < n; ++i)
          coarse.local_element(coarse_dofs[i]) += values[i];
      }
    coarse.compress(VectorOperation::add);
    // The transpose of resolving the coarse constraints: a hanging node's
    // sum to its masters, constrained dofs zero.
    for (const auto &[dof, entries] : pair.coarse_lines)
      {
        const double value        = coarse.local_element(dof);
        coarse.local_element(dof) = 0.;
        for (const auto &[master, weight] : entries)
          coarse.local_element(master) += weight * value;
      }
    coarse.compress(VectorOperation::add);
    for (unsigned int i = 0; i < coarse.locally_owned_size(); ++i)
      dst.local_element(i) += coarse.local_element(i);
  }

  template class LevelTransfer<2>;
  template class LevelTransfer<3>;
} // namespace signorini
