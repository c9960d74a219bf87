#include <signorini/base/failures.h>
#include <signorini/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::solve(const bool final_step)
  {
    TrilinosWrappers::MPI::Vector distributed(locally_owned_dofs,
                                              mpi_communicator);
    distributed = solution; // a warm start for the iterative solver
    constraints.set_zero(distributed);
    try
      {
        const auto &linear = parameters.linear_solver;
        linear_system_solver.solve(system_matrix,
                                   distributed,
                                   system_rhs,
                                   fe->n_components(),
                                   final_step ? linear.tolerance :
                                                linear.newton_tolerance);
      }
    catch (const SolverFailure &failure)
      {
        const auto method = parameters.contact.method;
        throw SolverFailure(
          failure.status,
          std::string(failure.what()) +
            " (is the body held against rigid motion?" +
            (method == ContactParameters::Method::penalty ||
                 method == ContactParameters::Method::augmented_lagrangian ?
               " is Contact/Penalty parameter too small?" :
               "") +
            ")");
      }
    constraints.distribute(distributed);
    solution = distributed;
  }

  std::string
  method_name(const ContactParameters::Method method)
  {
    return method == ContactParameters::Method::penalty ?
             "penalty" :
           method == ContactParameters::Method::augmented_lagrangian ?
             "augmented lagrangian" :
             "active set";
  }

  std::string
  number(const double x)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g", x);
    return text;
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_newton(const unsigned int cycle)
  {
    const auto &contact = parameters.contact;
    std::vector<std::pair<unsigned int, std::size_t>> visited = {
      active_set_signature()};
    double       previous_residual = 0.;
    unsigned int previous_changes  = 1;
    // Inexact Newton: the linear solves are loose while the active set
    // still changes, and tight once an update left it as it was.
    bool settled = contact.method == ContactParameters::Method::none;
    for (unsigned int iteration = 1; iteration <= contact.max_iterations;
         ++iteration)
      {
        const bool contact_free = visited.back().first == 0;
        assemble_newton_system();
        solve(settled);
        ++newton_iterations;
        const double       residual_norm = compute_contact_forces();
        const unsigned int changes =
          contact_free ? activate_first_contact() : update_active_set();
        const auto signature = active_set_signature();
        settled              = changes == 0;

        if (parameters.output.verbose)
          {
            char line[160];
            std::snprintf(line,
                          sizeof(line),
                          "   iteration %2u: residual %.3e, %u active, %u "
                          "changed",
                          iteration,
                          residual_norm,
                          signature.first,
                          changes);
            pcout << line << std::endl;
          }
        if (!std::isfinite(residual_norm))
          throw SolverFailure(exit_status::linear_solver,
                              "the solution is not a number on cycle " +
                                std::to_string(cycle) +
                                " (is the body held against rigid motion?)");
        if (changes == 0 && residual_norm < contact.tolerance)
          return;
        // With the active set unchanged, the next step solves the same linear
        // system again. A residual that did not fall since the last step
        // is the round-off floor of a fine mesh if it is near the tolerance,
        // and a failure if it is not.
        if (changes == 0 && previous_changes == 0 &&
            residual_norm > 0.5 * previous_residual)
          {
            if (residual_norm < 100. * contact.tolerance)
              return;
            throw SolverFailure(
              exit_status::contact_stalled,
              "contact solver (" + method_name(contact.method) +
                ") stalled on cycle " + std::to_string(cycle) +
                " at residual " + number(residual_norm) +
                " with an unchanged active set (" +
                (contact.method == ContactParameters::Method::penalty ?
                   "the round-off of a stiff penalty: is Contact/Penalty "
                   "parameter too small? " :
                   "") +
                "is the body held against rigid motion? is Linear "
                "solver/Tolerance too loose?)");
          }
        previous_residual = residual_norm;
        previous_changes  = changes;
        if (changes > 0 &&
            std::find(visited.begin(), visited.end(), signature) !=
              visited.end() &&
            contact.method != ContactParameters::Method::augmented_lagrangian &&
            contact.remedies && !sign_rule)
          {
            // Cycle breaking. Active set: the rule pressure - c x gap > 0
            // with a c that lets round-off decide (too small: the noise of
            // the pressure; too large: the touching tolerance) gives way to
            // the signs alone. Penalty: a node whose penetration epsilon x
            // pressure is below the touching tolerance flips on every step;
            // it is penetrating if its gap is negative at all.
            sign_rule = true;
            pcout << "   remedy: the active set returned to an earlier one on "
                     "iteration "
                  << iteration << "; cycle broken by "
                  << (contact.method == ContactParameters::Method::penalty ?
                        "counting every negative gap as penetrating" :
                        "the c-free update (release where the pressure is "
                        "negative, add where the gap is)")
                  << std::endl;
            update_active_set();
            visited = {active_set_signature()};
            continue;
          }
        if (changes > 0 &&
            std::find(visited.begin(), visited.end(), signature) !=
              visited.end())
          throw SolverFailure(exit_status::active_set_cycling,
                              "contact solver (" + method_name(contact.method) +
                                (sign_rule ? ", cycle breaking applied" : "") +
                                ") is cycling on cycle " +
                                std::to_string(cycle) + ": iteration " +
                                std::to_string(iteration) +
                                " returned to an earlier active set of " +
                                std::to_string(signature.first) + " nodes");
        visited.push_back(signature);
      }
    throw SolverFailure(exit_status::contact_no_converge,
                        "contact solver (" + method_name(contact.method) +
                          ") did not converge in " +
                          std::to_string(contact.max_iterations) +
                          " iterations on cycle " + std::to_string(cycle) +
                          " (Contact/Maximum iterations)");
  }

  template void
  ContactProblem<2>::solve(bool);
  template void
  ContactProblem<3>::solve(bool);
  template void
  ContactProblem<2>::solve_newton(unsigned int);
  template void
  ContactProblem<3>::solve_newton(unsigned int);
} // namespace signorini
