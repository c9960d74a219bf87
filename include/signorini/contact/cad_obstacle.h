#ifndef signorini_contact_cad_obstacle_h
#define signorini_contact_cad_obstacle_h

#include <signorini/contact/obstacle.h>

#include <memory>

namespace signorini
{
  /**
   * A rigid solid from a CAD or Gmsh geometry file: a .step/.stp or .brep
   * file read by OpenCASCADE, or a .geo file (with OpenCASCADE as its
   * kernel) that Gmsh turns into one. In 3D the solid is its volumes, in 2D
   * its surfaces in the plane z = 0; lengths in mm.
   *
   * The gap of a point is its distance to the solid's boundary (the closest
   * point by OpenCASCADE's projection, BRepExtrema), negative inside the
   * solid; the normal points from the closest point to the point (away from
   * the solid), and on the boundary itself it is the surface's normal (a
   * face's in 3D, an edge's in 2D; the mean of the adjacent ones on an edge
   * or corner of the solid). With the body inside (a bore, a seat milled
   * into a block), the signs turn: the solid's inside is free space.
   */
  template <int dim>
  class CadObstacle : public Obstacle<dim>
  {
  public:
    /** Reads @p file, given by the parameter @p entry; throws InputError if
     * it cannot be read or holds no solid (3D) or surface (2D). */
    CadObstacle(const std::string &file,
                const bool         body_inside,
                const std::string &entry);
    ~CadObstacle() override;

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    std::string
    entry() const override;

    /** The solid's boundary, tessellated by OpenCASCADE (3D) or its edges
     * sampled (2D); whole, whatever @p box. */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    /** The OpenCASCADE shapes and their queries. */
    struct Geometry;
    std::unique_ptr<Geometry> geometry;
    const bool                body_inside;
    const std::string         file_entry;
  };
} // namespace signorini

#endif
