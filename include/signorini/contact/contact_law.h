#ifndef signorini_contact_contact_law_h
#define signorini_contact_contact_law_h

#include <deal.II/base/tensor.h>

#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/contact/friction_parameters.h>
#include <signorini/contact/obstacle_parameters.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * A kinematic condition on one contact node: direction . u = value [mm]
   * at the node's dofs (the normal of a node on the obstacle: n.u = -gap;
   * a sticking node's tangent: t.u = t.u_reference).
   */
  template <int dim>
  struct NodeCondition
  {
    dealii::Tensor<1, dim> direction;
    double                 value;
    /** The free component to solve the condition for where the node has
     * no other condition (the node's scalar dof's). */
    unsigned int component;
  };

  /**
   * A force equation on one contact node: direction . f = value [N], f
   * the obstacle's nodal force on the node (a slipping node's tangential
   * force, bound to its normal force by Coulomb's law: (t - mu d n) . f =
   * 0). It replaces the force balance along the node's directions that no
   * condition holds.
   */
  template <int dim>
  struct NodeEquation
  {
    dealii::Tensor<1, dim> direction;
    double                 value;
    /** A term g . u on the node's displacement [N/mm] (the linearised
     * slip of a node whose slip direction turns): direction . f +
     * displacement . u = value. */
    dealii::Tensor<1, dim> displacement = {};
  };

  /**
   * What a node's law decides from: the formulation's augmented normal
   * pressure sigma [MPa] (its estimate of the contact pressure plus its
   * penalty of the penetration: the active set's p - c gap, a penalty's
   * -gap / epsilon, the augmented Lagrangian's lambda - gap / epsilon),
   * and, for a law with friction, the augmented tangential traction zeta
   * [MPa] in the node's tangent plane (the active set's q - c s: the
   * obstacle's tangential traction q on the body and the slip s of the
   * load step), with the contact pressure p, q, s and the formulation's
   * dzeta/ds = -c [MPa/mm] for a law that linearises zeta, and dzeta/dq
   * (1 for the active set; 0 for the penalty's zeta = -s / epsilon, a
   * regularised stick). The friction bound takes bound_sigma, the
   * augmented pressure without the round-off margin by which sigma
   * decides contact (a gap counts as negative only beyond it): the one the
   * residual takes, so that a node's state and its slip equation bound its
   * shear alike (with sigma's margin, a node at its bound stuck by the
   * residual and slipped by the state, and the iteration stalled).
   */
  template <int dim>
  struct NodeTraction
  {
    double                 sigma       = 0.;
    double                 bound_sigma = 0.;
    double                 pressure    = 0.;
    dealii::Tensor<1, dim> tangential;
    dealii::Tensor<1, dim> shear;
    dealii::Tensor<1, dim> slip;
    double                 stiffness    = 0.;
    double                 shear_weight = 1.;
  };

  /**
   * The law of a contact node, independent of how it is enforced (the
   * ContactFormulation): which state the node's tractions put it in, the
   * nodal forces complementarity asks of it, and the kinematic conditions
   * and force equations of its state.
   *
   * Implementations: FrictionlessLaw, FrictionLaw (Coulomb, Tresca). A new
   * law is a file beside them and a line in create_contact_law().
   */
  template <int dim>
  class ContactLaw
  {
  public:
    virtual ~ContactLaw() = default;

    /** The law's name in messages. */
    virtual std::string
    name() const = 0;

    /** Whether a node's law depends on its path (friction: the slip of a
     * load step is counted from the step's start), so that the Newton
     * iteration keeps each node's displacement at the start of a step and
     * its tangential traction. */
    virtual bool
    path_dependent() const
    {
      return false;
    }

    /** Whether @p node, in contact, resists tangential motion (friction):
     * it then holds the body along its tangents too. */
    virtual bool
    frictional(const ContactNode<dim> &node) const
    {
      (void)node;
      return false;
    }

    /** The state of a node that comes into contact before its forces are
     * known (it touches, or is where contact begins). */
    virtual NodeState
    contact_state() const
    {
      return NodeState::closed;
    }

    /** The state of @p node for the augmented tractions @p traction. */
    virtual NodeState
    state(const ContactNode<dim>  &node,
          const NodeTraction<dim> &traction) const = 0;

    /** The obstacle's normal force [N] that complementarity asks of the
     * owned @p node with the augmented tractions @p traction. */
    virtual double
    complementarity_force(const ContactNode<dim>  &node,
                          const NodeTraction<dim> &traction) const = 0;

    /** The obstacle's tangential force [N] that complementarity asks of
     * the owned @p node, or none where the law does not bind it (without
     * friction: it is then part of the force balance). */
    virtual std::optional<dealii::Tensor<1, dim>>
    tangential_force(const ContactNode<dim>  &node,
                     const NodeTraction<dim> &traction) const
    {
      (void)node;
      (void)traction;
      return std::nullopt;
    }

    /** Appends the kinematic conditions of @p node in its state (none for
     * an open node) to @p conditions and its force equations to
     * @p equations; @p traction: the node's tractions of its last state
     * update (a slip's direction). */
    virtual void
    conditions(const ContactNode<dim>          &node,
               const NodeTraction<dim>         &traction,
               std::vector<NodeCondition<dim>> &conditions,
               std::vector<NodeEquation<dim>>  &equations) const = 0;
  };

  /** The law of the obstacles' friction (frictionless where none has a
   * friction coefficient or a Tresca slip bound), for parameters that
   * FrictionParameters::check() accepted. */
  template <int dim>
  std::unique_ptr<ContactLaw<dim>>
  create_contact_law(const ContactParameters       &contact,
                     const FrictionParameters      &friction,
                     const ObstacleParameters<dim> &obstacles);
} // namespace signorini

#endif
