#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    const Choices<Refinement::Strategy> strategies{
      {Refinement::Strategy::global, "global"},
      {Refinement::Strategy::kelly, "kelly"}};

    const Choices<Refinement::KellyWeight> kelly_weights{
      {Refinement::KellyWeight::revolution, "revolution"},
      {Refinement::KellyWeight::section, "section"}};
  } // namespace

  void
  Refinement::declare_parameters(ParameterHandler &prm)
  {
    const Refinement defaults;
    prm.enter_subsection("Mesh refinement");
    prm.declare_entry("Number of cycles",
                      entry_text::of(defaults.n_cycles),
                      Patterns::Integer(1, 100),
                      "Solve-estimate-refine cycles; each starts from the "
                      "previous cycle's solution and active set.");
    prm.declare_entry("Strategy",
                      strategies.name(defaults.strategy),
                      strategies.pattern(),
                      "global: refine every cell; kelly: refine and coarsen "
                      "the cells with the largest/smallest Kelly error "
                      "indicators (quadrilaterals/hexahedra), or, on "
                      "triangles/tetrahedra from a .geo, remesh it with Gmsh "
                      "with cell sizes from the indicators (growing the "
                      "number of cells as the fractions would). A .geo on "
                      "simplices remeshes for global too, halving sizes.");
    prm.declare_entry("Refine fraction",
                      entry_text::of(defaults.refine_fraction),
                      Patterns::Double(0., 1.),
                      "kelly: fraction of the cells refined per cycle.");
    prm.declare_entry("Coarsen fraction",
                      entry_text::of(defaults.coarsen_fraction),
                      Patterns::Double(0., 1.),
                      "kelly: fraction of the cells coarsened per cycle.");
    prm.declare_entry(
      "Kelly weight",
      kelly_weights.name(defaults.kelly_weight),
      kelly_weights.pattern(),
      "Axisymmetric models only: revolution weights the Kelly indicators "
      "by 2 pi r, as every other integral, so that the cycles spread the "
      "energy error of the revolved body evenly; section leaves them "
      "unweighted, the error of the (r, z) section, which refines near the "
      "axis as much as away from it (for a quantity on the axis, such as "
      "the peak pressure of a sphere).");
    prm.declare_entry(
      "Imbalance tolerance",
      entry_text::of(defaults.imbalance_tolerance),
      Patterns::Double(0.),
      "Several processes, quadrilaterals/hexahedra: a refined mesh keeps "
      "its partition (each process its cells) unless a process would own "
      "more than (1 + this) times the mean number of cells; then it is "
      "balanced anew. Cells that change processes are rebuilt there level "
      "by level, which on the 2D Hertz scene made a refinement on two "
      "processes slower than on one; an imbalance slows the cycle's solve "
      "by up to this fraction. 0 balances every refined mesh.");
    prm.leave_subsection();
  }

  void
  Refinement::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    n_cycles = prm.get_integer("Number of cycles");
    strategy =
      strategies.value(prm.get("Strategy"), "Mesh refinement/Strategy");
    refine_fraction     = prm.get_double("Refine fraction");
    coarsen_fraction    = prm.get_double("Coarsen fraction");
    kelly_weight        = kelly_weights.value(prm.get("Kelly weight"),
                                       "Mesh refinement/Kelly weight");
    imbalance_tolerance = prm.get_double("Imbalance tolerance");
    prm.leave_subsection();
    if (refine_fraction + coarsen_fraction > 1.)
      throw InputError("Mesh refinement/Coarsen fraction",
                       "refine and coarsen fractions add up to more than 1");
    if (strategy == Strategy::kelly && refine_fraction == 0. && n_cycles > 1)
      warn("Mesh refinement/Refine fraction",
           "is 0: the Kelly cycles after cycle 0 refine no cell");
  }
} // namespace signorini
