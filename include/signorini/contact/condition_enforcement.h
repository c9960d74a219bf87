#ifndef signorini_contact_condition_enforcement_h
#define signorini_contact_condition_enforcement_h

#include <signorini/contact/contact_law.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/elasticity/system_additions.h>

#include <vector>

namespace signorini
{
  /**
   * The two ways a formulation enforces the law's kinematic conditions
   * (NodeCondition) of the nodes in contact, as SystemAdditions.
   */
  namespace condition_enforcement
  {
    /**
     * Exactly: each condition d.u = value a constraint line, solved for its
     * component; the conditions of a corner (a vertex held by several
     * obstacles), or the several conditions of one node, together, on as
     * many of the vertex's free components as make the system best
     * conditioned. For every node a process knows; with constraint springs
     * (d d^T, scaled by the diagonal at the node's scalar dof) on the owned
     * nodes, for the multigrid's coarser levels. A node's force equations
     * (NodeEquation, with @p tractions: each node's of its last state
     * update) replace the force balance along its free components that no
     * line solves for: its lines get test weights of their own and the
     * equations' values are forces there (the system is then not
     * symmetric).
     */
    template <int dim>
    void
    add_constraints(const ContactSurface<dim>            &surface,
                    const ContactLaw<dim>                &law,
                    const std::vector<NodeTraction<dim>> &tractions,
                    SystemAdditions<dim>                 &additions);

    /**
     * By springs: each condition d.u = value of an owned node a spring of
     * stiffness m / @p epsilon [N/mm] pulling towards it, the block
     * (m / epsilon) d d^T with the right-hand side (m / epsilon) value d;
     * with the force m lambda_i d of the node's first condition where
     * @p multipliers (indexed like the nodes, [MPa]) is not empty, and
     * m (lambda_t . d) d of its other (tangential) conditions where
     * @p tangential_multipliers is. A node's force equations (a slipping
     * node's) bind its tangential force to its normal spring's force:
     * another spring, not symmetric.
     */
    template <int dim>
    void
    add_springs(
      const ContactSurface<dim>                 &surface,
      const ContactLaw<dim>                     &law,
      const std::vector<NodeTraction<dim>>      &tractions,
      const double                               epsilon,
      const std::vector<double>                 &multipliers,
      const std::vector<dealii::Tensor<1, dim>> &tangential_multipliers,
      SystemAdditions<dim>                      &additions);
  } // namespace condition_enforcement
} // namespace signorini

#endif
