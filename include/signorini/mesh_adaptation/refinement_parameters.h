#ifndef signorini_mesh_adaptation_refinement_parameters_h
#define signorini_mesh_adaptation_refinement_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace signorini
{
  /** Adaptive cycles: subsection `Mesh refinement`. */
  struct Refinement
  {
    enum class Strategy
    {
      global,
      kelly
    };

    /** What an axisymmetric model's Kelly indicators measure. */
    enum class KellyWeight
    {
      /** The error of the revolved body: face integrals weighted by
       * 2 pi r. */
      revolution,
      /** The error of the (r, z) section: unweighted. */
      section
    };

    /** Solve-estimate-refine cycles. */
    unsigned int n_cycles = 1;
    Strategy     strategy = Strategy::kelly;
    /** kelly: fraction of the cells refined per cycle. */
    double refine_fraction = 0.3;
    /** kelly: fraction of the cells coarsened per cycle. */
    double coarsen_fraction = 0.03;
    /** kelly, axisymmetric models: the weight of the indicators. */
    KellyWeight kelly_weight = KellyWeight::revolution;
    /** Several processes: how far above the mean number of cells a
     * process's share of a refined mesh may lie before the mesh is
     * repartitioned (see execute_refinement()). */
    double imbalance_tolerance = 0.1;

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
