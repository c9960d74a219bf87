#ifndef signorini_mesh_adaptation_size_field_h
#define signorini_mesh_adaptation_size_field_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <vector>

namespace signorini
{
  /**
   * The mesh size field [mm] that Gmsh remeshes with on a kelly cycle:
   * small cells where the error indicator is large, coarser ones where it
   * is small, so that the next mesh equidistributes the error.
   *
   * For P1 the Kelly indicator of a cell of size h (its mean edge length)
   * scales as eta_K ~ h^(1 + d/2) (energy-norm error density times the
   * cell's measure). Asking every cell of the next mesh for the same
   * eta_target gives the new size
   *
   *     h_new = h * clamp((eta_target / eta_K)^(1 / (1 + d/2)), 1/4, 2),
   *
   * at least @p min_size. The new mesh has about sum_K (h / h_new)^d
   * cells; eta_target is found by bisection so that this is @p growth
   * times the current number of cells. A vertex takes the mean of its cells'
   * sizes; a point between vertices the inverse-distance weighted mean of
   * the d + 1 nearest vertices, which also covers points of a curved
   * boundary outside the old, polygonal mesh.
   */
  template <int dim>
  class SizeField
  {
  public:
    /** @p indicators per active cell of the serial @p mesh. */
    SizeField(const dealii::Triangulation<dim> &mesh,
              const std::vector<double>        &indicators,
              const double                      growth,
              const double                      min_size);
    ~SizeField();

    /** The target size at @p point (its z is ignored in 2D). */
    double
    operator()(const dealii::Point<3> &point) const;

    /** The smallest and the largest target size [mm]. */
    double smallest = 0., largest = 0.;
    /** The number of cells the field asks for. */
    double expected_cells = 0.;

  private:
    std::vector<dealii::Point<dim>> vertices;
    std::vector<double>             vertex_sizes;
    struct Tree;
    std::unique_ptr<Tree> tree;
  };
} // namespace signorini

#endif
