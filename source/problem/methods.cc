#include <deal.II/grid/grid_tools.h>

#include <signorini/base/failures.h>
#include <signorini/problem/contact_problem.h>

#include <algorithm>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::solve_contact_problem(const unsigned int cycle)
  {
    assemble_load();
    const auto &contact = parameters.contact;
    newton_iterations   = 0;
    multiplier_updates  = 0;
    sign_rule           = false;
    if (contact.method == ContactParameters::Method::none)
      {
        for (auto &node : contact_nodes)
          node.active = false;
        assemble_newton_system();
        solve(true);
        compute_contact_forces();
        newton_iterations = 1;
        return;
      }

    // Automatic: r = epsilon E / h_min = 0.1, a penalty ten times as stiff
    // as the finest cell.
    penalty_parameter = contact.penalty_parameter > 0 ?
                          contact.penalty_parameter :
                          0.1 *
                            GridTools::minimal_cell_diameter(*triangulation) /
                            parameters.material.young_modulus;
    if (contact.method == ContactParameters::Method::penalty)
      solve_penalty(cycle);
    else if (contact.method == ContactParameters::Method::augmented_lagrangian)
      solve_augmented_lagrangian(cycle);
    else
      {
        initialize_active_set();
        solve_newton(cycle);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_penalty(const unsigned int cycle)
  {
    initialize_active_set();
    if (!parameters.contact.remedies)
      {
        solve_newton(cycle);
        return;
      }
    try
      {
        solve_newton(cycle);
        return;
      }
    catch (const SolverFailure &failure)
      {
        if (failure.status != exit_status::active_set_cycling &&
            failure.status != exit_status::contact_stalled &&
            failure.status != exit_status::contact_no_converge)
          throw;
        // Penalty continuation: from a 1000 times softer penalty, whose
        // Newton iteration settles easily, down to the asked one by factors
        // of 10, each stage starting from the one before (for a cycling set,
        // after the cycle breaking of solve_newton() failed).
        const double target = penalty_parameter;
        pcout << "   remedy: " << failure.what()
              << "; penalty continuation from epsilon = "
              << number(1000. * target) << " down to " << number(target)
              << std::endl;
        for (double epsilon = 1000. * target;; epsilon /= 10.)
          {
            penalty_parameter = std::max(epsilon, target);
            initialize_active_set();
            try
              {
                solve_newton(cycle);
              }
            catch (const SolverFailure &again)
              {
                throw SolverFailure(again.status,
                                    std::string(again.what()) +
                                      "; penalty continuation did not help "
                                      "(failed at epsilon = " +
                                      number(penalty_parameter) + ")");
              }
            if (penalty_parameter <= target)
              return;
          }
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_augmented_lagrangian(const unsigned int cycle)
  {
    const auto &contact = parameters.contact;
    // The multipliers start from the previous cycle's pressure (zero on
    // cycle 0).
    for (auto &node : contact_nodes)
      if (node.owned)
        node.multiplier =
          std::max(0., static_cast<double>(pressure(node.dofs[dim - 1])));
    initialize_active_set();
    double previous_change = 0.;
    for (;;)
      {
        solve_newton(cycle);
        const double change = update_multipliers();
        ++multiplier_updates;
        if (parameters.output.verbose)
          pcout << "   multiplier update " << multiplier_updates
                << ": relative change " << number(change) << std::endl;
        if (change <= contact.multiplier_tolerance)
          return;
        if (multiplier_updates >= contact.max_updates)
          throw SolverFailure(
            exit_status::multipliers_slow,
            "contact solver (augmented lagrangian): the multipliers still "
            "change by " +
              number(change) + " after " + std::to_string(multiplier_updates) +
              " updates on cycle " + std::to_string(cycle) +
              " (Contact/Maximum updates; a smaller Contact/Penalty "
              "parameter converges faster)");
        // The multipliers converge by about r / (1 + r) per update, r =
        // epsilon E / h: if they shrink by less than half, the penalty is too
        // soft for this mesh. Stiffen it tenfold (one more factorisation).
        const double rate = previous_change > 0 ? change / previous_change : 0;
        previous_change   = change;
        if (contact.remedies && rate > 0.5)
          {
            penalty_parameter /= 10.;
            previous_change = 0.;
            pcout << "   remedy: the multipliers change by a factor of "
                  << number(rate) << " per update on update "
                  << multiplier_updates << "; penalty stiffened to epsilon = "
                  << number(penalty_parameter) << std::endl;
          }
      }
  }

  template void
  ContactProblem<2>::solve_contact_problem(unsigned int);
  template void
  ContactProblem<3>::solve_contact_problem(unsigned int);
  template void
  ContactProblem<2>::solve_penalty(unsigned int);
  template void
  ContactProblem<3>::solve_penalty(unsigned int);
  template void
  ContactProblem<2>::solve_augmented_lagrangian(unsigned int);
  template void
  ContactProblem<3>::solve_augmented_lagrangian(unsigned int);
} // namespace signorini
