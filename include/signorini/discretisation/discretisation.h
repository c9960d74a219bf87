#ifndef signorini_discretisation_discretisation_h
#define signorini_discretisation_discretisation_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <signorini/discretisation/axisymmetry.h>
#include <signorini/discretisation/boundary_conditions.h>
#include <signorini/discretisation/geometry.h>
#include <signorini/discretisation/mesh_adaptation.h>

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace signorini
{
  /** Whether @p cell, its faces and (3D) its edges all lie on the flat
   * manifold: a mapping of any degree makes it the image of its vertices. */
  template <typename Cell>
  bool
  on_flat_manifolds(const Cell &cell)
  {
    constexpr int dim = Cell::AccessorType::dimension;
    if (cell->manifold_id() != dealii::numbers::flat_manifold_id)
      return false;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->manifold_id() != dealii::numbers::flat_manifold_id)
        return false;
    if (dim == 3)
      for (unsigned int l = 0; l < cell->n_lines(); ++l)
        if (cell->line(l)->manifold_id() != dealii::numbers::flat_manifold_id)
          return false;
    return true;
  }

  /**
   * The discretisation of the body: its mesh (and where each cycle's mesh
   * comes from), the finite element (Q1 or Q2 on quadrilaterals/hexahedra,
   * P1 on triangles/tetrahedra, dim components), the mapping and
   * quadratures, the
   * dofs with their index sets, and the constraints that stay fixed within a
   * load step: hanging nodes, and those plus the Dirichlet data (and, in an
   * axisymmetric model, u_r = 0 on the axis). It gives the weight of the
   * measure at a point, 1, or 2 pi r in an axisymmetric model.
   */
  template <int dim>
  class Discretisation
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /** @p axisymmetric: the mesh is the (r, z) half-plane of a body of
     * revolution (see elasticity/axisymmetry.h). */
    /** Makes the mesh adaptation once the cell type is known: the
     * argument is whether the cells are simplices. */
    using AdaptationFactory =
      std::function<std::unique_ptr<MeshAdaptation<dim>>(const bool)>;

    /** @p adaptation: see AdaptationFactory (mesh_adaptation_factory()). */
    Discretisation(const Geometry<dim>           &geometry,
                   const AdaptationFactory       &adaptation,
                   const BoundaryConditions<dim> &boundary_conditions,
                   const MPI_Comm                 mpi_communicator,
                   const bool                     axisymmetric = false);
    ~Discretisation();

    /** The boundary ids that an entry (named first) refers to. */
    using BoundaryIdUse =
      std::vector<std::pair<std::string, std::set<dealii::types::boundary_id>>>;

    /** The mesh of cycle 0, with its element, mapping and quadratures, and
     * its dofs. Throws InputError for a mesh that mixes cell types, or one
     * that lacks a boundary id of @p boundary_ids (naming the entry), or an
     * axisymmetric one that crosses the axis. */
    void
    make_grid(const BoundaryIdUse &boundary_ids);

    /**
     * The next cycle's mesh, guided by the cell error @p indicators, with its
     * dofs set up. Returns the ghosted @p vectors interpolated to the new
     * dofs (not ghosted; the first one with the constraints applied), or
     * nothing if the adaptation cannot carry them (a remesh).
     */
    std::vector<VectorType>
    refine(const dealii::Vector<float>           &indicators,
           const std::vector<const VectorType *> &vectors);

    /** Whether save() can store the mesh (a p4est mesh); otherwise cycle k's
     * mesh is the initial one refined globally k times. */
    bool
    saves_mesh() const;

    /** Stores the mesh to @p file with @p vectors and the cell values
     * @p cell_data attached (collective). */
    void
    save(const std::string                     &file,
         const std::vector<const VectorType *> &vectors,
         const dealii::Vector<float>           &cell_data) const;

    /** Replaces the mesh by the one saved to @p file and sets up its dofs;
     * fills @p vectors (locally owned) and @p cell_data from it. */
    void
    load(const std::string               &file,
         const std::vector<VectorType *> &vectors,
         dealii::Vector<float>           &cell_data);

    /** The Dirichlet data at the pseudo-time @p t of the load history:
     * sets the time of Boundary conditions/Prescribed displacement and, once
     * the mesh has dofs, makes constraints() anew with its values (the same
     * dofs constrained). Throws InputError if the displacement is not
     * finite at a Dirichlet node. */
    void
    set_time(const double t);

    /** Refines the mesh globally @p times and sets up its dofs. */
    void
    refine_globally(const unsigned int times);

    /** The smallest cell diameter of the mesh [mm]. */
    double
    minimal_cell_diameter() const;

    /** The diagonal of the initial mesh's bounding box [mm]. */
    double
    body_size() const;

    bool
    simplex() const;

    /** Whether the model is axisymmetric. */
    bool
    axisymmetric() const;

    /** The weight of the measure at @p x: 1, or 2 pi r in an axisymmetric
     * model, where every integral is over the whole revolution. Integrals
     * over cells and faces multiply their JxW values by it. */
    double
    weight(const dealii::Point<dim> &x) const
    {
      return axisymmetric_model ? axisymmetry::weight(x) : 1.;
    }

    /** The weight at quadrature point @p q of @p values, which has the
     * flags of weight_flags(). */
    double
    weight(const dealii::FEValuesBase<dim> &values, const unsigned int q) const
    {
      return axisymmetric_model ?
               axisymmetry::weight(values.quadrature_point(q)) :
               1.;
    }

    /** What FEValues must compute for weight(values, q): the quadrature
     * points of an axisymmetric model, nothing otherwise (asking a mapping
     * for points can change its Jacobians in the last bit). */
    dealii::UpdateFlags
    weight_flags() const
    {
      return axisymmetric_model ? dealii::update_quadrature_points :
                                  dealii::update_default;
    }

    const dealii::Triangulation<dim> &
    triangulation() const;
    const dealii::DoFHandler<dim> &
    dof_handler() const;
    const dealii::FiniteElement<dim> &
    fe() const;
    /** The linear mapping (degree 1), or the mapping of degree 2 whose
     * cells follow the mesh's manifolds. */
    const dealii::Mapping<dim> &
    mapping() const;
    /** The element's polynomial degree (Geometry/Element degree). */
    unsigned int
    degree() const;
    /** Whether the mapping curves @p cell: a mapping of degree 2 and a
     * manifold other than the flat one on the cell, a face or (3D) an
     * edge. A cell that is not curved is the image of its vertices. */
    bool
    curved(
      const typename dealii::Triangulation<dim>::cell_iterator &cell) const;
    /** Gauss rules exact for the stiffness of the element's degree. */
    const dealii::Quadrature<dim> &
    quadrature() const;
    const dealii::Quadrature<dim - 1> &
    face_quadrature() const;
    /** The rule of the contact nodes' lumped masses: the face rule at
     * degree 1; at degree 2 the nodes themselves with positive weights
     * (Gauss-Lobatto on edges and quadrilaterals; a triangle lumped as the
     * four its mid-nodes cut it into). */
    const dealii::Quadrature<dim - 1> &
    contact_face_quadrature() const;
    /** The rule of the contact zone's integrals (the pressure's, its
     * error's, the pressure recovery's mass matrix): far finer than the
     * element needs, so that they are those of the fields. */
    dealii::Quadrature<dim - 1>
    fine_face_quadrature() const;
    const dealii::IndexSet &
    locally_owned_dofs() const;
    const dealii::IndexSet &
    locally_relevant_dofs() const;
    /** Hanging nodes alone. */
    const dealii::AffineConstraints<double> &
    hanging_node_constraints() const;
    /** Hanging nodes and Dirichlet data. */
    const dealii::AffineConstraints<double> &
    constraints() const;
    /** Dofs on a Dirichlet boundary in a fixed component: where the support
     * reactions act (not the axis of an axisymmetric model). */
    const dealii::IndexSet &
    support_dofs() const;
    MPI_Comm
    mpi_communicator() const;

    /** The locally owned entries of the ghosted or owned @p vector in a
     * deal.II vector with the locally relevant ones as ghosts (updated):
     * faster to read in cell loops than a Trilinos vector, which looks
     * every entry up in a hash table. */
    dealii::LinearAlgebra::distributed::Vector<double>
    relevant_copy(const dealii::TrilinosWrappers::MPI::Vector &vector) const;

  private:
    void
    setup_dofs();

    /** The hanging nodes, the Dirichlet data at the time of the prescribed
     * displacement and (axisymmetric) the axis: constraints(). */
    void
    make_fixed_constraints();

    const Geometry<dim>           &geometry;
    const AdaptationFactory        adaptation_factory;
    const BoundaryConditions<dim> &boundary_conditions;
    MPI_Comm                       communicator;
    const bool                     axisymmetric_model;

    std::unique_ptr<MeshAdaptation<dim>>        mesh_adaptation;
    std::unique_ptr<dealii::Triangulation<dim>> mesh;
    bool                                        simplex_cells = false;
    double                                      diagonal      = 0.;
    std::unique_ptr<dealii::FiniteElement<dim>> element;
    const dealii::Mapping<dim>                 *linear_mapping = nullptr;
    std::unique_ptr<dealii::Mapping<dim>>       curved_mapping;
    dealii::Quadrature<dim>                     cell_rule;
    dealii::Quadrature<dim - 1>                 face_rule;
    dealii::Quadrature<dim - 1>                 contact_face_rule;
    dealii::DoFHandler<dim>                     dofs;
    dealii::IndexSet                            owned_dofs;
    dealii::IndexSet                            relevant_dofs;
    dealii::AffineConstraints<double>           hanging_nodes;
    dealii::AffineConstraints<double>           fixed_constraints;
    dealii::IndexSet                            supported_dofs;
  };
} // namespace signorini

#endif
