#include <signorini/input/input_error.h>
#include <signorini/mesh_adaptation/refinement_parameters.h>

namespace signorini
{
  using namespace dealii;

  void
  Refinement::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    prm.declare_entry("Number of cycles",
                      "1",
                      Patterns::Integer(1, 100),
                      "Solve-estimate-refine cycles; each starts from the "
                      "previous cycle's solution and active set.");
    prm.declare_entry("Strategy",
                      "kelly",
                      Patterns::Selection("global|kelly"),
                      "global: refine every cell; kelly: refine and coarsen "
                      "the cells with the largest/smallest Kelly error "
                      "indicators (quadrilaterals/hexahedra), or, on "
                      "triangles/tetrahedra from a .geo, remesh it with Gmsh "
                      "with cell sizes from the indicators (growing the "
                      "number of cells as the fractions would). A .geo on "
                      "simplices remeshes for global too, halving sizes.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0., 1.),
                      "kelly: fraction of the cells refined per cycle.");
    prm.declare_entry("Coarsen fraction",
                      "0.03",
                      Patterns::Double(0., 1.),
                      "kelly: fraction of the cells coarsened per cycle.");
    prm.leave_subsection();
  }

  void
  Refinement::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    n_cycles = prm.get_integer("Number of cycles");
    strategy =
      prm.get("Strategy") == "global" ? Strategy::global : Strategy::kelly;
    refine_fraction  = prm.get_double("Refine fraction");
    coarsen_fraction = prm.get_double("Coarsen fraction");
    prm.leave_subsection();
    if (refine_fraction + coarsen_fraction > 1.)
      throw InputError("Mesh refinement/Coarsen fraction",
                       "refine and coarsen fractions add up to more than 1");
  }
} // namespace signorini
