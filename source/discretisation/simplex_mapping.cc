#include <deal.II/fe/fe_simplex_p.h>

#include <signorini/discretisation/simplex_mapping.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  SimplexMapping<dim>::SimplexMapping()
    : MappingFE<dim>(FE_SimplexP<dim>(2))
  {
  }

  template <int dim>
  std::unique_ptr<Mapping<dim>>
  SimplexMapping<dim>::clone() const
  {
    return std::make_unique<SimplexMapping<dim>>(*this);
  }

  template <int dim>
  std::vector<Point<dim>>
  SimplexMapping<dim>::compute_mapping_support_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    // P2's support points: the vertices, then the edges' middles in the
    // order of the cell's lines (a triangle's lines are its faces).
    std::vector<Point<dim>> points;
    points.reserve(cell->n_vertices() + cell->n_lines());
    for (const unsigned int v : cell->vertex_indices())
      points.push_back(cell->vertex(v));
    for (unsigned int l = 0; l < cell->n_lines(); ++l)
      points.push_back(cell->line(l)->center(/*respect_manifold=*/true));
    return points;
  }

  template class SimplexMapping<2>;
  template class SimplexMapping<3>;
} // namespace signorini
