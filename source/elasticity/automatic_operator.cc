#include <deal.II/base/mpi.h>

#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/automatic_operator.h>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Whether @p cell is a parallelogram or parallelepiped with flat
     * manifolds: its matrix-free stiffness is one matrix per shape. */
    template <typename Cell>
    bool
    affine(const Cell &cell)
    {
      constexpr int dim = Cell::AccessorType::dimension;
      if (!on_flat_manifolds(cell))
        return false;
      // Vertex i (bits x, y, z) at v0 + the edges along its bits.
      const auto   v0        = cell->vertex(0);
      const double tolerance = 1e-10 * cell->diameter();
      for (unsigned int i = 0; i < cell->n_vertices(); ++i)
        {
          auto expected = v0;
          for (unsigned int bit = 0; bit < dim; ++bit)
            if (i & (1u << bit))
              expected += cell->vertex(1u << bit) - v0;
          if (cell->vertex(i).distance(expected) > tolerance)
            return false;
        }
      return true;
    }
  } // namespace

  template <int dim>
  AutomaticOperator<dim>::AutomaticOperator(
    const Discretisation<dim> &discretisation,
    const bool                 pointwise,
    Factory                    make)
    : discretisation(discretisation)
    , pointwise(pointwise)
    , make(std::move(make))
  {
  }

  template <int dim>
  void
  AutomaticOperator<dim>::reinit()
  {
    if (!chosen)
      {
        bool matrix_free = dim == 3 && !discretisation.simplex() && pointwise;
        // At degree 2 on any hexahedra; at degree 1 where at least half the
        // cells are parallelepipeds.
        if (matrix_free && discretisation.degree() == 1)
          {
            double counts[2] = {0., 0.};
            for (const auto &cell :
                 discretisation.triangulation().active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  counts[0] += affine(cell) ? 1. : 0.;
                  counts[1] += 1.;
                }
            Utilities::MPI::sum(counts,
                                discretisation.mpi_communicator(),
                                counts);
            matrix_free = counts[0] >= 0.5 * counts[1];
          }
        chosen = make(matrix_free);
      }
    chosen->reinit();
  }

  template <int dim>
  void
  AutomaticOperator<dim>::assemble_load()
  {
    chosen->assemble_load();
  }

  template <int dim>
  const typename AutomaticOperator<dim>::VectorType &
  AutomaticOperator<dim>::load() const
  {
    return chosen->load();
  }

  template <int dim>
  void
  AutomaticOperator<dim>::residual(const VectorType &u, VectorType &residual)
  {
    chosen->residual(u, residual);
  }

  template <int dim>
  void
  AutomaticOperator<dim>::solve(const SystemAdditions<dim> &additions,
                                VectorType                 &u,
                                const bool                  final_step)
  {
    chosen->solve(additions, u, final_step);
  }

  template <int dim>
  void
  AutomaticOperator<dim>::invalidate()
  {
    if (chosen)
      chosen->invalidate();
  }

  template <int dim>
  void
  AutomaticOperator<dim>::release()
  {
    if (chosen)
      chosen->release();
  }

  template class AutomaticOperator<2>;
  template class AutomaticOperator<3>;
} // namespace signorini
