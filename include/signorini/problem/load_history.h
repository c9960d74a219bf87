#ifndef signorini_problem_load_history_h
#define signorini_problem_load_history_h

#include <deal.II/base/parameter_handler.h>

namespace signorini
{
  /**
   * A quasi-static load history: subsection `Load history`. The pseudo-time
   * t runs over `Steps` steps to `End time`, t_k = k End time / Steps for
   * k = 1 ... Steps; every load, prescribed displacement and obstacle
   * displacement may be an expression of t. With one step (the default)
   * the scene is solved once per cycle at t = End time.
   */
  struct LoadHistory
  {
    /** The number of load steps, at least 1. */
    unsigned int n_steps = 1;
    /** The pseudo-time of the last step [-], positive and finite. */
    double end_time = 1.;

    /** Whether the history has more than one step: each cycle then solves
     * every step, from t_1 on. */
    bool
    stepped() const
    {
      return n_steps > 1;
    }

    /** The pseudo-time of step @p step = 1 ... n_steps: step End time /
     * Steps, the last one End time exactly. */
    double
    time(const unsigned int step) const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Throws InputError for Steps below 1 and an End time that is not a
     * positive finite number. */
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
