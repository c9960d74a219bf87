#ifndef signorini_contact_contact_linearisation_h
#define signorini_contact_contact_linearisation_h

#include <deal.II/lac/affine_constraints.h>

#include <signorini/contact/contact_surface.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * What a contact strategy adds to the elastic operator K u = f for one
   * Newton step: the door between the contact strategies and the elastic
   * operators.
   *
   * - Held nodes sit on the obstacle: n.u = -gap, one constraint per node
   *   (exact contact: the active set); the held nodes of a corner (a vertex
   *   held by several obstacles) together, on as many of the vertex's free
   *   components.
   * - Springs push a node along its normal n with the force
   *   (-stiffness n.u - rest_force + extra_force) n [N]: a penalty of
   *   stiffness m / epsilon with rest_force = m gap / epsilon, and around
   *   it the augmented Lagrangian multiplier's force m lambda as
   *   extra_force. The operator adds stiffness n n^T to the matrix, and the
   *   forces to the right-hand side.
   */
  template <int dim>
  struct ContactLinearisation
  {
    struct Spring
    {
      const ContactNode<dim> *node;
      /** [N/mm] */
      double stiffness;
      /** [N] */
      double rest_force;
      /** A force that does not change the matrix [N]. */
      double extra_force = 0.;
    };

    /** Held nodes: every active node a process knows. */
    std::vector<const ContactNode<dim> *> held;
    /** Springs: on the locally owned nodes. */
    std::vector<Spring> springs;
    /** Whether the strategy uses springs, and extra forces, on any process
     * (the same on every process). */
    bool penalised    = false;
    bool extra_forces = false;

    /** What the matrix depends on (held nodes, spring stiffnesses): equal
     * keys, equal matrices, so that a matrix and its factorisation or AMG
     * are kept. */
    std::pair<std::pair<unsigned int, std::size_t>, double> key;
    /** Whether a change of key with the same second entry changes only the
     * rows and columns of a few nodes (an AMG may be kept). */
    bool local_changes = false;

    /** Adds the held nodes' constraints n.u = -gap to @p constraints:
     * each solved for the node's scalar dof; at a corner with several held
     * nodes, solved together for the free components that make the system
     * best conditioned. */
    void
    add_held_constraints(dealii::AffineConstraints<double> &constraints) const;
  };
} // namespace signorini

#endif
