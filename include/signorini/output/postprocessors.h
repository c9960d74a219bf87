#ifndef signorini_output_postprocessors_h
#define signorini_output_postprocessors_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <signorini/contact/obstacle.h>
#include <signorini/elasticity/material.h>

#include <string>
#include <vector>

namespace signorini
{
  /**
   * The scalar fields of a solution file that follow from the displacement at
   * a point: `von_mises` and the components `stress_xx`, `stress_yy`,
   * `stress_zz`, `stress_xy`[, `stress_xz`, `stress_yz`] [MPa], then `gap`
   * [mm], the gap of the deformed point along the obstacle's normal,
   * y + u_y - psi(x) (z + u_z - psi(x, y) in 3D), negative inside it. In 2D,
   * stress_zz is the out-of-plane stress (zero in plane stress). An
   * axisymmetric model names them by its axes, r = x and z = y:
   * `stress_rr`, `stress_zz` (axial), `stress_hoop` (sigma_theta_theta) and
   * `stress_rz`, and von Mises includes the hoop stress.
   *
   * One call evaluates all of them from the displacement and its gradient,
   * which the output computes once per point for every field. Cells with
   * mean dilatation (Material::mean_dilatation) pass the cell's mean
   * volumetric strain, which the stress takes instead of div u (in an
   * axisymmetric model the mean over the revolved cell of div u with the
   * hoop strain).
   */
  template <int dim>
  class DisplacementFields
  {
  public:
    /** The number of fields. */
    static constexpr unsigned int n_fields = (dim == 2 ? 5 : 7) + 1;

    /** @p axis_tolerance: points of an axisymmetric model closer to the
     * axis are on it [mm]. */
    DisplacementFields(const Material      &material,
                       const Obstacle<dim> &obstacle,
                       const double         axis_tolerance = 0.);

    /** The names of the fields, in the order evaluate() fills them. */
    std::vector<std::string>
    names() const;

    /** Fills @p fields (n_fields values) at the point @p point, where the
     * displacement is @p displacement with the gradient @p gradient (row i:
     * the gradient of u_i). */
    void
    evaluate(const dealii::Point<dim>     &point,
             const dealii::Tensor<1, dim> &displacement,
             const dealii::Tensor<2, dim> &gradient,
             double                       *fields,
             const double *cell_mean_dilatation = nullptr) const;

    /** The material, whose mean_dilatation() tells which cells pass their
     * mean volumetric strain to evaluate(). */
    const Material &
    material_law() const;

  private:
    const Material      &material;
    const Obstacle<dim> &obstacle;
    const double         axis_tolerance;
  };
} // namespace signorini

#endif
