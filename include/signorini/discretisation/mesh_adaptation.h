#ifndef signorini_discretisation_mesh_adaptation_h
#define signorini_discretisation_mesh_adaptation_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <memory>
#include <vector>

namespace signorini
{
  /**
   * Where each cycle's mesh comes from: the mesh of cycle 0, and the next
   * cycle's mesh from this one's error indicators. Two implementations
   * behind one interface:
   *
   * - HangingNodeRefinement: quadrilateral/hexahedral meshes (distributed
   *   with p4est) refined and coarsened with hanging nodes, and simplex
   *   meshes without a geometry refined globally on one process; the
   *   solution is carried over to the new mesh.
   * - GmshRemeshing: simplex meshes. Meshes from a .geo are remeshed by
   *   Gmsh from the geometry each cycle, with a size field from the error
   *   indicators (kelly) or halved sizes (global); other simplex meshes
   *   are refined globally. On several processes the serial mesh is
   *   partitioned and becomes a fully distributed triangulation. The
   *   solution is interpolated at the new vertices.
   *
   * create_mesh_adaptation() (mesh_adaptation/mesh_adaptation_factory.h)
   * chooses by the cell type; the Discretisation calls the factory it is
   * given once it knows the cell type.
   */
  template <int dim>
  class MeshAdaptation
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    virtual ~MeshAdaptation() = default;

    /** The mesh of cycle 0 from @p coarse_mesh, the same serial mesh on
     * every process: serial, p4est-distributed or fully distributed. */
    virtual std::unique_ptr<dealii::Triangulation<dim>>
    create_mesh(const dealii::Triangulation<dim> &coarse_mesh) = 0;

    /**
     * Turns @p triangulation into the next cycle's mesh (in place, or by a
     * new object), guided by the cell error @p indicators (indexed by
     * active cell index, set on locally owned cells) of the current
     * @p dof_handler. Once the new mesh is in place, @p setup_system is
     * called: it must distribute the dofs on `*triangulation`. Returns the
     * ghosted @p vectors of the old mesh interpolated to the new dofs (not
     * ghosted, without constraints applied).
     */
    virtual std::vector<VectorType>
    adapt(std::unique_ptr<dealii::Triangulation<dim>> &triangulation,
          const dealii::DoFHandler<dim>               &dof_handler,
          const dealii::Vector<float>                 &indicators,
          const std::function<void()>                 &setup_system,
          const std::vector<const VectorType *>       &vectors) = 0;
  };

} // namespace signorini

#endif
