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
    static_assert(GeometryInfo<dim>::vertices_per_cell <= 8,
                  "a cell's carried vertices are the bits of one byte");
    // Which vertices each locally owned cell carries.
    const IndexSet            &owned = dofs.locally_owned_dofs();
    std::vector<bool>          taken(owned.n_elements(), false);
    std::vector<unsigned char> carried(
      dofs.get_triangulation().n_active_cells(), 0);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto i = cell->vertex_dof_index(v, 0);
            if (!owned.is_element(i))
              continue;
            const auto k = owned.index_within_set(i);
            if (!taken[k])
              {
                taken[k] = true;
                carried[cell->active_cell_index()] |= 1u << v;
              }
          }

    auto &mesh = distributed(dofs);
    mesh.register_data_attach(
      [&dofs, &vectors, carried = std::move(carried)](
        const CellIterator<dim> &mesh_cell, const auto) {
        const auto          cell  = dof_cell(dofs, mesh_cell);
        const unsigned char which = carried[cell->active_cell_index()];
        std::vector<double> values;
        for (const unsigned int v : cell->vertex_indices())
          if (which & (1u << v))
            for (const auto *vector : vectors)
              for (unsigned int d = 0; d < dim; ++d)
                values.push_back((*vector)(cell->vertex_dof_index(v, d)));
        std::vector<char> record(1 + values.size() * sizeof(double));
        record[0] = static_cast<char>(which);
        if (!values.empty())
          std::memcpy(record.data() + 1,
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

    auto              &mesh = distributed(dofs);
    const unsigned int handle =
      mesh.register_data_attach([](const CellIterator<dim> &,
                                   const auto) { return std::vector<char>(); },
                                /*returns_variable_size_data=*/true);
    mesh.notify_ready_to_unpack(
      handle,
      [&](const CellIterator<dim> &mesh_cell,
          const auto,
          const boost::iterator_range<std::vector<char>::const_iterator>
            &record) {
        const auto          cell  = dof_cell(dofs, mesh_cell);
        const unsigned char which = static_cast<unsigned char>(*record.begin());
        const char         *read  = &*record.begin() + 1;
        for (const unsigned int v : cell->vertex_indices())
          if (which & (1u << v))
            for (auto &vector : gathered)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double value;
                  std::memcpy(&value, read, sizeof(value));
                  read += sizeof(value);
                  vector(cell->vertex_dof_index(v, d)) = value;
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
