#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <signorini/discretisation/axisymmetry.h>
#include <signorini/elasticity/cell_stiffness.h>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Shapes stored at most, and how many look-ups must have found a
     * repetition for the cache to go on storing. */
    constexpr unsigned int max_shapes = 4096;

    /** The strain (r, z, theta) of shape function @p i of an axisymmetric
     * model at quadrature point @p q. */
    template <int dim>
    SymmetricTensor<2, 3>
    revolved_shape_strain(const FEValues<dim> &fe_values,
                          const unsigned int   i,
                          const unsigned int   q)
    {
      const FEValuesExtractors::Vector displacement(0);
      const bool                       radial =
        fe_values.get_fe().system_to_component_index(i).first == 0;
      return axisymmetry::revolved_strain<dim>(
        fe_values[displacement].symmetric_gradient(i, q),
        radial ?
          fe_values.shape_value(i, q) / fe_values.quadrature_point(q)[0] :
          0.);
    }

    /** The matrix of an axisymmetric model's cell, the integral over the
     * revolved cell; with @p mean_dilatation, 2 mu eps : eps pointwise and
     * lambda D_i D_j / V, D_i the integral of the trace of the revolved
     * strain of phi_i (hoop strain included) and V the revolved volume. */
    template <int dim>
    void
    compute_revolved(const Material      &material,
                     const bool           mean_dilatation,
                     const FEValues<dim> &fe_values,
                     FullMatrix<double>  &cell_matrix)
    {
      const unsigned int n = fe_values.get_fe().n_dofs_per_cell();
      std::vector<SymmetricTensor<2, 3>> strain(n), stress(n);
      Vector<double>                     divergence(mean_dilatation ? n : 0);
      double                             volume = 0.;
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW = fe_values.JxW(q) *
                             axisymmetry::weight(fe_values.quadrature_point(q));
          for (unsigned int i = 0; i < n; ++i)
            {
              strain[i] = revolved_shape_strain(fe_values, i, q);
              if (mean_dilatation)
                {
                  stress[i] = 2. * material.mu() * JxW * strain[i];
                  divergence(i) += trace(strain[i]) * JxW;
                }
              else
                stress[i] = material.template stress<3>(strain[i]) * JxW;
            }
          volume += JxW;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j <= i; ++j)
              cell_matrix(i, j) += strain[i] * stress[j];
        }
      if (mean_dilatation)
        {
          const double factor = material.template lambda<3>() / volume;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j <= i; ++j)
              cell_matrix(i, j) += factor * divergence(i) * divergence(j);
        }
    }

    /** cell_internal_force() of an axisymmetric model's cell, with or
     * without @p mean_dilatation; returns the strain energy. */
    template <int dim, typename VectorType>
    double
    revolved_internal_force(const Material      &material,
                            const bool           mean_dilatation,
                            const FEValues<dim> &fe_values,
                            const VectorType    &u,
                            Vector<double>      &internal)
    {
      const FEValuesExtractors::Vector     displacement(0);
      const unsigned int                   n_q = fe_values.n_quadrature_points;
      std::vector<SymmetricTensor<2, dim>> in_plane(n_q);
      std::vector<Tensor<1, dim>>          values(n_q);
      fe_values[displacement].get_function_symmetric_gradients(u, in_plane);
      fe_values[displacement].get_function_values(u, values);
      const double   mu = material.mu(), lambda = material.template lambda<3>();
      Vector<double> divergence(internal.size());
      double         volume = 0., dilatation = 0., strain_energy = 0.;
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const Point<dim> &x   = fe_values.quadrature_point(q);
          const double      JxW = fe_values.JxW(q) * axisymmetry::weight(x);
          const auto        strain =
            axisymmetry::revolved_strain<dim>(in_plane[q], values[q][0] / x[0]);
          if (!mean_dilatation)
            {
              const auto stress = material.template stress<3>(strain);
              strain_energy += 0.5 * (strain * stress) * JxW;
              for (unsigned int i = 0; i < internal.size(); ++i)
                internal(i) +=
                  revolved_shape_strain(fe_values, i, q) * stress * JxW;
              continue;
            }
          volume += JxW;
          dilatation += trace(strain) * JxW;
          strain_energy += mu * (strain * strain) * JxW;
          for (unsigned int i = 0; i < internal.size(); ++i)
            {
              const auto strain_i = revolved_shape_strain(fe_values, i, q);
              internal(i) += 2. * mu * (strain_i * strain) * JxW;
              divergence(i) += trace(strain_i) * JxW;
            }
        }
      if (!mean_dilatation)
        return strain_energy;
      for (unsigned int i = 0; i < internal.size(); ++i)
        internal(i) += lambda * divergence(i) * dilatation / volume;
      return strain_energy + 0.5 * lambda * dilatation * dilatation / volume;
    }
  } // namespace

  UpdateFlags
  elastic_update_flags(const Material &material)
  {
    return update_gradients | update_JxW_values |
           (material.axisymmetric() ? update_values | update_quadrature_points :
                                      update_default);
  }

  template <int dim>
  CellStiffness<dim>::CellStiffness(const Material   &material,
                                    const CurvedCell &curved)
    : material(material)
    , curved(curved)
    , scales_linearly(dim == 3 || material.axisymmetric())
  {
  }

  template <int dim>
  void
  CellStiffness<dim>::clear()
  {
    cache.clear();
    seen.clear();
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
    if (material.axisymmetric())
      compute_revolved(material, mean_dilatation, fe_values, cell_matrix);
    else
      {
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
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(j, i) = cell_matrix(i, j);
  }

  template <int dim>
  typename CellStiffness<dim>::Shape
  CellStiffness<dim>::shape_of(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    double                                               &scale) const
  {
    const Point<dim> origin = cell->vertex(0);
    scale                   = cell->vertex(1).distance(origin);
    Shape shape;
    shape.fill(0.);
    for (unsigned int v = 1; v < cell->n_vertices(); ++v)
      for (unsigned int d = 0; d < dim; ++d)
        shape[(v - 1) * dim + d] = (cell->vertex(v)[d] - origin[d]) / scale;
    if (material.axisymmetric())
      shape.back() = origin[0] / scale;
    return shape;
  }

  template <int dim>
  const FullMatrix<double> *
  CellStiffness<dim>::cached(
    const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    if (curved && curved(cell))
      return nullptr;
    double     scale;
    const auto found = cache.find(shape_of(cell, scale));
    if (found == cache.end())
      return nullptr;
    if (!scales_linearly)
      return &found->second;
    scaled = found->second;
    scaled *= scale;
    return &scaled;
  }

  template <int dim>
  const FullMatrix<double> *
  CellStiffness<dim>::shared(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &fe_values,
    double                                               &factor)
  {
    return find_or_store(cell, fe_values, factor, false);
  }

  template <int dim>
  const FullMatrix<double> *
  CellStiffness<dim>::find_or_store(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &fe_values,
    double                                               &factor,
    const bool                                            at_first_sight)
  {
    if (curved && curved(cell))
      return nullptr;
    double      scale;
    const Shape shape = shape_of(cell, scale);
    factor            = scales_linearly ? scale : 1.;

    // Keep storing while the cache is small or repetitions are common.
    ++lookups;
    auto found = cache.find(shape);
    if (found != cache.end())
      return &found->second;
    if (cache.size() >= max_shapes || cache.size() * 2 > lookups + 64)
      return nullptr;
    // For shared(), a shape is stored at its second sighting: a matrix of
    // a shape seen once costs its cell's evaluation n times over (a
    // distorted mesh's every cell: 1.2 s of the Q2 Hertz ball's statistics
    // at 265k dofs). matrix() needs the matrix anyway.
    if (seen.insert(shape).second && !at_first_sight)
      return nullptr;
    // Stored for the unit scale: K(s x) = s^(dim-2) K(x) (s K(x) in an
    // axisymmetric model).
    fe_values.reinit(cell);
    found = cache.emplace(shape, FullMatrix<double>()).first;
    compute(fe_values, found->second);
    if (scales_linearly)
      found->second *= 1. / scale;
    return &found->second;
  }

  template <int dim>
  const FullMatrix<double> &
  CellStiffness<dim>::matrix(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &fe_values)
  {
    double factor;
    if (const auto *unit = find_or_store(cell, fe_values, factor, true))
      {
        if (!scales_linearly)
          return *unit;
        scaled = *unit;
        scaled *= factor;
        return scaled;
      }
    fe_values.reinit(cell);
    compute(fe_values, scaled);
    return scaled;
  }

  template <int dim, typename VectorType>
  double
  cell_internal_force(const Material      &material,
                      const FEValues<dim> &fe_values,
                      const VectorType    &u,
                      Vector<double>      &internal)
  {
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(fe_values.n_quadrature_points);
    fe_values[displacement].get_function_symmetric_gradients(u, strain);
    internal        = 0;
    const bool mean = material.template mean_dilatation<dim>(
      fe_values.get_fe().reference_cell().is_simplex());
    if (material.axisymmetric())
      return revolved_internal_force(material, mean, fe_values, u, internal);
    if (!mean)
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
  template double
  cell_internal_force(const Material &,
                      const FEValues<2> &,
                      const LinearAlgebra::distributed::Vector<double> &,
                      Vector<double> &);
  template double
  cell_internal_force(const Material &,
                      const FEValues<3> &,
                      const LinearAlgebra::distributed::Vector<double> &,
                      Vector<double> &);
} // namespace signorini
