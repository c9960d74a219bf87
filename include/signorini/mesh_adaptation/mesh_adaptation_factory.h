#ifndef signorini_mesh_adaptation_mesh_adaptation_factory_h
#define signorini_mesh_adaptation_mesh_adaptation_factory_h

#include <deal.II/base/mpi.h>

#include <signorini/discretisation/geometry.h>
#include <signorini/discretisation/mesh_adaptation.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>

#include <functional>
#include <memory>

namespace signorini
{
  /** The adaptation for a mesh of @p simplex cells (else quadrilaterals or
   * hexahedra); throws an InputError for a combination that cannot be
   * adapted (kelly cycles on a simplex mesh without a .geo). */
  template <int dim>
  std::unique_ptr<MeshAdaptation<dim>>
  create_mesh_adaptation(const Geometry<dim> &geometry,
                         const Refinement    &refinement,
                         const bool           simplex,
                         const MPI_Comm       comm);

  /** The factory a Discretisation is given: create_mesh_adaptation() of
   * @p geometry and @p refinement on @p comm, for the cell type found. */
  template <int dim>
  std::function<std::unique_ptr<MeshAdaptation<dim>>(const bool)>
  mesh_adaptation_factory(const Geometry<dim> &geometry,
                          const Refinement    &refinement,
                          const MPI_Comm       comm)
  {
    return [&geometry, &refinement, comm](const bool simplex) {
      return create_mesh_adaptation(geometry, refinement, simplex, comm);
    };
  }
} // namespace signorini

#endif
