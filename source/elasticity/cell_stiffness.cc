#include <deal.II/base/symmetric_tensor.h>

#include <signorini/elasticity/cell_stiffness.h>

#include <cmath>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Shapes stored at most, and how many look-ups must have found a
     * repetition for the cache to go on storing. */
    constexpr unsigned int max_shapes = 4096;
  } // namespace

  template <int dim>
  CellStiffness<dim>::CellStiffness(const Material &material)
    : material(material)
  {
  }

  template <int dim>
  void
  CellStiffness<dim>::clear()
  {
    cache.clear();
    lookups = 0;
  }

  template <int dim>
  void
  CellStiffness<dim>::compute(const FEValues<dim> &fe_values,
                              FullMatrix<double>  &cell_matrix) const
  {
    const unsigned int               n = fe_values.get_fe().n_dofs_per_cell();
    const FEValuesExtractors::Vector displacement(0);
    const bool mean_dilatation = material.template mean_dilatation<dim>(
      fe_values.get_fe().reference_cell().is_simplex());
    std::vector<SymmetricTensor<2, dim>> strain(n), stress(n);
    // With mean dilatation: the integrals of div phi_i and the cell's
    // volume; the volumetric part lambda (div u)(div v) of the stiffness is
    // then lambda D_i D_j / V, and the pointwise part 2 mu eps : eps.
    Vector<double> divergence(mean_dilatation ? n : 0);
    double         volume = 0.;
    cell_matrix.reinit(n, n);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            strain[i] = fe_values[displacement].symmetric_gradient(i, q);
            if (mean_dilatation)
              {
                stress[i] = 2. * material.mu() * JxW * strain[i];
                divergence(i) += trace(strain[i]) * JxW;
              }
            else
              stress[i] = material.template stress<dim>(strain[i]) * JxW;
          }
        volume += JxW;
        // The matrix is symmetric: the lower triangle, mirrored below.
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            cell_matrix(i, j) += strain[i] * stress[j];
      }
    if (mean_dilatation)
      {
        const double factor = material.template lambda<dim>() / volume;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            cell_matrix(i, j) += factor * divergence(i) * divergence(j);
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(j, i) = cell_matrix(i, j);
  }

  template <int dim>
  typename CellStiffness<dim>::Shape
  CellStiffness<dim>::shape_of(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    double                                               &scale)
  {
    const Point<dim> origin = cell->vertex(0);
    scale                   = cell->vertex(1).distance(origin);
    Shape shape;
    shape.fill(0.);
    for (unsigned int v = 1; v < cell->n_vertices(); ++v)
      for (unsigned int d = 0; d < dim; ++d)
        shape[(v - 1) * dim + d] = (cell->vertex(v)[d] - origin[d]) / scale;
    return shape;
  }

  template <int dim>
  const FullMatrix<double> *
  CellStiffness<dim>::cached(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    double     scale;
    const auto found = cache.find(shape_of(cell, scale));
    if (found == cache.end())
      return nullptr;
    if (dim == 2)
      return &found->second;
    scaled = found->second;
    scaled *= std::pow(scale, dim - 2.);
    return &scaled;
  }

  template <int dim>
  const FullMatrix<double> &
  CellStiffness<dim>::matrix(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &fe_values)
  {
    double      scale;
    const Shape shape = shape_of(cell, scale);

    // Keep storing while the cache is small or repetitions are common.
    ++lookups;
    const bool store =
      cache.size() < max_shapes && cache.size() * 2 <= lookups + 64;
    auto found = cache.find(shape);
    if (found == cache.end())
      {
        fe_values.reinit(cell);
        if (!store)
          {
            compute(fe_values, scaled);
            return scaled;
          }
        // Stored for the unit scale: K(s x) = s^(dim-2) K(x).
        found = cache.emplace(shape, FullMatrix<double>()).first;
        compute(fe_values, found->second);
        found->second *= std::pow(scale, 2. - dim);
      }
    if (dim == 2)
      return found->second;
    scaled = found->second;
    scaled *= std::pow(scale, dim - 2.);
    return scaled;
  }

  template <int dim>
  double
  cell_internal_force(const Material                      &material,
                      const FEValues<dim>                 &fe_values,
                      const TrilinosWrappers::MPI::Vector &u,
                      Vector<double>                      &internal)
  {
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(fe_values.n_quadrature_points);
    fe_values[displacement].get_function_symmetric_gradients(u, strain);
    internal = 0;
    if (!material.template mean_dilatation<dim>(
          fe_values.get_fe().reference_cell().is_simplex()))
      {
        double strain_energy = 0.;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const auto stress = material.template stress<dim>(strain[q]);
            strain_energy += 0.5 * (strain[q] * stress) * fe_values.JxW(q);
            for (unsigned int i = 0; i < internal.size(); ++i)
              internal(i) += fe_values[displacement].symmetric_gradient(i, q) *
                             stress * fe_values.JxW(q);
          }
        return strain_energy;
      }

    // Mean dilatation: 2 mu eps(phi_i) : eps(u) pointwise, and
    // lambda D_i Theta / V with D_i, Theta the integrals of div phi_i and
    // div u over the cell of volume V.
    const double   mu = material.mu(), lambda = material.template lambda<dim>();
    Vector<double> divergence(internal.size());
    double         volume = 0., dilatation = 0., strain_energy = 0.;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        volume += JxW;
        dilatation += trace(strain[q]) * JxW;
        strain_energy += mu * (strain[q] * strain[q]) * JxW;
        for (unsigned int i = 0; i < internal.size(); ++i)
          {
            const auto strain_i =
              fe_values[displacement].symmetric_gradient(i, q);
            internal(i) += 2. * mu * (strain_i * strain[q]) * JxW;
            divergence(i) += trace(strain_i) * JxW;
          }
      }
    for (unsigned int i = 0; i < internal.size(); ++i)
      internal(i) += lambda * divergence(i) * dilatation / volume;
    return strain_energy + 0.5 * lambda * dilatation * dilatation / volume;
  }

  template class CellStiffness<2>;
  template class CellStiffness<3>;
  template double
  cell_internal_force(const Material &,
                      const FEValues<2> &,
                      const TrilinosWrappers::MPI::Vector &,
                      Vector<double> &);
  template double
  cell_internal_force(const Material &,
                      const FEValues<3> &,
                      const TrilinosWrappers::MPI::Vector &,
                      Vector<double> &);
} // namespace signorini
