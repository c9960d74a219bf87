#ifndef signorini_mesh_adaptation_hanging_node_refinement_h
#define signorini_mesh_adaptation_hanging_node_refinement_h

#include <signorini/discretisation/geometry.h>
#include <signorini/discretisation/mesh_adaptation.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>

namespace signorini
{
  /**
   * Refinement in place: quadrilateral/hexahedral meshes distributed with
   * p4est, refined globally or, for kelly, by refining and coarsening the
   * fixed fractions of cells with the largest and smallest indicators
   * (hanging nodes); simplex meshes without a geometry on one process,
   * refined globally. The displacement and pressure are interpolated to
   * the new mesh, so that a cycle starts from the previous one's solution
   * and active set.
   */
  template <int dim>
  class HangingNodeRefinement : public MeshAdaptation<dim>
  {
  public:
    using typename MeshAdaptation<dim>::VectorType;

    /** @p initial_refinement global refinements make cycle 0's mesh. */
    HangingNodeRefinement(const Refinement  &refinement,
                          const unsigned int initial_refinement,
                          const bool         simplex,
                          const MPI_Comm     comm);

    std::unique_ptr<dealii::Triangulation<dim>>
    create_mesh(const dealii::Triangulation<dim> &coarse_mesh) override;

    std::vector<VectorType>
    adapt(std::unique_ptr<dealii::Triangulation<dim>> &triangulation,
          const dealii::DoFHandler<dim>               &dof_handler,
          const dealii::Vector<float>                 &indicators,
          const std::function<void()>                 &setup_system,
          const std::vector<const VectorType *>       &vectors) override;

  private:
    const Refinement   refinement;
    const unsigned int initial_refinement;
    const bool         simplex;
    const MPI_Comm     comm;
  };
} // namespace signorini

#endif
