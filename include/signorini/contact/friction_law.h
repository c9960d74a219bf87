#ifndef signorini_contact_friction_law_h
#define signorini_contact_friction_law_h

#include <signorini/contact/frictionless_law.h>

#include <vector>

namespace signorini
{
  /**
   * Contact with friction, per obstacle Coulomb's (the shear traction of a
   * node in contact bounded by mu times its pressure) or Tresca's (bounded
   * by a slip bound s), or none (frictionless). With the augmented normal
   * pressure sigma and tangential traction zeta (the obstacle's shear
   * traction q on the body less c times the node's slip of the load
   * step), a node is
   * - open where sigma <= 0 (no force),
   * - sticking where |zeta| < b, b = mu sigma or s: held on the obstacle
   *   and where it was at the start of the step (n.u = -gap, t.u =
   *   t.u_reference),
   * - slipping otherwise: held on the obstacle, its shear traction b along
   *   d = zeta / |zeta| (against its slip): the equations (t_i - mu d_i n)
   *   . f = 0 (Coulomb) or t_i . f = m s d_i (Tresca) for the obstacle's
   *   nodal force f, with d from the last state update.
   * The complementarity function of the tangential force is m b zeta /
   * max(b, |zeta|) (Alart-Curnier; Hueber, Stadler and Wohlmuth 2008). A
   * vertex at a corner of several obstacles is frictionless. The normal
   * part (complementarity, the condition n.u = -gap) is FrictionlessLaw's.
   */
  template <int dim>
  class FrictionLaw : public FrictionlessLaw<dim>
  {
  public:
    /** @p coefficient, @p slip_bound: mu and s [MPa] of each obstacle of
     * the ObstacleSet (0: none). */
    FrictionLaw(const std::vector<double> &coefficient,
                const std::vector<double> &slip_bound);

    std::string
    name() const override;

    bool
    path_dependent() const override;

    NodeState
    contact_state() const override;

    NodeState
    state(const ContactNode<dim>  &node,
          const NodeTraction<dim> &traction) const override;

    std::optional<dealii::Tensor<1, dim>>
    tangential_force(const ContactNode<dim>  &node,
                     const NodeTraction<dim> &traction) const override;

    void
    conditions(const ContactNode<dim>          &node,
               const NodeTraction<dim>         &traction,
               std::vector<NodeCondition<dim>> &conditions,
               std::vector<NodeEquation<dim>>  &equations) const override;

    /** Whether @p node has friction (its obstacle's, not at a corner, nor
     * where a support holds a tangent in part). */
    bool
    frictional(const ContactNode<dim> &node) const override;

  private:
    /** Appends the Newton equations of a slipping @p node whose augmented
     * tangential traction depends on its slip alone (a penalty's zeta =
     * -c s), its slip direction linearised in 3D, to @p equations. */
    void
    add_regularised_slip_equations(
      const ContactNode<dim>         &node,
      const NodeTraction<dim>        &traction,
      std::vector<NodeEquation<dim>> &equations) const;

    /** Appends the semismooth Newton equations of a slipping @p node in
     * 3D (its slip direction linearised) to @p equations. */
    void
    add_slip_equations(const ContactNode<dim>         &node,
                       const NodeTraction<dim>        &traction,
                       std::vector<NodeEquation<dim>> &equations) const;

    /** The bound b [MPa] of the shear traction of @p node at the
     * augmented pressure @p sigma. */
    double
    bound(const ContactNode<dim> &node, const double sigma) const;

    const std::vector<double> coefficient;
    const std::vector<double> slip_bound;
  };
} // namespace signorini

#endif
