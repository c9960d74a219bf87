#ifndef signorini_contact_contact_surface_h
#define signorini_contact_contact_surface_h

#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/obstacle_set.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/input/input_error.h>

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace signorini
{
  /** Where a contact node stands: off the obstacle, or on it: closed
   * (frictionless), sticking or slipping (friction). Written as 0, 1, 2, 3
   * in the output. */
  enum class NodeState : unsigned char
  {
    open,
    closed,
    stick,
    slip
  };

  /**
   * A vertex of the candidate contact boundary facing one obstacle, along
   * whose normal it may move (its displacement along the normal is not all
   * fixed by Dirichlet conditions or hanging nodes). A vertex that may
   * touch several obstacles at once (the bottom of a groove) is several
   * contact nodes with the same dofs, one per obstacle: a corner.
   */
  template <int dim>
  struct ContactNode
  {
    /** Displacement dofs, one per component. */
    std::array<dealii::types::global_dof_index, dim> dofs;
    /** Which of them are free (not fixed by a Dirichlet condition). */
    std::array<bool, dim> free;
    /** The dof that carries the node's scalars (contact pressure, active
     * flag) in vectors of the displacement's layout: a free component,
     * the one along which the normal is largest; at a corner each node has
     * its own. */
    dealii::types::global_dof_index scalar_dof;
    /** Where the node is [mm]. */
    dealii::Point<dim> position;
    /** The node's frame: the obstacle's outward unit normal at the node,
     * and unit tangents that make it a right-handed orthonormal frame (in
     * 2D t = (-n_y, n_x); in 3D the first tangent lies in the plane of n
     * and the axis along which n is smallest). */
    dealii::Tensor<1, dim>                      normal;
    std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
    /** Initial gap to the obstacle along the normal [mm]. */
    double gap;
    /** The node's displacement at the start of the load step [mm], from
     * which its slip is counted (a path-dependent law's; zero before the
     * first step). */
    dealii::Tensor<1, dim> reference;
    /** Which obstacle the node faces (its index in the ObstacleSet). */
    unsigned int obstacle = 0;
    /** Lumped contact-boundary mass, integral of the shape function over
     * the contact boundary [mm^(dim-1); mm^2 over the revolution of an
     * axisymmetric model]; set on owned nodes only. */
    double mass = 0.;
    bool   owned;
    /** Open, or in contact in the way the contact law says (written as 0,
     * 1, ... in the output: the field active_set, the contact pressure
     * table). */
    NodeState state = NodeState::open;
    /** Whether this is the vertex's first node (its nearest obstacle):
     * quantities of the vertex (its nodal force) count there once. */
    bool primary = true;
    /** The corner the node belongs to (an index into
     * ContactSurface::corners()), or invalid_unsigned_int. */
    unsigned int corner = dealii::numbers::invalid_unsigned_int;

    /** Whether the node is on the obstacle (in the active set). */
    bool
    in_contact() const
    {
      return state != NodeState::open;
    }

    /** The node's displacement in @p u [mm]. */
    dealii::Tensor<1, dim>
    displacement(const dealii::TrilinosWrappers::MPI::Vector &u) const
    {
      dealii::Tensor<1, dim> value;
      for (unsigned int d = 0; d < dim; ++d)
        value[d] = u(dofs[d]);
      return value;
    }

    /** The tangential part of @p v: v - (v.n) n. */
    dealii::Tensor<1, dim>
    tangential(const dealii::Tensor<1, dim> &v) const
    {
      return v - (v * normal) * normal;
    }

    /** The slip of the load step [mm]: the tangential part of the
     * displacement @p u since the reference. */
    dealii::Tensor<1, dim>
    slip(const dealii::TrilinosWrappers::MPI::Vector &u) const
    {
      return tangential(displacement(u) - reference);
    }

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

  /** Unit tangents completing the unit normal @p n to an orthonormal frame
   * (see ContactNode::tangents); t_1 x t_2 = n in 3D. */
  template <int dim>
  std::array<dealii::Tensor<1, dim>, dim - 1>
  tangent_frame(const dealii::Tensor<1, dim> &n);

  /**
   * The candidate contact nodes of the current mesh: the vertices on the
   * contact boundary ids, each facing the obstacle nearest to it (smallest
   * gap) and, as a corner, up to dim obstacles whose normals are
   * independent on its free components; each node with its frame, gap and
   * lumped mass, and its state (the active set of the contact
   * formulation).
   */
  template <int dim>
  class ContactSurface
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /** @p check_input: setup() refuses a body that starts inside an
     * obstacle, a support that holds a node inside one, and contact
     * boundary ids where no node can act (off for Contact/Method = none). */
    ContactSurface(const std::set<dealii::types::boundary_id> &contact_ids,
                   const ObstacleSet<dim>                     &obstacles,
                   const bool check_input = true);

    /** Finds the nodes of @p discretisation's current mesh. Throws
     * InputError if a gap is not a finite number, and for the input that
     * the constructor's @p check_input names. */
    void
    setup(const Discretisation<dim> &discretisation);

    std::vector<ContactNode<dim>> &
    nodes();
    const std::vector<ContactNode<dim>> &
    nodes() const;

    /** The nodes of each vertex that faces more than one obstacle, the
     * primary one first. */
    const std::vector<std::vector<unsigned int>> &
    corners() const;

    /** The obstacles. */
    const ObstacleSet<dim> &
    obstacles() const;

    /** The communicator of the mesh the nodes are on. */
    MPI_Comm
    communicator() const
    {
      return mpi_communicator;
    }

    /** The boundary ids that may touch an obstacle. */
    const std::set<dealii::types::boundary_id> &
    contact_ids() const;

    /** Calls @p action(cell, f) for each face f of a locally owned cell of
     * @p discretisation that lies on the contact boundary. */
    template <typename Action>
    void
    for_each_owned_face(const Discretisation<dim> &discretisation,
                        const Action              &action) const
    {
      for (const auto &cell :
           discretisation.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                ids.count(cell->face(f)->boundary_id()))
              action(cell, f);
    }

    /** The gap of @p node after the displacement @p u [mm]. */
    double
    deformed_gap(const ContactNode<dim> &node, const VectorType &u) const;

    /** The obstacles' normal forces lambda_i [N] at the owned nodes (0
     * elsewhere) from the nodal forces @p residual = K u - f: on the free
     * components of each vertex, residual = sum of lambda_i n_i over its
     * nodes (least squares at a corner). */
    std::vector<double>
    normal_forces(const VectorType &residual) const;

    /** Gaps below this count as touching: round-off in the body's size
     * [mm]. */
    double
    touching_tolerance() const;

    /** The number of nodes in contact and a hash of which they are (and of
     * their states), the same on every process. */
    std::pair<unsigned int, std::size_t>
    active_set_signature() const;

    /** Below this, the free part of a unit direction is none: the node
     * cannot move along it. */
    static constexpr double fixed_along_normal = 1e-8;

    /** The length of @p normal's part along the @p free components. */
    static double
    free_part(const dealii::Tensor<1, dim> &normal,
              const std::array<bool, dim>  &free);

  private:
    /** A vertex of the contact boundary with its gap and normal to every
     * obstacle. */
    struct Vertex
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      std::array<bool, dim>                            free;
      dealii::Point<dim>                               position;
      std::vector<double>                              gaps;
      std::vector<dealii::Tensor<1, dim>>              normals;
      std::set<dealii::types::boundary_id>             boundary_ids;
    };


    /** Throws @p error of the first process that has one (by rank) on
     * every process. */
    static void
    throw_first(const std::optional<InputError> &error, const MPI_Comm comm);

    /** The input the constructor's check_input names
     * (contact_surface_checks.cc): a body inside an obstacle before it
     * moves, a support that holds a node inside one, contact boundary ids
     * with no node that can act (@p acting_vertices: per id, the vertices
     * that face an obstacle). */
    void
    check_vertices(
      const std::vector<Vertex>                                &vertices,
      const std::map<dealii::types::boundary_id, unsigned int> &acting_vertices,
      const dealii::AffineConstraints<double> &constraints) const;

    /** The nodes' lumped contact-boundary masses
     * (contact_surface_masses.cc). */
    void
    compute_masses(const Discretisation<dim> &discretisation);

    const std::set<dealii::types::boundary_id> ids;
    const ObstacleSet<dim>                    &obstacle_set;
    const bool                                 check_input;
    MPI_Comm                                   mpi_communicator;
    double                                     tolerance = 0.;
    std::vector<ContactNode<dim>>              contact_nodes;
    std::vector<std::vector<unsigned int>>     corner_nodes;
  };
} // namespace signorini

#endif
