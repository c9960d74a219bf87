#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/matrix_free/tools.h>

#include <signorini/elasticity/elastic_level_operator.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <unordered_map>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ElasticLevelOperator<dim>::ElasticLevelOperator(const Material &material)
    : material(material)
    , mu(material.mu())
    , lambda(material.template lambda<dim>())
  {
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::reinit(const Mapping<dim>              &mapping,
                                    const DoFHandler<dim>           &dofs,
                                    const AffineConstraints<double> &given)
  {
    constraints = &given;
    dof_handler = &dofs;
    fe_degree   = dofs.get_fe().degree;
    n_cell_dofs = dofs.get_fe().n_dofs_per_cell();
    AssertThrow(fe_degree == 1 || fe_degree == 2,
                ExcMessage("the matrix-free operator is of degree 1 or 2"));
    std::vector<CellIterator> cells;
    by_vertices = setup_by_vertices(mapping, cells);
    if (by_vertices)
      {
        matrix_free.clear();
        curved_cells.clear();
        curved_of_cell.assign(matrix_of_cell.size(), CellMatrices::none);
        // (A Q2 quadrilateral's 18 x 18 matrix stays cheaper.)
        if (fe_degree == 2 && dim == 3)
          setup_affine_cells(cells);
      }
    else
      {
        typename MatrixFree<dim, double>::AdditionalData data;
        data.tasks_parallel_scheme =
          MatrixFree<dim, double>::AdditionalData::none;
        data.mapping_update_flags = update_gradients | update_JxW_values;
        matrix_free.reinit(
          mapping, dofs, given, QGauss<1>(fe_degree + 1), data);
        partitioner = matrix_free.get_vector_partitioner();
        with_degree([&](const auto degree) {
          setup_cell_matrices<decltype(degree)::value>();
        });
        for (unsigned int cell = 0; cell < matrix_free.n_cell_batches(); ++cell)
          cells.push_back(matrix_free.get_cell_iterator(cell, 0));
      }

    constrained.clear();
    for (const auto i : dofs.locally_owned_dofs())
      if (given.is_constrained(i))
        constrained.push_back(partitioner->global_to_local(i));
    with_degree([&](const auto degree) {
      compute_diagonal<decltype(degree)::value>(cells);
    });
    initialize_dof_vector(projected);
    set_contact({}, {});
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::clear()
  {
    matrix_free.clear();
    cell_matrices.clear();
    matrix_of_cell = {};
    curved_cells.clear();
    curved_of_cell      = {};
    cell_dofs           = {};
    resolved_dofs       = {};
    batch_dofs          = {};
    batch_patches       = {};
    batch_patch_offsets = {};
    direct              = {};
    line_offsets.clear();
    line_entries.clear();
    line_dof.clear();
    line_values = {};
    line_forces = {};
    constraints = nullptr;
    dof_handler = nullptr;
    partitioner.reset();
    by_vertices = false;
    constrained.clear();
    identity.clear();
    held.clear();
    held_test.clear();
    blocks.clear();
    symmetric_blocks.clear();
    diagonal_without_contact.reinit(0);
    inverse.reinit(0);
    projected.reinit(0);
  }

  template <int dim>
  template <typename F>
  void
  ElasticLevelOperator<dim>::with_degree(const F &f) const
  {
    if (fe_degree == 2)
      f(std::integral_constant<int, 2>());
    else
      f(std::integral_constant<int, 1>());
  }

  template <int dim>
  template <int degree>
  void
  ElasticLevelOperator<dim>::quadrature_matrix(
    Evaluation<degree>  &phi,
    std::vector<double> &columns) const
  {
    constexpr unsigned int n = Evaluation<degree>::static_dofs_per_cell;
    for (unsigned int j = 0; j < n; ++j)
      {
        for (unsigned int i = 0; i < n; ++i)
          phi.begin_dof_values()[i] = (i == j) ? 1. : 0.;
        apply_at_quadrature_points(phi);
        for (unsigned int i = 0; i < n; ++i)
          columns[j * n + i] = phi.begin_dof_values()[i][0];
      }
  }

  template <int dim>
  template <int degree>
  void
  ElasticLevelOperator<dim>::setup_cell_matrices()
  {
    using CellEvaluation = Evaluation<degree>;
    static_assert(VectorizedArray<double>::size() == 1 &&
                    sizeof(VectorizedArray<double>) == sizeof(double),
                  "a cell batch of one cell (Debian's deal.II)");
    constexpr unsigned int n = CellEvaluation::static_dofs_per_cell;
    cell_matrices.reinit(n);
    matrix_of_cell.assign(matrix_free.n_cell_batches(), CellMatrices::none);
    CellEvaluation      phi(matrix_free);
    CellMatrices::Key   key(dim * dim);
    std::vector<double> columns(n * n);
    curved_cells.reinit(dim, degree, mu, lambda);
    curved_of_cell.assign(matrix_free.n_cell_batches(), CellMatrices::none);
    std::vector<double> geometry(phi.n_q_points * dim * dim);
    // A cell without a matrix (curved, or of a shape beyond
    // CellMatrices::max_matrices): B_q = sqrt(JxW) J^{-1}, FEEvaluation's
    // inverse_jacobian() being J^{-T}, entry [j][k] = d xi_k / d x_j.
    const auto add_curved = [&](const unsigned int cell) {
      for (unsigned int q = 0; q < phi.n_q_points; ++q)
        {
          const auto   inverse = phi.inverse_jacobian(q);
          const double root    = std::sqrt(phi.JxW(q)[0]);
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int j = 0; j < dim; ++j)
              geometry[(q * dim + k) * dim + j] = root * inverse[j][k][0];
        }
      curved_of_cell[cell] = curved_cells.add(geometry);
    };
    for (unsigned int cell = 0; cell < matrix_free.n_cell_batches(); ++cell)
      {
        phi.reinit(cell);
        if (phi.get_cell_type() > internal::MatrixFreeFunctions::affine)
          {
            add_curved(cell);
            continue;
          }
        const auto jacobian = phi.inverse_jacobian(0);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            key[a * dim + b] = jacobian[a][b][0];
        unsigned int index = cell_matrices.find(key);
        if (index == CellMatrices::none)
          {
            quadrature_matrix(phi, columns);
            index = cell_matrices.add(key, columns);
          }
        matrix_of_cell[cell] = index;
        if (index == CellMatrices::none)
          add_curved(cell);
      }
  }

  template <int dim>
  template <int degree>
  void
  ElasticLevelOperator<dim>::apply_cell(Evaluation<degree> &phi) const
  {
    using CellEvaluation     = Evaluation<degree>;
    const unsigned int index = matrix_of_cell[phi.get_current_cell_index()];
    if (index == CellMatrices::none)
      {
        apply_at_quadrature_points(phi);
        return;
      }
    constexpr unsigned int n = CellEvaluation::static_dofs_per_cell;
    double                 x[n];
    double *const          values = &phi.begin_dof_values()[0][0];
    std::copy(values, values + n, x);
    cell_matrices.apply(index, x, values);
  }

  template <int dim>
  template <int degree>
  void
  ElasticLevelOperator<dim>::apply_at_quadrature_points(
    Evaluation<degree> &phi) const
  {
    phi.evaluate(EvaluationFlags::gradients);
    for (unsigned int q = 0; q < phi.n_q_points; ++q)
      {
        const auto strain     = phi.get_symmetric_gradient(q);
        auto       stress     = (2. * mu) * strain;
        const auto volumetric = lambda * trace(strain);
        for (unsigned int d = 0; d < dim; ++d)
          stress[d][d] += volumetric;
        phi.submit_symmetric_gradient(stress, q);
      }
    phi.integrate(EvaluationFlags::gradients);
  }

  template <int dim>
  template <int degree, bool as_given, typename CellNumber>
  void
  ElasticLevelOperator<dim>::apply_cells(VectorType       &dst,
                                         const VectorType &src) const
  {
    constexpr unsigned int n = dim * Utilities::pow(degree + 1, dim);
    // The values by local index, owned and ghost ones (raw: a store through
    // dst does not make the compiler read either vector's address again).
    const double *const in  = src.begin();
    double *const       out = dst.begin();
    // x = C src (src itself if @p as_given), dst += C^T y, C the
    // constraints: a constrained dof is read from its line's value, and
    // writes to its line's force, both once per line here.
    const unsigned int n_lines = line_dof.size();
    line_values.resize(n_lines);
    line_forces.assign(n_lines, 0.);
    for (unsigned int line = 0; line < n_lines; ++line)
      if (as_given)
        line_values[line] = in[line_dof[line]];
      else
        {
          double value = 0.;
          for (unsigned int e = line_offsets[line]; e < line_offsets[line + 1];
               ++e)
            value += line_entries[e].second * in[line_entries[e].first];
          line_values[line] = value;
        }
    // A resolved cell's values, and its forces.
    const auto gather = [&](const unsigned int cell, CellNumber *x) {
      const unsigned int *dofs =
        &resolved_dofs[std::size_t(cell_dofs[cell * (n / dim)]) * n];
      for (unsigned int i = 0; i < n; ++i)
        x[i] = (dofs[i] & constrained_flag) ?
                 line_values[dofs[i] & ~constrained_flag] :
                 in[dofs[i]];
    };
    const auto scatter = [&](const unsigned int cell, const CellNumber *y) {
      const unsigned int *dofs =
        &resolved_dofs[std::size_t(cell_dofs[cell * (n / dim)]) * n];
      for (unsigned int i = 0; i < n; ++i)
        if (dofs[i] & constrained_flag)
          line_forces[dofs[i] & ~constrained_flag] += y[i];
        else
          out[dofs[i]] += y[i];
    };
    // The curved cells a batch at a time (when its first lane's cell comes):
    // x by dof, then lane, read and written through the index lists of
    // their batches of eight; in single precision (CellNumber float), two
    // of them side by side, sixteen lanes.
    constexpr bool         single = std::is_same_v<CellNumber, float>;
    constexpr unsigned int lanes  = CurvedCells::lanes,
                           wide   = single ? CurvedCells::single_lanes : lanes;
    const unsigned int        n_batches = batch_patch_offsets.size() - 1;
    AlignedVector<CellNumber> batch_x(n * wide), batch_y(n * wide);
    CellNumber *const bx = batch_x.data(), *const by = batch_y.data();
    const auto apply_batch = [&](const unsigned int batch) {
      // The wide batch's lanes half * 8 on are batch of eight
      // batch * halves + half.
      constexpr unsigned int halves = wide / lanes;
      // Entry `position` (dof, then lane) of batch of eight `half`.
      const auto slot = [&](const unsigned int half,
                            const unsigned int position) {
        return (position / lanes) * wide + half * lanes + position % lanes;
      };
      for (unsigned int half = 0; half < halves; ++half)
        {
          const unsigned int eight = batch * halves + half;
          if (eight >= n_batches)
            {
              for (unsigned int position = 0; position < n * lanes; ++position)
                bx[slot(half, position)] = 0.;
              continue;
            }
          const unsigned int *dofs =
            &batch_dofs[std::size_t(eight) * n * lanes];
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int l = 0; l < lanes; ++l)
              bx[i * wide + half * lanes + l] = in[dofs[i * lanes + l]];
          for (unsigned int p = batch_patch_offsets[eight];
               p < batch_patch_offsets[eight + 1];
               ++p)
            {
              const auto [position, line] = batch_patches[p];
              bx[slot(half, position)] =
                line == CellMatrices::none ? 0. : line_values[line];
            }
        }
      if constexpr (single)
        curved_cells.apply_single(batch, bx, by);
      else
        curved_cells.apply(batch, bx, by);
      for (unsigned int half = 0; half < halves; ++half)
        {
          const unsigned int eight = batch * halves + half;
          if (eight >= n_batches)
            continue;
          for (unsigned int p = batch_patch_offsets[eight];
               p < batch_patch_offsets[eight + 1];
               ++p)
            {
              const auto [position, line] = batch_patches[p];
              if (line != CellMatrices::none)
                line_forces[line] += by[slot(half, position)];
              by[slot(half, position)] = 0.;
            }
          const unsigned int *dofs =
            &batch_dofs[std::size_t(eight) * n * lanes];
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int l = 0; l < lanes; ++l)
              out[dofs[i * lanes + l]] += by[i * wide + half * lanes + l];
        }
    };

    CellNumber x[n], y[n];
    for (unsigned int cell = 0; cell < matrix_of_cell.size(); ++cell)
      if (curved_of_cell[cell] != CellMatrices::none)
        {
          if (curved_of_cell[cell] % wide == 0)
            apply_batch(curved_of_cell[cell] / wide);
        }
      else if (direct[cell])
        {
          // A vertex's dim dofs are consecutive: one index per vertex.
          constexpr unsigned int n_vertex = n / dim;
          const unsigned int    *base     = &cell_dofs[cell * n_vertex];
          for (unsigned int v = 0; v < n_vertex; ++v)
            for (unsigned int a = 0; a < dim; ++a)
              x[a * n_vertex + v] = in[base[v] + a];
          cell_matrices.apply(matrix_of_cell[cell], x, y);
          for (unsigned int v = 0; v < n_vertex; ++v)
            for (unsigned int a = 0; a < dim; ++a)
              out[base[v] + a] += y[a * n_vertex + v];
        }
      else if (matrix_of_cell[cell] != CellMatrices::none)
        {
          gather(cell, x);
          cell_matrices.apply(matrix_of_cell[cell], x, y);
          scatter(cell, y);
        }

    for (unsigned int line = 0; line < n_lines; ++line)
      if (line_forces[line] != 0.)
        for (unsigned int e = line_offsets[line]; e < line_offsets[line + 1];
             ++e)
          out[line_entries[e].first] +=
            line_entries[e].second * line_forces[line];
  }

  template <int dim>
  template <bool as_given, typename CellNumber>
  void
  ElasticLevelOperator<dim>::cell_loop(VectorType       &dst,
                                       const VectorType &src) const
  {
    // As MatrixFree::cell_loop() does it, which an operator set up
    // by_vertices, without a MatrixFree, cannot call.
    const bool had_ghosts = src.has_ghost_elements();
    if (!had_ghosts)
      src.update_ghost_values();
    dst = 0.;
    with_degree([&](const auto degree) {
      apply_cells<decltype(degree)::value, as_given, CellNumber>(dst, src);
    });
    dst.compress(VectorOperation::add);
    if (!had_ghosts)
      src.zero_out_ghost_values();
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::vmult(VectorType &dst, const VectorType &src) const
  {
    apply<double, false>(dst, src);
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::vmult_newton(VectorType       &dst,
                                          const VectorType &src) const
  {
    apply<double, true>(dst, src);
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::vmult_single(VectorType       &dst,
                                          const VectorType &src) const
  {
    apply<float, false>(dst, src);
  }

  template <int dim>
  template <typename CellNumber, bool newton>
  void
  ElasticLevelOperator<dim>::apply(VectorType &dst, const VectorType &src) const
  {
    const VectorType *input = &src;
    if (!held.empty())
      {
        // P src: the held dofs from the dofs of their vertex.
        // (Not operator=, which is collective: processes without held
        // dofs do not come here.)
        projected.copy_locally_owned_data_from(src);
        for (const auto &[dof, entries] : held)
          {
            double value = 0.;
            for (const auto &[master, weight] : entries)
              value += weight * projected.local_element(master);
            projected.local_element(dof) = value;
          }
        input = &projected;
      }
    cell_loop<false, CellNumber>(dst, *input);
    // P^T (T^T): a held row's force goes to the dofs it is solved from,
    // with its test weights in the Newton system.
    for (std::size_t line = 0; line < held.size(); ++line)
      for (const auto &[master, weight] :
           newton ? held_test[line] : held[line].second)
        dst.local_element(master) +=
          weight * dst.local_element(held[line].first);
    for (const auto &[dofs, stiffness] : newton ? blocks : symmetric_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          if (stiffness[a][b] != 0.)
            dst.local_element(dofs[a]) +=
              stiffness[a][b] * src.local_element(dofs[b]);
    for (const unsigned int i : identity)
      dst.local_element(i) = src.local_element(i);
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::Tvmult(VectorType       &dst,
                                    const VectorType &src) const
  {
    vmult(dst, src);
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::internal_force(VectorType       &dst,
                                            const VectorType &u) const
  {
    cell_loop<true, double>(dst, u);
    for (const unsigned int i : constrained)
      dst.local_element(i) = 0.;
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::condense(VectorType &force) const
  {
    for (std::size_t line = 0; line < held.size(); ++line)
      for (const auto &[master, weight] : held_test[line])
        force.local_element(master) +=
          weight * force.local_element(held[line].first);
    for (const unsigned int i : identity)
      force.local_element(i) = 0.;
  }

  template <int dim>
  template <int degree>
  void
  ElasticLevelOperator<dim>::compute_diagonal(
    const std::vector<CellIterator> &cells)
  {
    using CellEvaluation = Evaluation<degree>;
    // The diagonal of C^T K C, C the constraints: a cell without
    // constrained dofs adds its matrix's diagonal; a cell with some adds
    // v^T K v for each dof g its dofs depend on, v_i the weight of g in
    // local dof i (1 for g itself, a hanging node's weight, 0 for a
    // Dirichlet dof).
    constexpr unsigned int n        = CellEvaluation::static_dofs_per_cell;
    const auto             position = evaluation_positions();
    initialize_dof_vector(diagonal_without_contact);
    cell_dofs.assign(cells.size() * n, 0);
    direct.assign(cells.size(), false);
    line_offsets.assign(1, 0);
    line_entries.clear();
    line_dof.clear();
    std::unordered_map<types::global_dof_index, unsigned int> line_of;
    std::vector<types::global_dof_index>                      indices(n);
    // A curved cell's diagonal, or where constraints couple its dofs its
    // whole matrix, computed for its batch (eight cells) at once.
    constexpr unsigned int lanes          = CurvedCells::lanes;
    unsigned int           diagonal_batch = CellMatrices::none,
                 matrix_batch             = CellMatrices::none;
    AlignedVector<double> batch_diagonal, batch_matrix;
    if (curved_cells.n_cells() > 0)
      {
        batch_diagonal.resize(n * lanes);
        batch_matrix.resize(n * n * lanes);
      }
    std::vector<double> cell_matrix;
    std::vector<std::pair<types::global_dof_index,
                          std::vector<std::pair<unsigned int, double>>>>
      depends;
    for (unsigned int cell = 0; cell < cells.size(); ++cell)
      {
        cells[cell]->get_dof_indices(indices);
        bool plain = true;
        for (unsigned int k = 0; k < n; ++k)
          {
            plain = plain && !constraints->is_constrained(indices[k]);
            cell_dofs[cell * n + position[k]] =
              partitioner->global_to_local(indices[k]);
          }
        // K by columns, a column's entries `stride` apart (the diagonal of
        // a plain curved cell: `curved_diagonal`, `lanes` apart).
        const double *K               = nullptr;
        const double *curved_diagonal = nullptr;
        unsigned int  stride          = n;
        if (matrix_of_cell[cell] != CellMatrices::none)
          {
            K      = cell_matrices.matrix(matrix_of_cell[cell]);
            stride = cell_matrices.column_stride();
          }
        else
          {
            // A curved cell (setup_cell_matrices() gave every cell without
            // a matrix to curved_cells).
            const unsigned int number = curved_of_cell[cell];
            const unsigned int batch = number / lanes, lane = number % lanes;
            if (plain)
              {
                if (batch != diagonal_batch)
                  {
                    diagonal_batch = batch;
                    curved_cells.diagonals(batch, batch_diagonal.data());
                  }
                curved_diagonal = &batch_diagonal[lane];
              }
            else
              {
                if (batch != matrix_batch)
                  {
                    matrix_batch = batch;
                    curved_cells.matrices(batch, batch_matrix.data());
                  }
                cell_matrix.resize(n * n);
                for (unsigned int e = 0; e < n * n; ++e)
                  cell_matrix[e] = batch_matrix[e * lanes + lane];
                K = cell_matrix.data();
              }
          }
        direct[cell] = plain && matrix_of_cell[cell] != CellMatrices::none;
        if (!plain)
          {
            // A constrained dof's entry names its line (stored once, in
            // local indices) instead of its own index.
            for (unsigned int k = 0; k < n; ++k)
              if (constraints->is_constrained(indices[k]))
                {
                  const auto [it, added] =
                    line_of.emplace(indices[k], line_offsets.size() - 1);
                  if (added)
                    {
                      line_dof.push_back(
                        partitioner->global_to_local(indices[k]));
                      if (const auto *entries =
                            constraints->get_constraint_entries(indices[k]))
                        for (const auto &[master, weight] : *entries)
                          line_entries.emplace_back(
                            partitioner->global_to_local(master), weight);
                      line_offsets.push_back(line_entries.size());
                    }
                  cell_dofs[cell * n + position[k]] =
                    constrained_flag | it->second;
                }
          }
        if (plain)
          {
            for (unsigned int k = 0; k < n; ++k)
              diagonal_without_contact(indices[k]) +=
                curved_diagonal ? curved_diagonal[position[k] * lanes] :
                                  K[position[k] * stride + position[k]];
            continue;
          }
        depends.clear();
        const auto add = [&](const types::global_dof_index g,
                             const unsigned int            local,
                             const double                  weight) {
          for (auto &[dof, weights] : depends)
            if (dof == g)
              {
                weights.emplace_back(local, weight);
                return;
              }
          depends.push_back({g, {{local, weight}}});
        };
        for (unsigned int k = 0; k < n; ++k)
          if (const auto *entries =
                constraints->get_constraint_entries(indices[k]))
            for (const auto &[master, weight] : *entries)
              add(master, position[k], weight);
          else if (!constraints->is_constrained(indices[k]))
            add(indices[k], position[k], 1.);
        for (const auto &[dof, weights] : depends)
          {
            double sum = 0.;
            for (const auto &[a, wa] : weights)
              for (const auto &[b, wb] : weights)
                sum += wa * wb * K[b * stride + a];
            diagonal_without_contact(dof) += sum;
          }
      }
    diagonal_without_contact.compress(VectorOperation::add);
    for (const unsigned int i : constrained)
      diagonal_without_contact.local_element(i) = 1.;
    compact_cell_dofs();
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::compact_cell_dofs()
  {
    const unsigned int n        = n_cell_dofs;
    const unsigned int n_vertex = n / dim;
    const unsigned int n_cells  = direct.size();
    // The resolved cells' n entries, in order, in resolved_dofs; their
    // first entry in cell_dofs says where.
    const auto resolved_cell = [&](const unsigned int cell) {
      return !direct[cell] && curved_of_cell[cell] == CellMatrices::none;
    };
    // The curved cells' entries by batch, then dof, then lane; a
    // constrained entry (and a lane without a cell) reads entry 0 and is
    // patched from `batch_patches`.
    constexpr unsigned int lanes = CurvedCells::lanes;
    const unsigned int n_batches = (curved_cells.n_cells() + lanes - 1) / lanes;
    batch_dofs.assign(std::size_t(n_batches) * n * lanes, 0);
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> patches(
      n_batches);
    std::vector<bool> filled(std::size_t(n_batches) * lanes, false);
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      if (curved_of_cell[cell] != CellMatrices::none)
        {
          const unsigned int number = curved_of_cell[cell];
          const unsigned int batch = number / lanes, lane = number % lanes;
          filled[number] = true;
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int entry    = cell_dofs[cell * n + i];
              const unsigned int position = i * lanes + lane;
              if (entry & constrained_flag)
                patches[batch].emplace_back(position,
                                            entry & ~constrained_flag);
              else
                batch_dofs[std::size_t(batch) * n * lanes + position] = entry;
            }
        }
    for (unsigned int number = 0; number < n_batches * lanes; ++number)
      if (!filled[number])
        for (unsigned int i = 0; i < n; ++i)
          patches[number / lanes].emplace_back(i * lanes + number % lanes,
                                               CellMatrices::none);
    batch_patch_offsets.assign(1, 0);
    batch_patches.clear();
    for (const auto &list : patches)
      {
        batch_patches.insert(batch_patches.end(), list.begin(), list.end());
        batch_patch_offsets.push_back(batch_patches.size());
      }
    resolved_dofs.clear();
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      if (resolved_cell(cell))
        resolved_dofs.insert(resolved_dofs.end(),
                             cell_dofs.begin() + cell * n,
                             cell_dofs.begin() + (cell + 1) * n);
    // In place: entry cell * n_vertex is written after cell * n was read.
    unsigned int resolved = 0;
    for (unsigned int cell = 0; cell < n_cells; ++cell)
      if (direct[cell])
        for (unsigned int v = 0; v < n_vertex; ++v)
          {
            const unsigned int first = cell_dofs[cell * n + v];
            for (unsigned int a = 1; a < dim; ++a)
              AssertThrow(cell_dofs[cell * n + a * n_vertex + v] == first + a,
                          ExcMessage("a vertex's dofs are not consecutive"));
            cell_dofs[cell * n_vertex + v] = first;
          }
      else if (resolved_cell(cell))
        cell_dofs[cell * n_vertex] = resolved++;
    cell_dofs.resize(n_cells * n_vertex);
    cell_dofs.shrink_to_fit();
    resolved_dofs.shrink_to_fit();
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::set_contact(std::vector<HeldLine>   held_lines,
                                         std::vector<NodalBlock> nodal_blocks)
  {
    held.clear();
    held_test.clear();
    const auto to_local = [this](const auto &global) {
      std::vector<std::pair<unsigned int, double>> entries;
      for (const auto &[master, weight] : global)
        entries.emplace_back(partitioner->global_to_local(master), weight);
      return entries;
    };
    for (const auto &line : held_lines)
      {
        held.emplace_back(partitioner->global_to_local(line.dof),
                          to_local(line.entries));
        held_test.push_back(line.petrov_galerkin ? to_local(line.test_entries) :
                                                   held.back().second);
      }
    identity = constrained;
    for (const auto &line : held)
      identity.push_back(line.first);
    std::sort(identity.begin(), identity.end());

    blocks.clear();
    symmetric_blocks.clear();
    for (const auto &block : nodal_blocks)
      {
        std::array<unsigned int, dim> local;
        std::array<bool, dim>         acting;
        for (unsigned int a = 0; a < dim; ++a)
          {
            local[a] = partitioner->global_to_local(block.dofs[a]);
            acting[a] =
              !std::binary_search(identity.begin(), identity.end(), local[a]);
          }
        auto stiffness = block.stiffness;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            if (!acting[a] || !acting[b])
              stiffness[a][b] = 0.;
        blocks.emplace_back(local, stiffness);
        auto symmetric = stiffness;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            symmetric[a][b] = 0.5 * (stiffness[a][b] + stiffness[b][a]);
        symmetric_blocks.emplace_back(local, symmetric);
      }

    // The diagonal of P^T A P + blocks, without the cross terms of the held
    // lines: a smoother's, not an exact one.
    inverse = diagonal_without_contact;
    for (const auto &[dof, entries] : held)
      for (const auto &[master, weight] : entries)
        inverse.local_element(master) +=
          weight * weight * diagonal_without_contact.local_element(dof);
    for (const auto &[dofs, stiffness] : symmetric_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        inverse.local_element(dofs[a]) += stiffness[a][a];
    for (const unsigned int i : identity)
      inverse.local_element(i) = 1.;
    for (unsigned int i = 0; i < inverse.locally_owned_size(); ++i)
      inverse.local_element(i) = 1. / inverse.local_element(i);
  }

  template <int dim>
  const typename ElasticLevelOperator<dim>::VectorType &
  ElasticLevelOperator<dim>::inverse_diagonal() const
  {
    return inverse;
  }

  template <int dim>
  const typename ElasticLevelOperator<dim>::VectorType &
  ElasticLevelOperator<dim>::diagonal() const
  {
    return diagonal_without_contact;
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::assemble_matrix(
    TrilinosWrappers::SparseMatrix        &matrix,
    const AffineConstraints<double> *const with_contact) const
  {
    const AffineConstraints<double> &lines =
      with_contact ? *with_contact : *constraints;
    const auto    &dofs = *dof_handler;
    const MPI_Comm comm = dofs.get_communicator();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    TrilinosWrappers::SparsityPattern sparsity(dofs.locally_owned_dofs(),
                                               dofs.locally_owned_dofs(),
                                               relevant,
                                               comm);
    DoFTools::make_sparsity_pattern(
      dofs, sparsity, lines, false, Utilities::MPI::this_mpi_process(comm));
    sparsity.compress();
    matrix.reinit(sparsity);
    if (by_vertices)
      {
        // The cells' matrices, in the mesh's order as matrix_of_cell.
        const unsigned int                   n        = n_cell_dofs;
        const auto                           position = evaluation_positions();
        FullMatrix<double>                   cell_matrix(n, n);
        std::vector<types::global_dof_index> indices(n);
        unsigned int                         c = 0;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const double *K = cell_matrices.matrix(matrix_of_cell[c++]);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) =
                    K[position[j] * cell_matrices.column_stride() +
                      position[i]];
              cell->get_dof_indices(indices);
              lines.distribute_local_to_global(cell_matrix, indices, matrix);
            }
      }
    else
      with_degree([&](const auto degree) {
        constexpr int p = decltype(degree)::value;
        MatrixFreeTools::compute_matrix(
          matrix_free,
          lines,
          matrix,
          &ElasticLevelOperator::template apply_cell<p>,
          this);
      });
    // The contact of a coarse level: nodal blocks, no held lines.
    for (const auto &[dofs_of, stiffness] : symmetric_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          if (stiffness[a][b] != 0.)
            matrix.add(partitioner->local_to_global(dofs_of[a]),
                       partitioner->local_to_global(dofs_of[b]),
                       stiffness[a][b]);
    matrix.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ElasticLevelOperator<dim>::initialize_dof_vector(VectorType &vector) const
  {
    vector.reinit(partitioner);
  }

  template <int dim>
  double
  ElasticLevelOperator<dim>::el(const types::global_dof_index i,
                                const types::global_dof_index j) const
  {
    AssertThrow(i == j, ExcNotImplemented());
    return 1. / inverse(i);
  }

  template <int dim>
  types::global_dof_index
  ElasticLevelOperator<dim>::m() const
  {
    return dof_handler->n_dofs();
  }

  template <int dim>
  const std::vector<unsigned int> &
  ElasticLevelOperator<dim>::identity_rows() const
  {
    return identity;
  }

  template <int dim>
  const DoFHandler<dim> &
  ElasticLevelOperator<dim>::get_dof_handler() const
  {
    return *dof_handler;
  }

  template class ElasticLevelOperator<2>;
  template class ElasticLevelOperator<3>;
} // namespace signorini
