#ifndef signorini_postprocessors_h
#define signorini_postprocessors_h

#include <deal.II/numerics/data_postprocessor.h>

#include <signorini/material.h>
#include <signorini/obstacle.h>

#include <string>
#include <vector>

namespace signorini
{
  /** Stress fields from the displacement: `von_mises` and the components
   * `stress_xx`, `stress_yy`, `stress_zz`, `stress_xy`[, `stress_xz`,
   * `stress_yz`] [MPa]. In 2D, stress_zz is the out-of-plane stress (zero in
   * plane stress). */
  template <int dim>
  class StressPostprocessor : public dealii::DataPostprocessor<dim>
  {
  public:
    explicit StressPostprocessor(const Material &material);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    dealii::UpdateFlags
    get_needed_update_flags() const override;

  private:
    const Material &material;
  };

  /** `gap` [mm]: the vertical distance of the deformed point above the
   * obstacle, y + u_y - psi(x) (z + u_z - psi(x, y) in 3D); negative inside
   * it. */
  template <int dim>
  class GapPostprocessor : public dealii::DataPostprocessorScalar<dim>
  {
  public:
    explicit GapPostprocessor(const Obstacle<dim> &obstacle);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

  private:
    const Obstacle<dim> &obstacle;
  };

  /** A scalar named @p name: the vertical component of a nodal vector that
   * holds a contact quantity (pressure, active-set indicator) in the vertical
   * displacement slots. */
  template <int dim>
  class VerticalComponent : public dealii::DataPostprocessorScalar<dim>
  {
  public:
    explicit VerticalComponent(const std::string &name);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;
  };
} // namespace signorini

#endif
