#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/problem/load_history.h>

namespace signorini
{
  using namespace dealii;

  double
  LoadHistory::time(const unsigned int step) const
  {
    // The last step's time is End time itself (step * End time / Steps
    // can differ from it in the last bit): the history ends at the load of
    // a one-step run.
    return step >= n_steps ? end_time : step * end_time / n_steps;
  }

  void
  LoadHistory::declare_parameters(ParameterHandler &prm)
  {
    const LoadHistory defaults;
    prm.enter_subsection("Load history");
    prm.declare_entry(
      "Steps",
      entry_text::of(defaults.n_steps),
      Patterns::Integer(),
      "Quasi-static load steps, at least 1: step k = 1 ... Steps is solved "
      "at the pseudo-time t = k End time / Steps, each from the last one's "
      "displacement and contact set, and each mesh-refinement cycle replays "
      "all of them from zero (the last step's error indicators refine the "
      "mesh). Boundary conditions/Prescribed displacement, Traction, "
      "Traction resultant, Body force and each obstacle's Displacement may "
      "use t. With 1 step the scene is solved once per cycle, at t = End "
      "time.");
    prm.declare_entry(
      "End time",
      entry_text::of(defaults.end_time),
      Patterns::Anything(),
      "The pseudo-time t of the last load step [-], positive: a parameter "
      "of the loading, not a physical time (the problem is quasi-static and "
      "has no rate), e.g. 1 for a load ramped by t, 2 for a preload "
      "followed by a second load for t > 1.");
    prm.leave_subsection();
  }

  void
  LoadHistory::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load history");
    const double steps = prm.get_integer("Steps");
    const double time =
      parse::number(prm.get("End time"), "Load history/End time");
    prm.leave_subsection();
    n_steps = static_cast<unsigned int>(
      parse::in_range(steps, parse::Range::at_least(1.), "Load history/Steps"));
    end_time = parse::in_range(time,
                               parse::Range::positive(),
                               "Load history/End time",
                               "the pseudo-time of the last step");
  }
} // namespace signorini
