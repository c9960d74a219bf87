#ifndef signorini_elasticity_material_h
#define signorini_elasticity_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <string>

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

    /** How Q1 cells take the volumetric strain div u. */
    enum class VolumetricStrain
    {
      /** cell mean from nearly_incompressible on, where Q1 locks. */
      automatic,
      /** At every point: the standard displacement element. */
      pointwise,
      /** Replaced by its mean over the cell: mean dilatation (B-bar). */
      cell_mean
    };
    VolumetricStrain volumetric_strain = VolumetricStrain::automatic;

    /** The Poisson's ratio from which `automatic` takes the cell mean on
     * Q1, and P1 gets a warning: at nu = 0.4 Q1's locking begins to show
     * (lambda / mu = 4). */
    static constexpr double nearly_incompressible = 0.4;

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    double
    mu() const;

    /** Whether cells of the element of @p simplex kind (triangles and
     * tetrahedra: true) take the mean of the volumetric strain over the
     * cell: Q1 only, in plane strain, axisymmetric models and 3D. */
    template <int dim>
    bool
    mean_dilatation(const bool simplex) const;

    /** What the element of @p simplex kind makes of this material: throws
     * InputError if `cell mean` is asked of triangles or tetrahedra, and
     * returns a warning (else empty) if they lock. */
    std::string
    check_element(const bool simplex) const;

    /** The first Lamé constant, modified for plane stress in 2D (the 3D
     * one in plane strain and axisymmetric models). */
    template <int dim>
    double
    lambda() const;

    /** The stress for the strain @p strain. */
    template <int dim>
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const;

    /** The stress for the strain @p strain whose volumetric part is taken
     * as @p volumetric (the cell mean of the trace, with mean dilatation). */
    template <int dim>
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain,
           const double                           volumetric) const;

    /** The out-of-plane stress sigma_zz of a plane state (zero in plane
     * stress and in 3D, where it is part of the stress tensor; an
     * axisymmetric model's hoop stress needs the hoop strain: stress<3>() of
     * its revolved strain). */
    template <int dim>
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &strain) const;

    /** sigma_zz of a 2D state whose volumetric strain is @p volumetric. */
    template <int dim>
    double
    out_of_plane_stress(const double volumetric) const;
  };
} // namespace signorini

#endif
