#include <deal.II/base/symmetric_tensor.h>

#include <signorini/discretisation/axisymmetry.h>
#include <signorini/output/postprocessors.h>

#include <cmath>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  DisplacementFields<dim>::DisplacementFields(const Material      &material,
                                              const Obstacle<dim> &obstacle,
                                              const double axis_tolerance)
    : material(material)
    , obstacle(obstacle)
    , axis_tolerance(axis_tolerance)
  {
  }

  template <int dim>
  std::vector<std::string>
  DisplacementFields<dim>::names() const
  {
    if (material.axisymmetric())
      return {"von_mises",
              "stress_rr",
              "stress_zz",
              "stress_hoop",
              "stress_rz",
              "gap"};
    if (dim == 2)
      return {
        "von_mises", "stress_xx", "stress_yy", "stress_zz", "stress_xy", "gap"};
    return {"von_mises",
            "stress_xx",
            "stress_yy",
            "stress_zz",
            "stress_xy",
            "stress_xz",
            "stress_yz",
            "gap"};
  }

  template <int dim>
  void
  DisplacementFields<dim>::evaluate(const Point<dim>     &point,
                                    const Tensor<1, dim> &displacement,
                                    const Tensor<2, dim> &gradient,
                                    double               *fields,
                                    const double *cell_mean_dilatation) const
  {
    SymmetricTensor<2, dim> strain;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        strain[i][j] = 0.5 * (gradient[i][j] + gradient[j][i]);
    // The full 3x3 stress, with the out-of-plane entry of a 2D state (the
    // hoop stress of an axisymmetric one).
    double s[3][3] = {};
    if (material.axisymmetric())
      {
        const double hoop     = axisymmetry::hoop_strain(displacement[0],
                                                     gradient[0][0],
                                                     point[0],
                                                     axis_tolerance);
        const auto   revolved = axisymmetry::revolved_strain<dim>(strain, hoop);
        const double volumetric =
          cell_mean_dilatation ? *cell_mean_dilatation : trace(revolved);
        const auto sigma = material.stress<3>(revolved, volumetric);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            s[i][j] = sigma[i][j];
      }
    else
      {
        const double volumetric =
          cell_mean_dilatation ? *cell_mean_dilatation : trace(strain);
        const auto sigma = material.stress<dim>(strain, volumetric);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            s[i][j] = sigma[i][j];
        if (dim == 2)
          s[2][2] = material.out_of_plane_stress<dim>(volumetric);
      }
    fields[0] = std::sqrt(
      0.5 * ((s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) +
             (s[1][1] - s[2][2]) * (s[1][1] - s[2][2]) +
             (s[2][2] - s[0][0]) * (s[2][2] - s[0][0])) +
      3. * (s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2]));
    fields[1] = s[0][0];
    fields[2] = s[1][1];
    fields[3] = s[2][2];
    fields[4] = s[0][1];
    if (dim == 3)
      {
        fields[5] = s[0][2];
        fields[6] = s[1][2];
      }
    // The deformed gap along the obstacle's normal.
    Tensor<1, dim> normal;
    const double   gap   = obstacle.gap(point, normal);
    fields[n_fields - 1] = gap + normal * displacement;
  }

  template <int dim>
  const Material &
  DisplacementFields<dim>::material_law() const
  {
    return material;
  }

  template class DisplacementFields<2>;
  template class DisplacementFields<3>;
} // namespace signorini
