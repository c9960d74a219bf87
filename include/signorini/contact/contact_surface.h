#ifndef signorini_contact_contact_surface_h
#define signorini_contact_contact_surface_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/obstacle.h>
#include <signorini/discretisation/discretisation.h>

#include <array>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * A vertex of the candidate contact boundary whose displacement along the
   * obstacle's normal is free (not fixed by a Dirichlet condition or a
   * hanging node).
   */
  template <int dim>
  struct ContactNode
  {
    /** Displacement dofs, one per component. */
    std::array<dealii::types::global_dof_index, dim> dofs;
    /** The dof that carries the node's scalars (contact pressure, active
     * flag) in vectors of the displacement's layout: the component along
     * which the normal is largest. */
    dealii::types::global_dof_index scalar_dof;
    /** Where the node is [mm]. */
    dealii::Point<dim> position;
    /** The obstacle's outward unit normal at the node. */
    dealii::Tensor<1, dim> normal;
    /** Initial gap to the obstacle along the normal [mm]. */
    double gap;
    /** Which obstacle the node faces. */
    unsigned int obstacle = 0;
    /** Lumped contact-boundary mass, integral of the shape function over
     * the contact boundary [mm^(dim-1); mm^2 over the revolution of an
     * axisymmetric model]; set on owned nodes only. */
    double mass = 0.;
    bool   owned;
    /** In the contact strategy's active set. */
    bool active = false;

    /** n.u at the node, for the displacement @p u [mm]. */
    double
    normal_displacement(const dealii::TrilinosWrappers::MPI::Vector &u) const
    {
      double value = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        value += normal[d] * u(dofs[d]);
      return value;
    }
  };

  /**
   * The candidate contact nodes of the current mesh: the vertices on the
   * contact boundary ids that face an obstacle, each with its normal, gap
   * and lumped mass, and the active set of the contact strategy.
   */
  template <int dim>
  class ContactSurface
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    ContactSurface(const std::set<dealii::types::boundary_id> &contact_ids,
                   const Obstacle<dim>                        &obstacle);

    /** Finds the nodes of @p discretisation's current mesh. Throws
     * InputError if a gap is not a finite number. */
    void
    setup(const Discretisation<dim> &discretisation);

    std::vector<ContactNode<dim>> &
    nodes();
    const std::vector<ContactNode<dim>> &
    nodes() const;

    /** The boundary ids that may touch an obstacle. */
    const std::set<dealii::types::boundary_id> &
    contact_ids() const;

    /** The gap of @p node after the displacement @p u [mm]. */
    double
    deformed_gap(const ContactNode<dim> &node, const VectorType &u) const;

    /** Gaps below this count as touching: round-off in the body's size
     * [mm]. */
    double
    touching_tolerance() const;

    /** The number of active nodes and a hash of which they are, the same on
     * every process. */
    std::pair<unsigned int, std::size_t>
    active_set_signature() const;

  private:
    const std::set<dealii::types::boundary_id> ids;
    const Obstacle<dim>                       &obstacle;
    MPI_Comm                                   mpi_communicator;
    double                                     tolerance = 0.;
    std::vector<ContactNode<dim>>              contact_nodes;
  };
} // namespace signorini

#endif
