#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/thread_management.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <signorini/discretisation/axisymmetry.h>
#include <signorini/output/solution_piece.h>

#include <cmath>
#include <optional>

namespace signorini
{
  using namespace dealii;

  std::vector<double>
  relevant_entries(const TrilinosWrappers::MPI::Vector &vector,
                   const IndexSet                      &dofs)
  {
    std::vector<double>    entries(dofs.n_elements());
    const Epetra_BlockMap &map    = vector.trilinos_partitioner();
    const double          *values = vector.trilinos_vector()[0];
    std::size_t            found  = 0;
    for (int k = 0; k < map.NumMyElements(); ++k)
      {
        const auto i =
          dofs.index_within_set(TrilinosWrappers::global_index(map, k));
        if (i != numbers::invalid_dof_index)
          {
            entries[i] = values[k];
            ++found;
          }
      }
    AssertThrow(found == entries.size(),
                ExcMessage("A vector written to the solution file lacks "
                           "locally relevant entries."));
    return entries;
  }


  namespace
  {
    /** The position of the node at @p unit (a support point of Q2) among
     * the points of VTK's Lagrange quadrilateral or hexahedron of order 2:
     * vertices, edges, faces, interior (vtkLagrangeHexahedron's
     * PointIndexFromIJK as ParaView 5.11 gives it, but with the two last
     * edges along z swapped: the files say VTK file version 0.1, and VTK's
     * reader takes a hexahedron of a file older than 2.2 in that legacy
     * order and swaps them back). */
    template <int dim>
    unsigned int
    vtk_lagrange_index(const Point<dim> &unit)
    {
      static constexpr unsigned int quadrilateral[3][3] = {{0, 4, 1},
                                                           {7, 8, 5},
                                                           {3, 6, 2}};
      static constexpr unsigned int hexahedron[3][3][3] = {
        {{0, 8, 1}, {11, 24, 9}, {3, 10, 2}},
        {{16, 22, 17}, {20, 26, 21}, {18, 23, 19}},
        {{4, 12, 5}, {15, 25, 13}, {7, 14, 6}}};
      unsigned int ijk[3] = {0, 0, 0};
      for (unsigned int d = 0; d < dim; ++d)
        ijk[d] = static_cast<unsigned int>(std::lround(2. * unit[d]));
      return dim == 2 ? quadrilateral[ijk[1]][ijk[0]] :
                        hexahedron[ijk[2]][ijk[1]][ijk[0]];
    }
  } // namespace

