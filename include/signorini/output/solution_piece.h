#ifndef signorini_output_solution_piece_h
#define signorini_output_solution_piece_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <signorini/output/file_output.h>
#include <signorini/output/postprocessors.h>

#include <vector>

namespace signorini
{
  /** The entries of the vector @p vector, which holds ghost entries, at
   * the indices of @p dofs (the locally relevant ones), in their order:
   * read by position, which is faster than by global index. */
  std::vector<double>
  relevant_entries(const dealii::TrilinosWrappers::MPI::Vector &vector,
                   const dealii::IndexSet                      &dofs);

  /** What the points of a solution file are computed from. */
  template <int dim>
  struct PieceInputs
  {
    const dealii::Mapping<dim>    &mapping;
    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::IndexSet        &relevant_dofs;
    const std::vector<double>     &displacement;
    const std::vector<double>     &pressure;
    const std::vector<double>     &active;
    const dealii::Vector<float>   &kelly_indicator;
    const float                    rank;
    const DisplacementFields<dim> &fields;
  };

  /**
   * The locally owned cells of a cycle as a VTU piece, each cell with a
   * point at each of its vertices, as deal.II's DataOut builds its patches
   * (with the default subdivision, 1). All fields are evaluated in one pass
   * per cell: one FEValues at the vertices gives the displacement and its
   * gradient, and the pressure and the active set, which are nodal vectors
   * in the layout of the displacement, at one component per node. The
   * cells are split evenly among @p n_threads threads (each with its own
   * FEValues), which write to disjoint parts of the arrays.
   */
  template <int dim>
  VtuPiece
  build_piece(const PieceInputs<dim> &in, const unsigned int n_threads);
} // namespace signorini

#endif
