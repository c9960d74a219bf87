#include <deal.II/base/mpi.h>

#include <signorini/base/failures.h>
#include <signorini/base/interruption.h>
#include <signorini/base/text.h>
#include <signorini/contact/newton_driver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** " (QUESTIONS)" for a failure's message, nothing for none. */
    std::string
    questions(const std::string &text)
    {
      const auto first = text.find_first_not_of(' ');
      return first == std::string::npos ? "" : " (" + text.substr(first) + ")";
    }
  } // namespace

  template <int dim>
  NewtonDriver<dim>::NewtonDriver(const Discretisation<dim> &discretisation,
                                  ElasticOperator<dim>      &elastic_operator,
                                  ContactSurface<dim>       &surface,
                                  const ContactLaw<dim>     &law,
                                  ContactFormulation<dim>   &formulation,
                                  const ContactParameters   &parameters,
                                  const bool                 verbose,
                                  VectorType                &solution,
                                  VectorType                &pressure,
                                  ConditionalOStream        &pcout,
                                  TimerOutput               &timer)
    : discretisation(discretisation)
    , elastic_operator(elastic_operator)
    , surface(surface)
    , law(law)
    , formulation(formulation)
    , parameters(parameters)
    , verbose(verbose)
    , solution(solution)
    , contact_pressure(pressure)
    , pcout(pcout)
    , timer(timer)
  {
  }

  template <int dim>
  void
  NewtonDriver<dim>::supports_hold_body(const std::string &question)
  {
    supports_hold     = true;
    material_question = question;
  }

  template <int dim>
  std::string
  NewtonDriver<dim>::singular_question() const
  {
    // Where the supports hold the body, the solver's own message stands,
    // with the material's question if there is one.
    if (!supports_hold)
      {
        // Held along the obstacle by friction alone, a body whose every
        // node in contact slips has nothing to hold it there.
        if (law.path_dependent())
          {
            unsigned int stick = 0, slip = 0;
            for (const auto &node : surface.nodes())
              if (node.owned)
                {
                  stick += node.state == NodeState::stick ? 1 : 0;
                  slip += node.state == NodeState::slip ? 1 : 0;
                }
            const MPI_Comm comm = discretisation.mpi_communicator();
            if (Utilities::MPI::sum(slip, comm) > 0 &&
                Utilities::MPI::sum(stick, comm) == 0)
              return "every node in contact slips, and nothing else holds "
                     "the body along the obstacle: is the tangential load "
                     "above the friction bound (mu times the normal force)?";
          }
        return "is the body held against rigid motion?";
      }
    return material_question.empty() ?
             std::string() :
             "the supports hold the body against every rigid motion: " +
               material_question;
  }

  template <int dim>
  void
  NewtonDriver<dim>::reinit()
  {
    contact_residual.reinit(discretisation.locally_owned_dofs(),
                            discretisation.mpi_communicator());
    if (law.path_dependent())
      tangential_pressure.reinit(solution);
    else
      tangential_pressure.clear();
  }

  template <int dim>
  void
  NewtonDriver<dim>::carry_over()
  {
    carried_over = true;
  }

  template <int dim>
  void
  NewtonDriver<dim>::start_cycle()
  {
    newton_iterations = 0;
  }

  template <int dim>
  void
  NewtonDriver<dim>::start_step()
  {
    if (law.path_dependent())
      for (auto &node : surface.nodes())
        node.reference = node.displacement(solution);
  }

  template <int dim>
  void
  NewtonDriver<dim>::restore_tangential_traction(const VectorType &traction)
  {
    if (law.path_dependent())
      {
        tangential_pressure = traction;
        shear_carried       = true;
      }
  }

  template <int dim>
  NodeTraction<dim>
  NewtonDriver<dim>::traction(const unsigned int      i,
                              const ContactNode<dim> &node,
                              const bool              for_state) const
  {
    NodeTraction<dim> traction;
    const double      gap      = surface.deformed_gap(node, solution);
    const double      pressure = contact_pressure(node.scalar_dof);
    traction.pressure          = pressure;
    traction.bound_sigma =
      formulation.residual_pressure(i, node, gap, pressure);
    traction.sigma = for_state ?
                       formulation.state_pressure(i, node, gap, pressure) :
                       traction.bound_sigma;
    if (law.path_dependent())
      {
        Tensor<1, dim> q;
        for (unsigned int d = 0; d < dim; ++d)
          q[d] = tangential_pressure(node.dofs[d]);
        traction.shear        = q;
        traction.slip         = node.slip(solution);
        traction.stiffness    = formulation.tangential_stiffness(i);
        traction.shear_weight = formulation.shear_weight();
        traction.tangential =
          formulation.tangential_traction(i, node, traction.slip, q);
      }
    return traction;
  }

  template <int dim>
  void
  NewtonDriver<dim>::initialize_active_set()
  {
    // From the previous cycle's displacement and pressure (zero on cycle 0),
    // with the touching and penetrating nodes in contact from the start, so
    // that a body held only by the obstacle is supported in the first
    // solve.
    // With friction, on a mesh that carried the last one's displacement
    // over, each node's shear traction is the last mesh's carried over, or
    // else from the nodal forces K u - f, so that the stick and slip zones
    // start where the last mesh left them. (Not where a load history
    // starts again from zero.)
    if (law.path_dependent() && carried_over && !shear_carried &&
        contact_pressure.linfty_norm() > 0.)
      evaluate_residual();
    shear_carried = false;
    carried_over  = false;
    auto &nodes   = surface.nodes();
    tractions.resize(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const double gap = surface.deformed_gap(nodes[i], solution);
        tractions[i]     = traction(i, nodes[i], true);
        const auto state = law.state(nodes[i], tractions[i]);
        nodes[i].state =
          state == NodeState::open && gap <= surface.touching_tolerance() ?
            law.contact_state() :
            state;
      }
  }

  template <int dim>
  unsigned int
  NewtonDriver<dim>::update_active_set()
  {
    TimerOutput::Scope t(timer, "Active set: update");
    unsigned int       changes = 0;
    auto              &nodes   = surface.nodes();
    tractions.resize(nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const auto previous = tractions[i].tangential;
        tractions[i]        = traction(i, nodes[i], true);
        auto state          = law.state(nodes[i], tractions[i]);
        // A slip whose augmented shear turned against the one it was
        // linearised with passes through stick: where zeta does not hold
        // the obstacle's traction (a penalty's, an augmented Lagrangian's
        // -s / epsilon), a node at its bound otherwise slides to and fro
        // (the Cattaneo-Mindlin disk by the augmented Lagrangian stalled).
        if (state == NodeState::slip && nodes[i].state == NodeState::slip &&
            tractions[i].shear_weight == 0. &&
            previous * tractions[i].tangential < 0.)
          state = NodeState::stick;
        if (nodes[i].owned && state != nodes[i].state)
          ++changes;
        nodes[i].state = state;
      }
    return Utilities::MPI::sum(changes, discretisation.mpi_communicator());
  }

  template <int dim>
  unsigned int
  NewtonDriver<dim>::activate_first_contact()
  {
    // After a solve with no contact at all, the displacement is proportional
    // to the load: scaled by theta_i = gap_i / (-u_i.n_i), node i just
    // touches. The nodes with the smallest theta are where contact begins;
    // starting from them, rather than from every penetrating node, spares
    // the iteration from releasing the wrongly active ones one by one.
    const MPI_Comm comm      = discretisation.mpi_communicator();
    double         theta_min = std::numeric_limits<double>::max();
    for (const auto &node : surface.nodes())
      {
        const double u = node.normal_displacement(solution);
        if (u < 0)
          theta_min = std::min(theta_min, node.gap / -u);
      }
    theta_min = Utilities::MPI::min(theta_min, comm);
    if (theta_min >= 1.)
      return 0; // nothing penetrates: the contact-free solution stands

    unsigned int changes = 0;
    for (auto &node : surface.nodes())
      {
        const double u = node.normal_displacement(solution);
        node.state     = u < 0 && node.gap / -u <= theta_min * (1. + 1e-6) ?
                           law.contact_state() :
                           NodeState::open;
        changes += node.owned && node.in_contact() ? 1 : 0;
      }
    return Utilities::MPI::sum(changes, comm);
  }

  template <int dim>
  double
  NewtonDriver<dim>::evaluate_residual()
  {
    TimerOutput::Scope t(timer, "Active set: contact forces");
    elastic_operator.residual(solution, contact_residual);

    // The residual K u - f at a contact node, on its free components, is
    // the obstacle's nodal force lambda_i n_i (at a corner, the sum of its
    // nodes' forces); the pressure is lambda_i / m_i. The nonlinear residual
    // combines the force balance at all other free dofs with the
    // complementarity function at the contact nodes (the law's, of the
    // formulation's augmented pressure).
    // With friction, the tangential part of the nodal force at a node
    // whose law binds it is the obstacle's too, and complementarity of the
    // law's tangential force replaces its balance.
    const MPI_Comm comm = discretisation.mpi_communicator();
    VectorType     owned_pressure(discretisation.locally_owned_dofs(), comm);
    VectorType     owned_tangential;
    const bool     friction = law.path_dependent();
    if (friction)
      owned_tangential.reinit(discretisation.locally_owned_dofs(), comm);
    VectorType  balance(contact_residual);
    double      complementarity = 0., contact_force = 0.;
    const auto &nodes  = surface.nodes();
    const auto  lambda = surface.normal_forces(contact_residual);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].owned)
        {
          const auto  &node = nodes[i];
          const double p    = node.mass > 0 ? lambda[i] / node.mass : 0.;
          owned_pressure(node.scalar_dof) = p;
          Tensor<1, dim> force;
          for (unsigned int d = 0; d < dim; ++d)
            if (node.free[d])
              force[d] = contact_residual(node.dofs[d]);
          const Tensor<1, dim> tangential =
            friction ? node.tangential(force) : Tensor<1, dim>();
          if (friction && node.mass > 0)
            for (unsigned int d = 0; d < dim; ++d)
              if (node.free[d])
                owned_tangential(node.dofs[d]) = tangential[d] / node.mass;
        }
    owned_pressure.compress(VectorOperation::insert);
    contact_pressure = owned_pressure;
    if (friction)
      {
        owned_tangential.compress(VectorOperation::insert);
        tangential_pressure = owned_tangential;
      }
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].owned)
        {
          const auto  &node          = nodes[i];
          const auto   node_traction = traction(i, node, false);
          const double expected =
            law.complementarity_force(node, node_traction);
          // The force balance along the obstacle's surface remains, unless
          // the law binds the tangential force.
          const auto expected_tangential =
            law.tangential_force(node, node_traction);
          Tensor<1, dim> tangential;
          if (expected_tangential)
            for (unsigned int d = 0; d < dim; ++d)
              tangential[d] = tangential_pressure(node.dofs[d]) * node.mass;
          for (unsigned int d = 0; d < dim; ++d)
            if (node.free[d])
              balance(node.dofs[d]) = balance(node.dofs[d]) -
                                      lambda[i] * node.normal[d] -
                                      tangential[d];
          complementarity += (lambda[i] - expected) * (lambda[i] - expected);
          contact_force += lambda[i] * lambda[i];
          if (expected_tangential)
            {
              complementarity +=
                (tangential - *expected_tangential).norm_square();
              contact_force += tangential.norm_square();
            }
        }
    balance.compress(VectorOperation::insert);

    const double balance_norm = balance.l2_norm();
    complementarity           = Utilities::MPI::sum(complementarity, comm);
    contact_force             = Utilities::MPI::sum(contact_force, comm);
    const double scale =
      elastic_operator.load().l2_norm() + std::sqrt(contact_force);
    return std::sqrt(balance_norm * balance_norm + complementarity) /
           (scale > 0 ? scale : 1.);
  }

  template <int dim>
  void
  NewtonDriver<dim>::assemble_newton_system()
  {
    additions = SystemAdditions<dim>();
    tractions.resize(surface.nodes().size());
    formulation.linearise(surface, law, tractions, additions);
    // A slipping node's rows change with its slip direction, which the
    // active set's signature does not hold: a system that is not
    // symmetric is never reused.
    if (!additions.symmetric)
      additions.key.first.second += ++nonsymmetric_systems;
  }

  template <int dim>
  void
  NewtonDriver<dim>::solve(const bool final_step)
  {
    try
      {
        elastic_operator.solve(additions, solution, final_step);
      }
    catch (const SolverFailure &failure)
      {
        throw SolverFailure(failure.status,
                            std::string(failure.what()) +
                              questions(singular_question() +
                                        formulation.failure_hint()));
      }
  }

  template <int dim>
  void
  NewtonDriver<dim>::solve_once()
  {
    assemble_newton_system();
    solve(true);
    evaluate_residual();
    newton_iterations = 1;
  }

  template <int dim>
  void
  NewtonDriver<dim>::iterate(const unsigned int cycle)
  {
    std::vector<std::pair<unsigned int, std::size_t>> visited = {
      surface.active_set_signature()};
    double       previous_residual = 0.;
    unsigned int previous_changes  = 1;
    // Inexact Newton: the linear solves are loose while the active set
    // still changes, and tight once an update left it as it was.
    bool settled = false;
    bool tight   = false;
    for (unsigned int iteration = 1; iteration <= parameters.max_iterations;
         ++iteration)
      {
        interruption::check(discretisation.mpi_communicator());
        const bool contact_free = visited.back().first == 0;
        assemble_newton_system();
        // With friction too the solves are loose while the states change
        // (tight ones each time made a 3D frictional cycle cost 2.1 to 2.8
        // frictionless ones, loose ones 1.0 to 1.9), until the states
        // return to earlier ones: a loose solve can move the shear of a
        // node near the stick zone's edge across its bound and back (a
        // nearly incompressible Cattaneo-Mindlin disk on 2 processes).
        solve(settled || tight);
        ++newton_iterations;
        const double       residual_norm = evaluate_residual();
        const unsigned int changes =
          contact_free ? activate_first_contact() : update_active_set();
        const auto signature = surface.active_set_signature();
        settled              = changes == 0;

        if (verbose)
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
                                questions(singular_question()));
        if (changes == 0 && residual_norm < parameters.tolerance)
          return;
        // With the active set unchanged, the next step solves the same linear
        // system again. A residual that did not fall since the last step
        // is the round-off floor of a fine mesh if it is near the tolerance,
        // and a failure if it is not.
        if (changes == 0 && previous_changes == 0 &&
            residual_norm > 0.5 * previous_residual)
          {
            if (residual_norm < 100. * parameters.tolerance)
              return;
            throw SolverFailure(
              exit_status::contact_stalled,
              "contact solver (" + formulation.name() + ") stalled on cycle " +
                std::to_string(cycle) + " at residual " +
                number(residual_norm) + " with an unchanged active set (" +
                formulation.stall_hint() +
                (singular_question().empty() ? std::string() :
                                               singular_question() + " ") +
                "is Linear "
                "solver/Tolerance too loose?)");
          }
        previous_residual = residual_norm;
        previous_changes  = changes;
        const bool returned =
          changes > 0 &&
          std::find(visited.begin(), visited.end(), signature) != visited.end();
        if (returned && law.path_dependent() && !tight)
          {
            // Friction's states came back: solve tightly from now on.
            tight   = true;
            visited = {signature};
            continue;
          }
        if (returned && parameters.remedies)
          {
            const std::string remedy = formulation.break_cycle();
            if (!remedy.empty())
              {
                pcout << "   remedy: the active set returned to an earlier "
                         "one on iteration "
                      << iteration << "; cycle broken by " << remedy
                      << std::endl;
                update_active_set();
                visited = {surface.active_set_signature()};
                continue;
              }
          }
        if (returned)
          throw SolverFailure(
            exit_status::active_set_cycling,
            "contact solver (" + formulation.name() +
              (formulation.cycle_broken() ? ", cycle breaking applied" : "") +
              ") is cycling on cycle " + std::to_string(cycle) +
              ": iteration " + std::to_string(iteration) +
              " returned to an earlier active set of " +
              std::to_string(signature.first) + " nodes");
        visited.push_back(signature);
      }
    throw SolverFailure(exit_status::contact_no_converge,
                        "contact solver (" + formulation.name() +
                          ") did not converge in " +
                          std::to_string(parameters.max_iterations) +
                          " iterations on cycle " + std::to_string(cycle) +
                          " (Contact/Maximum iterations)");
  }

  template <int dim>
  unsigned int
  NewtonDriver<dim>::iterations() const
  {
    return newton_iterations;
  }

  template <int dim>
  const ContactSurface<dim> &
  NewtonDriver<dim>::contact_surface() const
  {
    return surface;
  }

  template <int dim>
  const typename NewtonDriver<dim>::VectorType &
  NewtonDriver<dim>::pressure() const
  {
    return contact_pressure;
  }

  template <int dim>
  const typename NewtonDriver<dim>::VectorType &
  NewtonDriver<dim>::tangential_traction() const
  {
    return tangential_pressure;
  }

  template <int dim>
  const typename NewtonDriver<dim>::VectorType &
  NewtonDriver<dim>::residual() const
  {
    return contact_residual;
  }

  template <int dim>
  double
  NewtonDriver<dim>::minimal_cell_diameter() const
  {
    return discretisation.minimal_cell_diameter();
  }

  template <int dim>
  std::pair<unsigned int, std::size_t>
  NewtonDriver<dim>::active_set_signature() const
  {
    return surface.active_set_signature();
  }

  template <int dim>
  bool
  NewtonDriver<dim>::verbose_output() const
  {
    return verbose;
  }

  template <int dim>
  MPI_Comm
  NewtonDriver<dim>::mpi_communicator() const
  {
    return discretisation.mpi_communicator();
  }

  template class NewtonDriver<2>;
  template class NewtonDriver<3>;
} // namespace signorini
