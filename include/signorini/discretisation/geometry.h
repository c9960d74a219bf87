#ifndef signorini_discretisation_geometry_h
#define signorini_discretisation_geometry_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <signorini/discretisation/gmsh_mesher.h>

#include <string>
#include <vector>

namespace signorini
{
  /**
   * The body's shape: subsection `Geometry`. Three kinds of coarse mesh:
   *
   * - `rectangle` (a box in 3D) from `Lower left corner` to `Upper right
   *   corner` with `Subdivisions` cells per direction; boundary ids 0/1 at
   *   x = min/max, 2/3 at y = min/max, 4/5 at z = min/max. `Cell type =
   *   simplex` splits every quadrilateral into 8 triangles (hexahedron into 24
   *   tetrahedra), keeping the boundary ids.
   * - `half ball` (a half-disk in 2D) of `Radius` around `Center`, flat face
   *   on top (+y, or +z in 3D), curved face below: boundary id 0 on the curved
   *   face, 1 on the flat one.
   * - `quarter disk` (2D) and `quarter ball` (3D): the part x >= Center x
   *   (and y >= Center y in 3D) of the half ball, for symmetric scenes; the
   *   symmetry lines or planes get ids 2 (x = Center x) and 3 (y = Center
   *   y).
   * - `gmsh`: a `.msh` file, or a `.geo` geometry meshed by Gmsh when the
   *   run starts (see gmsh_mesher.h) with the `Cell type` and `Mesh size`
   *   asked for; physical groups give boundary ids. Triangles or
   *   tetrahedra get P1 elements, quadrilaterals or hexahedra Q1. A `.geo`
   *   takes `Initial refinement` as sizes divided by 2^k, so that curved
   *   boundaries follow the geometry.
   */
  template <int dim>
  struct Geometry
  {
    enum class Type
    {
      rectangle,
      half_ball,
      quarter_disk,
      quarter_ball,
      gmsh
    };

    Type type = Type::rectangle;
    /** rectangle: the corner with the smallest coordinates [mm]. */
    dealii::Point<dim> lower_left;
    /** rectangle: the corner with the largest coordinates [mm]. */
    dealii::Point<dim> upper_right = point_with(1., 1.);
    /** rectangle: cells in x, y[, z] on the coarse mesh. */
    std::vector<unsigned int> subdivisions = std::vector<unsigned int>(dim, 1);
    GmshOptions::CellType     cell_type    = GmshOptions::CellType::automatic;
    /** gmsh with a .geo: uniform target size [mm], 0: the .geo's sizes. */
    double mesh_size = 0.;
    /** half ball, quarter disk, quarter ball: the center of the flat face
     * [mm]. */
    dealii::Point<dim> center = point_with(0., 1.);
    /** half ball, quarter disk, quarter ball: the radius [mm]. */
    double radius = 1.;
    /** Absolute path, resolved relative to the parameter file's folder. */
    std::string mesh_file;
    /** Global refinements of the coarse mesh before cycle 0. */
    unsigned int initial_refinement = 0;
    /** Polynomial degree of the elements: 1 (Q1) or 2 (Q2, with cells
     * that follow the curved boundaries by a mapping of degree 2). */
    unsigned int element_degree = 1;

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** A relative `Mesh file` is looked for in @p folders, in order (the
     * parameter file's folder, then those of the files it includes). */
    void
    parse_parameters(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &folders);

    /** Whether `Mesh file` is a Gmsh geometry (.geo) meshed at run time,
     * which can be remeshed. */
    bool
    from_geometry_file() const;

    /** What Gmsh is asked for when it meshes the .geo: the cell type, the
     * mesh size and the initial refinement. */
    GmshOptions
    gmsh_options() const;

    /** Fills the empty serial @p coarse_mesh with the unrefined mesh, the
     * same on every process of @p comm (a .geo is meshed by the first one;
     * its initial refinement is part of the meshing). */
    void
    create_coarse_mesh(dealii::Triangulation<dim> &coarse_mesh,
                       const MPI_Comm              comm) const;

    /** The point with @p coordinate in every coordinate but the last and
     * @p last in the last one. */
    static dealii::Point<dim>
    point_with(const double coordinate, const double last);
  };
} // namespace signorini

#endif