  template <int dim>
  VtuPiece
  build_piece(const PieceInputs<dim> &in, const unsigned int n_threads)
  {
    std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
    for (const auto &cell : in.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cells.push_back(cell);

    const std::vector<std::string> names = in.fields.names();
    VtuPiece                       piece;
    piece.fields.push_back({"displacement", 3, {}});
    for (const auto &name : names)
      piece.fields.push_back({name, 1, {}});
    for (const std::string name :
         {"contact_pressure", "active_set", "kelly_indicator", "mpi_rank"})
      piece.fields.push_back({name, 1, {}});
    if (cells.empty())
      return piece;

    // All cells are of one kind (the mesh checks rule out mixed meshes).
    // Degree 1: a point at each vertex, the cell of VTK's linear type.
    // Degree 2: a point at each node, a Lagrange cell of VTK's (curved, as
    // the mapping curves it).
    const ReferenceCell       kind = cells[0]->reference_cell();
    const FiniteElement<dim> &fe   = in.dof_handler.get_fe();
    std::vector<Point<dim>>   unit_points;
    std::vector<unsigned int> vtk_order;
    if (fe.degree == 1)
      {
        for (unsigned int v = 0; v < kind.n_vertices(); ++v)
          unit_points.push_back(kind.template vertex<dim>(v));
        vtk_order.resize(unit_points.size());
        for (unsigned int v = 0; v < vtk_order.size(); ++v)
          vtk_order[v] = v;
        if (kind.is_hyper_cube())
          // deal.II numbers a quadrilateral's vertices lexicographically,
          // VTK counterclockwise (per face of a hexahedron).
          for (unsigned int v = 0; v < vtk_order.size(); v += 4)
            std::swap(vtk_order[v + 2], vtk_order[v + 3]);
      }
    else
      {
        // P2's nodes are VTK's Lagrange triangle's and tetrahedron's, in
        // its order (vertices, then the edges' mid-nodes edge by edge).
        unit_points = fe.base_element(0).get_unit_support_points();
        vtk_order.resize(unit_points.size());
        for (unsigned int q = 0; q < unit_points.size(); ++q)
          vtk_order[kind.is_simplex() ?
                      q :
                      vtk_lagrange_index<dim>(unit_points[q])] = q;
      }
    const unsigned int    n_vertices = unit_points.size();
    const std::size_t     n_points   = cells.size() * n_vertices;
    const Quadrature<dim> at_vertices(unit_points);

    piece.points.resize(3 * n_points);
    piece.connectivity.resize(n_points);
    piece.offsets.resize(cells.size());
    piece.types.resize(cells.size(),
                       fe.degree == 1 ? kind.vtk_linear_type() :
                                        kind.vtk_lagrange_type());
    for (auto &field : piece.fields)
      field.values.resize(field.n_components * n_points);

    const bool mean_dilatation =
      in.fields.material_law().template mean_dilatation<dim>(
        fe.reference_cell().is_simplex());
    const bool        revolved = in.fields.material_law().axisymmetric();
    const QGauss<dim> cell_quadrature(fe.degree + 1);
    const auto work = [&](const std::size_t begin, const std::size_t end) {
      // With mean dilatation, the mean of div u over each cell (over the
      // revolved cell, with the hoop strain, in an axisymmetric model).
      std::optional<FEValues<dim>> cell_values;
      if (mean_dilatation)
        cell_values.emplace(in.mapping,
                            fe,
                            cell_quadrature,
                            update_gradients | update_JxW_values |
                              (revolved ?
                                 update_values | update_quadrature_points :
                                 update_default));
      double                               cell_mean = 0.;
      FEValues<dim>                        fe_values(in.mapping,
                              fe,
                              at_vertices,
                              update_values | update_gradients |
                                update_quadrature_points);
      const unsigned int                   n_dofs = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      std::vector<double>       u(n_dofs), pressure(n_dofs), active(n_dofs);
      std::vector<unsigned int> component(n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        component[i] = fe.system_to_component_index(i).first;
      double             values[DisplacementFields<dim>::n_fields];
      const unsigned int n_fields = DisplacementFields<dim>::n_fields;

      for (std::size_t c = begin; c < end; ++c)
        {
          fe_values.reinit(cells[c]);
          cells[c]->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const auto k = in.relevant_dofs.index_within_set(dof_indices[i]);
              u[i]         = in.displacement[k];
              pressure[i]  = in.pressure[k];
              active[i]    = in.active[k];
            }
          const float kelly = in.kelly_indicator(cells[c]->active_cell_index());
          if (mean_dilatation)
            {
              cell_values->reinit(cells[c]);
              double dilatation = 0., volume = 0.;
              for (const unsigned int q :
                   cell_values->quadrature_point_indices())
                {
                  const double JxW =
                    cell_values->JxW(q) *
                    (revolved ?
                       axisymmetry::weight(cell_values->quadrature_point(q)) :
                       1.);
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    {
                      double divergence =
                        cell_values->shape_grad(i, q)[component[i]];
                      if (revolved && component[i] == 0)
                        divergence += cell_values->shape_value(i, q) /
                                      cell_values->quadrature_point(q)[0];
                      dilatation += u[i] * divergence * JxW;
                    }
                  volume += JxW;
                }
              cell_mean = dilatation / volume;
            }
          for (unsigned int q = 0; q < n_vertices; ++q)
            {
              Tensor<1, dim> displacement;
              Tensor<2, dim> gradient;
              double         p = 0., a = 0.;
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const double phi = fe_values.shape_value(i, q);
                  displacement[component[i]] += u[i] * phi;
                  gradient[component[i]] += u[i] * fe_values.shape_grad(i, q);
                  // Nodal scalars sit at one component, zero elsewhere.
                  p += pressure[i] * phi;
                  a += active[i] * phi;
                }
              const Point<dim> &x     = fe_values.quadrature_point(q);
              const std::size_t point = c * n_vertices + q;
              in.fields.evaluate(x,
                                 displacement,
                                 gradient,
                                 values,
                                 mean_dilatation ? &cell_mean : nullptr);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  piece.points[3 * point + d]           = x[d];
                  piece.fields[0].values[3 * point + d] = displacement[d];
                }
              for (unsigned int f = 0; f < n_fields; ++f)
                piece.fields[1 + f].values[point] = values[f];
              piece.fields[1 + n_fields].values[point] = p;
              piece.fields[2 + n_fields].values[point] = a;
              piece.fields[3 + n_fields].values[point] = kelly;
              piece.fields[4 + n_fields].values[point] = in.rank;
              piece.connectivity[point] = c * n_vertices + vtk_order[q];
            }
          piece.offsets[c] = (c + 1) * n_vertices;
        }
    };

    // A thread for each thousand cells at most: on fewer (0.4 ms on one
    // thread) starting a second one saves too little.
    const std::size_t n_chunks = std::max<std::size_t>(
      1, std::min<std::size_t>(n_threads, cells.size() / 1000));
    std::vector<Threads::Task<void>> tasks;
    for (std::size_t chunk = 1; chunk < n_chunks; ++chunk)
      tasks.push_back(Threads::new_task([&work, chunk, n_chunks, &cells]() {
        work(chunk * cells.size() / n_chunks,
             (chunk + 1) * cells.size() / n_chunks);
      }));
    work(0, cells.size() / n_chunks);
    for (auto &task : tasks)
      task.join();
    return piece;
  }
  template VtuPiece
  build_piece(const PieceInputs<2> &, unsigned int);
  template VtuPiece
  build_piece(const PieceInputs<3> &, unsigned int);
} // namespace signorini
