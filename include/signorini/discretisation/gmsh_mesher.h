#ifndef signorini_discretisation_gmsh_mesher_h
#define signorini_discretisation_gmsh_mesher_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <istream>
#include <string>

namespace signorini
{
  /** What Gmsh is asked to make of a geometry (.geo) file. */
  struct GmshOptions
  {
    /** Element kind: as the .geo says (Gmsh's default: triangles and
     * tetrahedra), or forced. */
    enum class CellType
    {
      automatic,
      quadrilateral,
      simplex
    };

    CellType cell_type = CellType::automatic;
    /** A uniform target cell size [mm] replacing the .geo's own sizes;
     * 0 keeps them. */
    double size = 0.;
    /** Multiplies every size (Gmsh's Mesh.MeshSizeFactor). */
    double size_factor = 1.;
    /** A size field [mm] at a point (x, y, z) replacing every other size:
     * used when remeshing. Called on the first process only. */
    std::function<double(const dealii::Point<3> &)> size_field;
    /** Bounds of the size field's sizes [mm] (0: none). */
    double min_size = 0.;
    double max_size = 0.;
  };

  /**
   * Meshes the geometry @p geo_file with the Gmsh library and fills the
   * empty serial @p mesh with the result on every process of @p comm. Gmsh
   * runs on the first process only; the others receive the mesh as the text
   * of a .msh file, so that every process holds the same mesh. Physical
   * groups of curves (surfaces in 3D) give the boundary ids; without a
   * physical group of @p dim-dimensional entities, all of them are meshed.
   *
   * Throws, on every process, an InputError for `Geometry/Mesh file` that
   * names the file and gives Gmsh's own reason when Gmsh cannot mesh it.
   */
  template <int dim>
  void
  mesh_geometry_file(const std::string          &geo_file,
                     const GmshOptions          &options,
                     dealii::Triangulation<dim> &mesh,
                     const MPI_Comm              comm);

  /** Reads a .msh file from @p input into the empty serial @p mesh; errors
   * are InputErrors for `Geometry/Mesh file` naming @p file_name. */
  template <int dim>
  void
  read_msh(std::istream               &input,
           const std::string          &file_name,
           dealii::Triangulation<dim> &mesh);
} // namespace signorini

#endif
