#ifndef signorini_base_owned_values_h
#define signorini_base_owned_values_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_MultiVector.h>
#include <algorithm>

namespace signorini
{
  /**
   * Where the locally owned entries of @p vector (with or without ghost
   * entries) begin in its local array, if @p owned, its locally owned
   * indices, is one range (a distributed DoFHandler's are); nullptr
   * otherwise. A ghosted Trilinos vector lists its entries by index, so
   * every process but the first has ghosts before its own entries, and
   * deal.II's element access looks each index up in the Epetra map's hash
   * table; the owned entries are one block of the local array all the same.
   */
  inline double *
  owned_values(const dealii::TrilinosWrappers::MPI::Vector &vector,
               const dealii::IndexSet                      &owned)
  {
    if (owned.n_elements() == 0 || !owned.is_contiguous())
      return nullptr;
    const auto &values = vector.trilinos_vector();
    const int   first =
      values.Map().LID(static_cast<dealii::TrilinosWrappers::types::int_type>(
        owned.nth_index_in_set(0)));
    return first < 0 ? nullptr : values[0] + first;
  }

  /** The locally owned entries of @p in (indices @p owned) into those of
   * @p out, which has the same locally owned indices. */
  inline void
  copy_owned(const dealii::TrilinosWrappers::MPI::Vector        &in,
             const dealii::IndexSet                             &owned,
             dealii::LinearAlgebra::distributed::Vector<double> &out)
  {
    if (const double *values = owned_values(in, owned))
      std::copy(values, values + owned.n_elements(), out.begin());
    else
      for (const auto i : owned)
        out(i) = in(i);
  }

  /** The locally owned entries of @p in into those of @p out (indices
   * @p owned); @p out is compressed. */
  inline void
  copy_owned(const dealii::LinearAlgebra::distributed::Vector<double> &in,
             const dealii::IndexSet                                   &owned,
             dealii::TrilinosWrappers::MPI::Vector                    &out)
  {
    if (double *values =
          out.has_ghost_elements() ? nullptr : owned_values(out, owned))
      std::copy(in.begin(), in.begin() + owned.n_elements(), values);
    else
      for (const auto i : owned)
        out(i) = in(i);
    out.compress(dealii::VectorOperation::insert);
  }
} // namespace signorini

#endif
