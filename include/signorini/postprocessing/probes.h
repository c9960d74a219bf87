#ifndef signorini_postprocessing_probes_h
#define signorini_postprocessing_probes_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/discretisation/discretisation.h>

#include <vector>

namespace signorini
{
  /** The ghosted displacement @p u [mm] at each of @p points, on every
   * process; each is evaluated by the lowest-ranked process that owns a
   * cell around it. Throws InputError (Output/Probe points) for a point
   * outside the body. */
  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  evaluate_probes(const Discretisation<dim>                   &discretisation,
                  const dealii::TrilinosWrappers::MPI::Vector &u,
                  const std::vector<dealii::Point<dim>>       &points);
} // namespace signorini

#endif
