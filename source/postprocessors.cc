#include <signorini/postprocessors.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(const Material &material)
    : material(material)
  {
  }

  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    if (dim == 2)
      return {"von_mises", "stress_xx", "stress_yy", "stress_zz", "stress_xy"};
    return {"von_mises",
            "stress_xx",
            "stress_yy",
            "stress_zz",
            "stress_xy",
            "stress_xz",
            "stress_yz"};
  }

  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_gradients;
  }

  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    for (unsigned int q = 0; q < computed_quantities.size(); ++q)
      {
        SymmetricTensor<2, dim> strain;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            strain[i][j] = 0.5 * (inputs.solution_gradients[q][i][j] +
                                  inputs.solution_gradients[q][j][i]);
        const auto sigma = material.stress<dim>(strain);

        // The full 3x3 stress, with the out-of-plane entry of a 2D state.
        double s[3][3] = {};
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            s[i][j] = sigma[i][j];
        if (dim == 2)
          s[2][2] = material.out_of_plane_stress<dim>(strain);
        const double von_mises = std::sqrt(
          0.5 * ((s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) +
                 (s[1][1] - s[2][2]) * (s[1][1] - s[2][2]) +
                 (s[2][2] - s[0][0]) * (s[2][2] - s[0][0])) +
          3. * (s[0][1] * s[0][1] + s[0][2] * s[0][2] + s[1][2] * s[1][2]));

        auto &out = computed_quantities[q];
        out(0)    = von_mises;
        out(1)    = s[0][0];
        out(2)    = s[1][1];
        out(3)    = s[2][2];
        out(4)    = s[0][1];
        if (dim == 3)
          {
            out(5) = s[0][2];
            out(6) = s[1][2];
          }
      }
  }

  template <int dim>
  GapPostprocessor<dim>::GapPostprocessor(const Obstacle<dim> &obstacle)
    : DataPostprocessorScalar<dim>("gap",
                                   update_values | update_quadrature_points)
    , obstacle(obstacle)
  {
  }

  template <int dim>
  void
  GapPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    for (unsigned int q = 0; q < computed_quantities.size(); ++q)
      computed_quantities[q](0) = obstacle.gap(inputs.evaluation_points[q]) +
                                  inputs.solution_values[q](dim - 1);
  }

  template <int dim>
  VerticalComponent<dim>::VerticalComponent(const std::string &name)
    : DataPostprocessorScalar<dim>(name, update_values)
  {
  }

  template <int dim>
  void
  VerticalComponent<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    for (unsigned int q = 0; q < computed_quantities.size(); ++q)
      computed_quantities[q](0) = inputs.solution_values[q](dim - 1);
  }

  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
  template class GapPostprocessor<2>;
  template class GapPostprocessor<3>;
  template class VerticalComponent<2>;
  template class VerticalComponent<3>;
} // namespace signorini
