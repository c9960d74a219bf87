#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>

#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/cell_stiffness.h>
#include <signorini/elasticity/elastic_level_operator.h>

#include <algorithm>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  std::vector<unsigned int>
  ElasticLevelOperator<dim>::evaluation_positions() const
  {
    // A node's lexicographic index from its unit support point: the sum of
    // x_d * degree * (degree + 1)^d.
    const auto        &fe     = dof_handler->get_fe();
    const unsigned int n      = fe.n_dofs_per_cell();
    const auto        &points = fe.base_element(0).get_unit_support_points();
    std::vector<unsigned int> position(n);
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto [component, node] = fe.system_to_component_index(k);
        unsigned int lexicographic = 0, stride = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lexicographic += stride * static_cast<unsigned int>(std::lround(
                                        points[node][d] * fe.degree));
            stride *= fe.degree + 1;
          }
        position[k] = component * (n / dim) + lexicographic;
      }
    return position;
  }

  template <int dim>
  bool
  ElasticLevelOperator<dim>::setup_by_vertices(const Mapping<dim> &mapping,
                                               std::vector<CellIterator> &cells)
  {
    const unsigned int n        = n_cell_dofs;
    const auto        &dofs     = *dof_handler;
    const auto         position = evaluation_positions();
    cells.clear();
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        cells.push_back(cell);
    cell_matrices.reinit(n);
    matrix_of_cell.assign(cells.size(), CellMatrices::none);

    // A parallelepiped's vertices are vertex 0 plus sums of its edges from
    // vertex 0 (vertices 1, 2, 4): its Jacobian, constant. Its shape's key
    // is the inverse Jacobian rounded to 40 bits below its largest entry,
    // so that cells equal up to round-off share a matrix.
    FEValues<dim>     fe_values(mapping,
                            dofs.get_fe(),
                            QGauss<dim>(fe_degree + 1),
                            elastic_update_flags(material));
    const auto *const polynomial =
      dynamic_cast<const MappingQ<dim> *>(&mapping);
    const bool follows_manifolds = polynomial && polynomial->get_degree() > 1;
    CellStiffness<dim>  stiffness(material);
    FullMatrix<double>  cell_matrix(n, n);
    std::vector<double> columns(n * n);
    CellMatrices::Key   key(dim * dim);
    bool                all = true;
    for (unsigned int c = 0; c < cells.size() && all; ++c)
      {
        const auto    &cell = cells[c];
        Tensor<2, dim> jacobian;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int a = 0; a < dim; ++a)
            jacobian[a][d] = cell->vertex(1u << d)[a] - cell->vertex(0)[a];
        const double tolerance = 1e-12 * cell->diameter();
        for (const unsigned int v : cell->vertex_indices())
          {
            Point<dim> expected = cell->vertex(0);
            for (unsigned int d = 0; d < dim; ++d)
              if (v & (1u << d))
                for (unsigned int a = 0; a < dim; ++a)
                  expected[a] += jacobian[a][d];
            all = all && expected.distance(cell->vertex(v)) <= tolerance;
          }
        // A mapping above degree 1 follows the manifolds (at degree 2,
        // and on the Q1 levels below it): a cell on a curved one is not
        // the image of its vertices.
        all = all && (!follows_manifolds || on_flat_manifolds(cell));
        if (!all)
          break;
        const Tensor<2, dim> inverse = invert(jacobian);
        double               largest = 0.;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            largest = std::max(largest, std::abs(inverse[a][b]));
        const int exponent = std::ilogb(largest) - 40;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            key[a * dim + b] =
              std::ldexp(std::round(std::ldexp(inverse[a][b], -exponent)),
                         exponent);
        unsigned int index = cell_matrices.find(key);
        if (index == CellMatrices::none)
          {
            fe_values.reinit(cell);
            stiffness.compute(fe_values, cell_matrix);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                columns[position[j] * n + position[i]] = cell_matrix(i, j);
            index = cell_matrices.add(key, columns);
            all   = index != CellMatrices::none;
          }
        matrix_of_cell[c] = index;
      }
    if (Utilities::MPI::logical_or(!all, dofs.get_communicator()))
      {
        cells.clear();
        cell_matrices.clear();
        matrix_of_cell = {};
        return false;
      }

    // The vectors' layout: the owned dofs, and as ghosts the others that
    // the cells read, their constrained dofs' masters too.
    const IndexSet                      &owned = dofs.locally_owned_dofs();
    std::vector<types::global_dof_index> ghosts, indices(n);
    for (const auto &cell : cells)
      {
        cell->get_dof_indices(indices);
        for (const auto i : indices)
          {
            if (!owned.is_element(i))
              ghosts.push_back(i);
            if (const auto *entries = constraints->get_constraint_entries(i))
              for (const auto &entry : *entries)
                if (!owned.is_element(entry.first))
                  ghosts.push_back(entry.first);
          }
      }
    IndexSet ghost_set(dofs.n_dofs()); // (sorts and merges them)
    ghost_set.add_indices(ghosts.begin(), ghosts.end());
    partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(owned,
                                                    ghost_set,
                                                    dofs.get_communicator());
    return true;
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::setup_affine_cells(
    const std::vector<CellIterator> &cells)
  {
    // B = sqrt(det J) J^{-1}, J from the edges at vertex 0.
    curved_cells.reinit(dim, 2, mu, lambda, true);
    std::vector<double> B(dim * dim);
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        Tensor<2, dim> jacobian;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int a = 0; a < dim; ++a)
            jacobian[a][d] =
              cells[c]->vertex(1u << d)[a] - cells[c]->vertex(0)[a];
        const Tensor<2, dim> inverse = invert(jacobian);
        const double         root = std::sqrt(std::abs(determinant(jacobian)));
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int j = 0; j < dim; ++j)
            B[k * dim + j] = root * inverse[k][j];
        curved_of_cell[c] = curved_cells.add(B);
      }
  }

  template std::vector<unsigned int>
  ElasticLevelOperator<2>::evaluation_positions() const;
  template std::vector<unsigned int>
  ElasticLevelOperator<3>::evaluation_positions() const;
  template void
  ElasticLevelOperator<2>::setup_affine_cells(
    const std::vector<CellIterator> &);
  template void
  ElasticLevelOperator<3>::setup_affine_cells(
    const std::vector<CellIterator> &);
  template bool
  ElasticLevelOperator<2>::setup_by_vertices(const Mapping<2> &,
                                             std::vector<CellIterator> &);
  template bool
  ElasticLevelOperator<3>::setup_by_vertices(const Mapping<3> &,
                                             std::vector<CellIterator> &);
} // namespace signorini
