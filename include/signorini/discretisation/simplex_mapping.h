#ifndef signorini_discretisation_simplex_mapping_h
#define signorini_discretisation_simplex_mapping_h

#include <deal.II/fe/mapping_fe.h>

#include <memory>

namespace signorini
{
  /**
   * The mapping of P2 triangles and tetrahedra that follows curved
   * boundaries: each cell is the image of its six (ten) nodes, its vertices
   * and the middles of its edges, where an edge's manifold puts its middle
   * (on the arc of a .geo's curve, in 3D on its surface). deal.II 9.4's
   * MappingFE puts the middles on the straight edges whenever the cell, its
   * faces and edges do not all have one manifold, so that a P2 disk stays
   * its polygon of chords.
   */
  template <int dim>
  class SimplexMapping : public dealii::MappingFE<dim>
  {
  public:
    /** The mapping of degree 2. */
    SimplexMapping();

    std::unique_ptr<dealii::Mapping<dim>>
    clone() const override;

  protected:
    std::vector<dealii::Point<dim>>
    compute_mapping_support_points(
      const typename dealii::Triangulation<dim>::cell_iterator &cell)
      const override;
  };
} // namespace signorini

#endif
