#ifndef signorini_mesh_adaptation_gmsh_remeshing_h
#define signorini_mesh_adaptation_gmsh_remeshing_h

#include <signorini/discretisation/geometry.h>
#include <signorini/discretisation/mesh_adaptation.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>

namespace signorini
{
  /**
   * Simplex meshes, on any number of processes. Every process keeps the
   * cycle's serial mesh; on several processes it is partitioned (METIS, on
   * the first process) and becomes a fully distributed triangulation.
   *
   * The next cycle's serial mesh: a .geo is remeshed by Gmsh from the
   * geometry, so that curved boundaries are sampled anew, with the
   * SizeField of the cells' error indicators (kelly; the number of cells
   * grows by the factor of a kelly cycle with hanging nodes,
   * 1 + (2^d - 1) x `Refine fraction` - (1 - 2^-d) x `Coarsen fraction`)
   * or with every size halved (global). Other simplex meshes are refined
   * globally. The displacement and pressure are carried over by
   * NodeTransfer, so that a cycle starts from the previous one's
   * solution and active set.
   */
  template <int dim>
  class GmshRemeshing : public MeshAdaptation<dim>
  {
  public:
    using typename MeshAdaptation<dim>::VectorType;

    GmshRemeshing(const Geometry<dim> &geometry,
                  const Refinement    &refinement,
                  const MPI_Comm       comm);

    std::unique_ptr<dealii::Triangulation<dim>>
    create_mesh(const dealii::Triangulation<dim> &coarse_mesh) override;

    std::vector<VectorType>
    adapt(std::unique_ptr<dealii::Triangulation<dim>> &triangulation,
          const dealii::DoFHandler<dim>               &dof_handler,
          const dealii::Vector<float>                 &indicators,
          const std::function<void()>                 &setup_system,
          const std::vector<const VectorType *>       &vectors) override;

  private:
    /** The triangulation the solver works on, made from #serial. */
    std::unique_ptr<dealii::Triangulation<dim>>
    distribute() const;

    const Geometry<dim> geometry;
    const Refinement    refinement;
    const MPI_Comm      comm;
    /** This cycle's mesh, complete on every process. */
    dealii::Triangulation<dim> serial;
    /** Global cycles so far: a .geo's sizes are divided by 2^level. */
    unsigned int level = 0;
  };
} // namespace signorini

#endif
