#ifndef signorini_elasticity_cell_stiffness_h
#define signorini_elasticity_cell_stiffness_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <signorini/elasticity/material.h>

#include <array>
#include <functional>
#include <map>
#include <set>

namespace signorini
{
  /**
   * The stiffness matrix of a cell, the integral of eps(phi_i) : sigma(phi_j)
   * [N/mm], computed once per cell shape. Cells whose vertices are a
   * translated and scaled copy of another cell's (all cells of a refined box,
   * most of an adaptive mesh of straight-sided cells) share one matrix, up to
   * the factor s^(dim-2) for the scale s: with linear mappings the geometry
   * is the vertices. The shape is compared exactly (vertex offsets divided
   * by the first edge's length), so a cached matrix is the computed one to
   * round-off. Cells of curved meshes rarely repeat: after a number of
   * shapes without repetition the cache stops storing new ones.
   *
   * In an axisymmetric model the matrix is the integral over the revolved
   * cell, eps : sigma with the hoop strain, times 2 pi r: it depends on the
   * cell's distance from the axis. The shape then includes the first
   * vertex's r divided by the edge length, so that cells share a matrix
   * only if one is a copy of the other scaled about the axis and moved
   * along it, and K(s x) = s K(x).
   */
  template <int dim>
  class CellStiffness
  {
  public:
    /** Whether a cell is curved by the mapping (its geometry more than its
     * vertices): such cells are never cached. */
    using CurvedCell = std::function<bool(
      const typename dealii::Triangulation<dim>::cell_iterator &)>;

    /** @p curved: see CurvedCell; empty for a linear mapping. */
    CellStiffness(const Material &material, const CurvedCell &curved = {});

    /** Forgets the cached matrices (call when the mesh changes). */
    void
    clear();

    /** The stiffness matrix of @p cell; @p fe_values is reinit'ed on it only
     * when the matrix has to be computed. */
    const dealii::FullMatrix<double> &
    matrix(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
           dealii::FEValues<dim> &fe_values);

    /** The stiffness matrix of @p cell over @p factor (K = factor times
     * it) if its shape is cached, or computed and cached now if it was seen
     * before (@p fe_values reinit'ed on @p cell); null, with @p fe_values
     * untouched, at a shape's first sighting and once the cache stores no
     * more shapes (curved meshes, whose cells rarely
     * repeat: the caller may evaluate the cell more cheaply than its
     * whole matrix). Valid until the cache is cleared. */
    const dealii::FullMatrix<double> *
    shared(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
           dealii::FEValues<dim> &fe_values,
           double                &factor);

    /** The stiffness matrix of @p cell if its shape is cached, else null
     * (the caller may then need less than the whole matrix). Valid until
     * the next call. */
    const dealii::FullMatrix<double> *
    cached(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell);

    /** The matrix of the cell @p fe_values was reinit'ed on, computed;
     * @p fe_values has the flags of elastic_update_flags(). */
    void
    compute(const dealii::FEValues<dim> &fe_values,
            dealii::FullMatrix<double>  &cell_matrix) const;

  private:
    static constexpr unsigned int max_vertices = 1U << dim;
    /** The vertex offsets, then the first vertex's r (axisymmetric; else
     * zero). */
    using Shape = std::array<double, dim *(max_vertices - 1) + 1>;

    /** The vertex offsets of @p cell (and the first vertex's r) divided by
     * its first edge's length, @p scale. */
    Shape
    shape_of(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
             double &scale) const;

    const Material  &material;
    const CurvedCell curved;
    /** Whether the matrix of a cell scaled by s is s times the unscaled
     * one's (3D, axisymmetric), or the same (2D plane states). */
    const bool                                  scales_linearly;
    std::map<Shape, dealii::FullMatrix<double>> cache;
    /** shared(), or for matrix() (@p at_first_sight) storing a shape the
     * first time it is seen. */
    const dealii::FullMatrix<double> *
    find_or_store(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      dealii::FEValues<dim>                                        &fe_values,
      double                                                       &factor,
      const bool at_first_sight);

    /** The shapes seen once, not yet stored. */
    std::set<Shape>            seen;
    unsigned int               lookups = 0;
    dealii::FullMatrix<double> scaled;
  };
  /** What FEValues must compute for CellStiffness::compute() and
   * cell_internal_force(): gradients and JxW values, and the shape values
   * and quadrature points of an axisymmetric model. */
  dealii::UpdateFlags
  elastic_update_flags(const Material &material);

  /** The internal force vector of the cell @p fe_values was reinit'ed on
   * (with the flags of elastic_update_flags()), the integral of
   * eps(phi_i) : sigma(u) [N], for the ghosted displacement @p u (a
   * Trilinos or a deal.II vector, the latter faster to read); returns the
   * cell's strain energy 1/2 a(u,u) [N mm]. */
  template <int dim, typename VectorType>
  double
  cell_internal_force(const Material              &material,
                      const dealii::FEValues<dim> &fe_values,
                      const VectorType            &u,
                      dealii::Vector<double>      &internal);
} // namespace signorini

#endif
