#ifndef signorini_discretisation_gmsh_geometry_h
#define signorini_discretisation_gmsh_geometry_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <string>

namespace signorini
{
  /**
   * The curved boundary of a mesh made by Gmsh from a .geo file, followed
   * by refinement and by the mid-nodes of degree 2: a face of the coarse
   * mesh on a curve of the .geo (in 3D a surface, and the face's edges)
   * that is not straight (flat) gets a manifold that puts each new vertex
   * or mid-node at the closest point of that curve, found by Gmsh from the
   * .geo itself (either geometry kernel). Without it, quadrilaterals and
   * hexahedra refined cycle by cycle keep the coarse mesh's straight edges:
   * a disk stays its coarse polygon, and the contact pressure spikes at its
   * corners.
   *
   * Attaches the manifolds to @p coarse_mesh, made from @p geo_file; every
   * process of @p comm reads the .geo. Manifold ids from 1000 on are this
   * function's.
   */
  template <int dim>
  void
  attach_gmsh_geometry(dealii::Triangulation<dim> &coarse_mesh,
                       const std::string          &geo_file,
                       const MPI_Comm              comm);
} // namespace signorini

#endif
