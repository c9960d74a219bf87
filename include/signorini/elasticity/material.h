#ifndef signorini_elasticity_material_h
#define signorini_elasticity_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

namespace signorini
{
  /**
   * Isotropic linear elasticity: subsection `Material`. Lamé constants
   * mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)); in 2D plane
   * stress replaces lambda by 2 lambda mu / (lambda + 2 mu).
   */
  struct Material
  {
    /** E [MPa = N/mm^2]. */
    double young_modulus = 2.1e5;
    /** nu [-]. */
    double poisson_ratio = 0.3;
    /** 2D: plane stress (sigma_zz = 0) instead of plane strain. */
    bool plane_stress = false;

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    mu() const;

    /** The first Lamé constant, modified for plane stress in 2D. */
    template <int dim>
    double
    lambda() const;

    /** The stress for the strain @p strain. */
    template <int dim>
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const;

    /** The out-of-plane stress sigma_zz of a 2D state (zero in plane stress
     * and in 3D, where it is part of the stress tensor). */
    template <int dim>
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &strain) const;
  };
} // namespace signorini

#endif
