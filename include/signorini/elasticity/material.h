#ifndef signorini_elasticity_material_h
#define signorini_elasticity_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

namespace signorini
{
  /**
   * Isotropic linear elasticity: subsection `Material`. Lamé constants
   * mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)); in 2D plane
   * stress replaces lambda by 2 lambda mu / (lambda + 2 mu). The 2D model
   * (`Plane state`) says what the third direction does: nothing (plane
   * strain), carries no stress (plane stress), or is the hoop direction of
   * a body of revolution (axisymmetric: x = r, y = z, the 3D law with the
   * hoop strain u_r / r; see elasticity/axisymmetry.h).
   */
  struct Material
  {
    /** How a 2D model closes the third direction. */
    enum class PlaneState
    {
      /** eps_zz = 0. */
      plane_strain,
      /** sigma_zz = 0. */
      plane_stress,
      /** (x, y) = (r, z) of a body of revolution; eps_theta = u_r / r. */
      axisymmetric
    };

    /** E [MPa = N/mm^2]. */
    double young_modulus = 2.1e5;
    /** nu [-]. */
    double poisson_ratio = 0.3;
    /** The 2D model (ignored in 3D, where axisymmetric is refused). */
    PlaneState plane_state = PlaneState::plane_strain;

    /** Whether the model is axisymmetric. */
    bool
    axisymmetric() const
    {
      return plane_state == PlaneState::axisymmetric;
    }

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    mu() const;

    /** The first Lamé constant, modified for plane stress in 2D (the 3D
     * one in plane strain and axisymmetric models). */
    template <int dim>
    double
    lambda() const;

    /** The stress for the strain @p strain. */
    template <int dim>
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const;

    /** The out-of-plane stress sigma_zz of a plane state (zero in plane
     * stress and in 3D, where it is part of the stress tensor; an
     * axisymmetric model's hoop stress needs the hoop strain: stress<3>() of
     * its revolved strain). */
    template <int dim>
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &strain) const;
  };
} // namespace signorini

#endif
