#ifndef signorini_elasticity_rigid_motions_h
#define signorini_elasticity_rigid_motions_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <signorini/discretisation/discretisation.h>

#include <string>
#include <vector>

namespace signorini
{
  /**
   * A rigid motion of the body, u(x) = translation + rotation x (x - centre)
   * (in 2D the rotation is about z: only its third component counts).
   */
  template <int dim>
  struct RigidMode
  {
    dealii::Tensor<1, dim> translation;
    dealii::Tensor<1, 3>   rotation;
    dealii::Point<dim>     centre;

    /** u(@p x). */
    dealii::Tensor<1, dim>
    value(const dealii::Point<dim> &x) const;
  };

  /**
   * The rigid motions of the body's model, which its supports and contact
   * must hold: in plane 2D the translations along x and y and the rotation
   * about z, in 3D three translations and three rotations. Translations
   * come first (rigid_motions_held names a free motion by the last mode of
   * this list it needs). The rotations turn about the centre of the initial
   * mesh's bounding box at a rate of one over its half diagonal, so that
   * every mode moves the body by about one. An axisymmetric body moves
   * rigidly along its axis (y) only. Collective.
   */
  template <int dim>
  std::vector<RigidMode<dim>>
  rigid_body_modes(const Discretisation<dim> &discretisation);

  /** A direction along which something other than a support may hold the
   * body at a point (a candidate contact node along its normal). */
  template <int dim>
  struct HeldDirection
  {
    dealii::Point<dim>     position;
    dealii::Tensor<1, dim> direction;
  };

  /**
   * Checks, before cycle 0, that what can hold the body holds each of the
   * rigid @p modes: the Dirichlet data (every dof of a fixed component) and,
   * if @p contact_can_hold, the @p contact_directions (this process's
   * candidate contact nodes along their normals). The modes evaluated at these
   * constraints form a small matrix (its Gram matrix summed over the processes,
   * so every process decides alike); a combination of modes that it maps to
   * zero is free. Throws an InputError on the entry `Boundary
   * conditions/Dirichlet` naming each free motion, e.g. "nothing holds the body
   * against a translation along x". Returns whether the supports alone hold
   * every mode (then a singular Newton system is not contact's failure to
   * hold the body). Collective.
   */
  template <int dim>
  bool
  check_rigid_motions_held(
    const Discretisation<dim>             &discretisation,
    const std::vector<HeldDirection<dim>> &contact_directions,
    const std::vector<RigidMode<dim>>     &modes,
    const bool                             contact_can_hold);
} // namespace signorini

#endif
