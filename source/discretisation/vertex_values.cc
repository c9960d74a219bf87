#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <signorini/discretisation/vertex_values.h>

#include <cstring>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    using CellIterator =
      typename parallel::distributed::Triangulation<dim>::cell_iterator;

    /** The cell of @p dofs that is @p cell of its mesh. */
    template <int dim>
    typename DoFHandler<dim>::cell_iterator
    dof_cell(const DoFHandler<dim> &dofs, const CellIterator<dim> &cell)
    {
      return {&dofs.get_triangulation(), cell->level(), cell->index(), &dofs};
    }

    /** The distributed mesh of @p dofs, to attach data to. */
    template <int dim>
    parallel::distributed::Triangulation<dim> &
    distributed(const DoFHandler<dim> &dofs)
    {
      return const_cast<parallel::distributed::Triangulation<dim> &>(
        dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
          dofs.get_triangulation()));
    }
  } // namespace

  template <int dim>
  void
  VertexValues<dim>::attach(const DoFHandler<dim>                 &dofs,
                            const std::vector<const VectorType *> &vectors)
  {
    // Which nodes each locally owned cell carries: a bit per node (its
    // support point of the base element), in bytes.
    const auto                &fe      = dofs.get_fe();
    const unsigned int         n_nodes = fe.base_element(0).n_dofs_per_cell();
    const unsigned int         n_bytes = (n_nodes + 7) / 8;
    const IndexSet            &owned   = dofs.locally_owned_dofs();
    std::vector<bool>          taken(owned.n_elements(), false);
    std::vector<unsigned char> carried(
      dofs.get_triangulation().n_active_cells() * n_bytes, 0);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int b = 0; b < n_nodes; ++b)
            {
              const auto i = cell_dofs[fe.component_to_system_index(0, b)];
              if (!owned.is_element(i))
                continue;
              const auto k = owned.index_within_set(i);
              if (!taken[k])
                {
                  taken[k] = true;
                  carried[cell->active_cell_index() * n_bytes + b / 8] |=
                    1u << (b % 8);
                }
            }
        }

    auto &mesh = distributed(dofs);
    mesh.register_data_attach(
      [&dofs, &vectors, n_nodes, n_bytes, carried = std::move(carried)](
        const CellIterator<dim> &mesh_cell, const auto) {
        const auto           cell = dof_cell(dofs, mesh_cell);
        const unsigned char *which =
          &carried[cell->active_cell_index() * n_bytes];
        const auto                          &fe = dofs.get_fe();
        std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
        cell->get_dof_indices(cell_dofs);
        std::vector<double> values;
        for (unsigned int b = 0; b < n_nodes; ++b)
          if (which[b / 8] & (1u << (b % 8)))
            for (const auto *vector : vectors)
              for (unsigned int d = 0; d < dim; ++d)
                values.push_back(
                  (*vector)(cell_dofs[fe.component_to_system_index(d, b)]));
        std::vector<char> record(n_bytes + values.size() * sizeof(double));
        std::memcpy(record.data(), which, n_bytes);
        if (!values.empty())
          std::memcpy(record.data() + n_bytes,
                      values.data(),
                      values.size() * sizeof(double));
        return record;
      },
      /*returns_variable_size_data=*/true);
  }

  template <int dim>
  void
  VertexValues<dim>::restore(const DoFHandler<dim>           &dofs,
                             const std::vector<VectorType *> &vectors)
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    const IndexSet &owned = dofs.locally_owned_dofs();
    const MPI_Comm  comm  = dofs.get_communicator();
    std::vector<LinearAlgebra::distributed::Vector<double>> gathered(
      vectors.size());
    for (auto &vector : gathered)
      vector.reinit(owned, relevant, comm);

    const auto        &fe      = dofs.get_fe();
    const unsigned int n_nodes = fe.base_element(0).n_dofs_per_cell();
    const unsigned int n_bytes = (n_nodes + 7) / 8;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    auto                                &mesh = distributed(dofs);
    const unsigned int                   handle =
      mesh.register_data_attach([](const CellIterator<dim> &,
                                   const auto) { return std::vector<char>(); },
                                /*returns_variable_size_data=*/true);
    mesh.notify_ready_to_unpack(
      handle,
      [&](const CellIterator<dim> &mesh_cell,
          const auto,
          const boost::iterator_range<std::vector<char>::const_iterator>
            &record) {
        const auto  cell  = dof_cell(dofs, mesh_cell);
        const char *which = &*record.begin();
        const char *read  = which + n_bytes;
        cell->get_dof_indices(cell_dofs);
        for (unsigned int b = 0; b < n_nodes; ++b)
          if (static_cast<unsigned char>(which[b / 8]) & (1u << (b % 8)))
            for (auto &vector : gathered)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double value;
                  std::memcpy(&value, read, sizeof(value));
                  read += sizeof(value);
                  vector(cell_dofs[fe.component_to_system_index(d, b)]) = value;
                }
      });

    // Each value was written once, on its carrier's process: the sum over
    // the processes is that value.
    for (unsigned int k = 0; k < vectors.size(); ++k)
      {
        gathered[k].compress(VectorOperation::add);
        for (const auto i : owned)
          (*vectors[k])(i) = gathered[k](i);
        vectors[k]->compress(VectorOperation::insert);
      }
  }

  template class VertexValues<2>;
  template class VertexValues<3>;
} // namespace signorini
