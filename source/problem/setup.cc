#include <signorini/contact/newton_driver.h>
#include <signorini/elasticity/elastic_operator.h>
#include <signorini/mesh_adaptation/mesh_adaptation_factory.h>
#include <signorini/problem/contact_problem.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters<dim> &parameters,
                                      const MPI_Comm         mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , timer(mpi_communicator,
            pcout,
            parameters.output.print_timings ? TimerOutput::summary :
                                              TimerOutput::never,
            TimerOutput::wall_times)
    , discretisation(parameters.geometry,
                     mesh_adaptation_factory(parameters.geometry,
                                             parameters.refinement,
                                             mpi_communicator),
                     parameters.boundary_conditions,
                     mpi_communicator,
                     parameters.material.axisymmetric())
    , loads(parameters.boundary_conditions, discretisation)
    , elastic_operator(create_elastic_operator(discretisation,
                                               parameters.material,
                                               parameters.boundary_conditions,
                                               loads,
                                               parameters.linear_solver,
                                               parameters.contact.remedies,
                                               parameters.output.verbose,
                                               pcout,
                                               timer))
    , obstacle(create_obstacles(parameters.obstacle))
    , contact_surface(parameters.obstacle.contact_ids,
                      *obstacle,
                      parameters.contact.acts())
    , law(create_contact_law<dim>(parameters.contact,
                                  parameters.friction,
                                  parameters.obstacle))
    , formulation(
        create_contact_formulation<dim>(parameters.contact,
                                        parameters.material.young_modulus,
                                        pcout))
    , newton(discretisation,
             *elastic_operator,
             contact_surface,
             *law,
             *formulation,
             parameters.contact,
             parameters.output.verbose,
             solution,
             pressure,
             pcout,
             timer)
  {
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(timer, "Setup: system");
    const auto        &owned_dofs    = discretisation.locally_owned_dofs();
    const auto        &relevant_dofs = discretisation.locally_relevant_dofs();
    elastic_operator->reinit();
    solution.reinit(owned_dofs, relevant_dofs, mpi_communicator);
    // The pressure shares the displacement's Epetra map: a map of ghosted
    // entries holds a global-to-local table and a directory, 20 to 30
    // bytes per relevant dof, which one made from the index sets again
    // would hold twice.
    pressure.clear();
    pressure.reinit(solution);
    newton.reinit();
    contact_surface.setup(discretisation);
  }

  template ContactProblem<2>::ContactProblem(const Parameters<2> &, MPI_Comm);
  template ContactProblem<3>::ContactProblem(const Parameters<3> &, MPI_Comm);
  template void
  ContactProblem<2>::setup_system();
  template void
  ContactProblem<3>::setup_system();
} // namespace signorini
