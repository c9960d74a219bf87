#ifndef signorini_contact_contact_law_h
#define signorini_contact_contact_law_h

#include <deal.II/base/tensor.h>

#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/contact_surface.h>

#include <memory>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * A kinematic condition on one contact node: direction . u = value [mm]
   * at the node's dofs (the normal of a node on the obstacle: n.u = -gap).
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
   * The law of a contact node, independent of how it is enforced (the
   * ContactFormulation): which state the node's forces put it in, the
   * nodal force complementarity asks of it, and the kinematic conditions of
   * its state. The formulation gives the law the node's augmented normal
   * pressure sigma [MPa]: its estimate of the contact pressure plus its
   * penalty of the penetration (the active set: p - c gap; a penalty:
   * -gap / epsilon; the augmented Lagrangian: lambda - gap / epsilon).
   *
   * Implementations: FrictionlessLaw. A new law is a file beside it and a
   * line in create_contact_law().
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
     * iteration keeps the displacement at the start of each load step. */
    virtual bool
    path_dependent() const
    {
      return false;
    }

    /** The state of @p node for the augmented normal pressure @p sigma
     * [MPa]. */
    virtual NodeState
    state(const ContactNode<dim> &node, const double sigma) const = 0;

    /** The nodal contact force [N] that complementarity asks of the owned
     * @p node with the augmented normal pressure @p sigma [MPa]. */
    virtual double
    complementarity_force(const ContactNode<dim> &node,
                          const double            sigma) const = 0;

    /** Appends the kinematic conditions of @p node in its state (none for
     * an open node) to @p conditions. */
    virtual void
    conditions(const ContactNode<dim>          &node,
               std::vector<NodeCondition<dim>> &conditions) const = 0;
  };

  /** The law the contact parameters name. */
  template <int dim>
  std::unique_ptr<ContactLaw<dim>>
  create_contact_law(const ContactParameters &parameters);
} // namespace signorini

#endif
