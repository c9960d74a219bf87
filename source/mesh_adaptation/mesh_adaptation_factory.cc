#include <signorini/input/input_error.h>
#include <signorini/mesh_adaptation/gmsh_remeshing.h>
#include <signorini/mesh_adaptation/hanging_node_refinement.h>
#include <signorini/mesh_adaptation/mesh_adaptation_factory.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  std::unique_ptr<MeshAdaptation<dim>>
  create_mesh_adaptation(const Geometry<dim> &geometry,
                         const Refinement    &refinement,
                         const bool           simplex,
                         const MPI_Comm       comm)
  {
    const bool remeshable = geometry.from_geometry_file();
    // A .geo was meshed with its initial refinement already.
    const unsigned int initial_refinement =
      remeshable ? 0 : geometry.initial_refinement;
    if (!simplex)
      return std::make_unique<HangingNodeRefinement<dim>>(refinement,
                                                          initial_refinement,
                                                          false,
                                                          comm);
    if (refinement.strategy == Refinement::Strategy::kelly &&
        refinement.n_cycles > 1 && !remeshable)
      throw InputError("Mesh refinement/Strategy",
                       "kelly cycles on triangles/tetrahedra remesh the "
                       "geometry with Gmsh: give a .geo as Geometry/Mesh "
                       "file, or use global");
    if (!remeshable && Utilities::MPI::n_mpi_processes(comm) == 1)
      return std::make_unique<HangingNodeRefinement<dim>>(refinement,
                                                          initial_refinement,
                                                          true,
                                                          comm);
    return std::make_unique<GmshRemeshing<dim>>(geometry, refinement, comm);
  }

  template std::unique_ptr<MeshAdaptation<2>>
  create_mesh_adaptation(const Geometry<2> &,
                         const Refinement &,
                         const bool,
                         const MPI_Comm);
  template std::unique_ptr<MeshAdaptation<3>>
  create_mesh_adaptation(const Geometry<3> &,
                         const Refinement &,
                         const bool,
                         const MPI_Comm);
} // namespace signorini
