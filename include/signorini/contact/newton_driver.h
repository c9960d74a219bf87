#ifndef signorini_contact_newton_driver_h
#define signorini_contact_newton_driver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/contact_formulation.h>
#include <signorini/contact/contact_law.h>
#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/elastic_operator.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * The semismooth Newton iteration of every contact formulation and law:
   * assemble and solve the Newton system of the current active set (the
   * formulation's SystemAdditions for the law's conditions), compute the
   * contact forces and the residual, update the nodes' states (the law's,
   * from the formulation's augmented pressures); until the states settle
   * and the residual is small, with cycle detection, stall detection and
   * the formulation's cycle breaking. It writes the displacement and the
   * contact pressure.
   */
  template <int dim>
  class NewtonDriver
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /** @p solution and @p pressure are the ghosted displacement [mm] and
     * nodal contact pressure [MPa] (at each contact node's scalar dof). */
    NewtonDriver(const Discretisation<dim>  &discretisation,
                 ElasticOperator<dim>       &elastic_operator,
                 ContactSurface<dim>        &surface,
                 const ContactLaw<dim>      &law,
                 ContactFormulation<dim>    &formulation,
                 const ContactParameters    &parameters,
                 const bool                  verbose,
                 VectorType                 &solution,
                 VectorType                 &pressure,
                 dealii::ConditionalOStream &pcout,
                 dealii::TimerOutput        &timer);

    /** The supports alone hold the body against every rigid motion: a
     * failed linear solve, a solution that is not a number or a stall then
     * asks @p material_question (if not empty; e.g. whether Poisson's ratio
     * is too near 0.5) rather than "is the body held against rigid
     * motion?", which they ask where contact must hold the body. */
    void
    supports_hold_body(const std::string &material_question);

    /** Sizes the residual for the current mesh. */
    void
    reinit();

    /** The displacement and the pressure were carried over from the previous
     * mesh: the next initialize_active_set() starts the stick and slip
     * zones from the shear tractions of that displacement. */
    void
    carry_over();

    /** Starts a cycle: no iterations yet. */
    void
    start_cycle();

    /** Starts a load step: the current displacement becomes each contact
     * node's reference, from which its slip in the step is counted (the
     * state of the previous step; zero on the first). */
    void
    start_step();

    /** Restores the obstacle's tangential traction @p traction (locally
     * owned, as tangential_traction() was after a load step) from a
     * checkpoint: the next step's active set and multipliers start from it.
     * Call after reinit(); nothing without friction. */
    void
    restore_tangential_traction(const VectorType &traction);

    /** Puts the nodes in contact that touch or penetrate, and sets the
     * others' states by the law, from the current displacement and
     * pressure. */
    void
    initialize_active_set();

    /** Newton iterations from the current active set until it settles
     * (Contact/Tolerance, Contact/Maximum iterations). Throws SolverFailure.
     */
    void
    iterate(const unsigned int cycle);

    /** One linear solve with the current active set and its contact forces
     * (Contact/Method = none). */
    void
    solve_once();

    /** The formulation's additions for the law's conditions of the
     * current states. */
    void
    assemble_newton_system();

    /** Solves the Newton system of the last assemble_newton_system() with
     * the elastic operator (which assembles or reuses its matrix). */
    void
    solve(const bool final_step);

    /** The Newton iterations of this cycle. */
    unsigned int
    iterations() const;

    /** The contact surface. */
    const ContactSurface<dim> &
    contact_surface() const;

    /** The contact pressure [MPa] at the contact nodes' scalar dofs. */
    const VectorType &
    pressure() const;

    /** The obstacle's tangential traction [MPa] on the body at the contact
     * nodes' dofs (a vector in each node's tangent plane), where the law
     * has friction; empty otherwise. */
    const VectorType &
    tangential_traction() const;

    /** K u - f with the contact dofs free: the obstacle's nodal force [N]. */
    const VectorType &
    residual() const;

    /** The smallest cell diameter of the mesh [mm]. */
    double
    minimal_cell_diameter() const;

    /** Whether each iteration is reported. */
    bool
    verbose_output() const;

    MPI_Comm
    mpi_communicator() const;

    /** The size of the active set and a hash of it, on every process. */
    std::pair<unsigned int, std::size_t>
    active_set_signature() const;

  private:
    /** The contact forces and pressure of the current displacement;
     * returns the norm of the nonlinear residual (force balance and
     * complementarity) relative to the load. */
    double
    evaluate_residual();

    /** The law's tractions of node @p i, @p node from the current
     * displacement and pressures: the formulation's augmented pressure
     * (for the state, with its touching tolerance and cycle breaking, or
     * for the residual) and, with friction, tangential traction. */
    NodeTraction<dim>
    traction(const unsigned int      i,
             const ContactNode<dim> &node,
             const bool              for_state) const;

    /** Sets the nodes' states by the law; returns the number of changes. */
    unsigned int
    update_active_set();

    /** After a solve without contact: the nodes where contact begins, those
     * that the displacement scaled by the smallest factor brings onto the
     * obstacle. Returns the number of changes. */
    unsigned int
    activate_first_contact();

    const Discretisation<dim> &discretisation;
    ElasticOperator<dim>      &elastic_operator;
    ContactSurface<dim>       &surface;
    const ContactLaw<dim>     &law;
    ContactFormulation<dim>   &formulation;
    const ContactParameters   &parameters;
    const bool                 verbose;
    VectorType                &solution;
    VectorType                &contact_pressure;
    VectorType                 contact_residual;
    /** See tangential_traction(); ghosted. */
    VectorType tangential_pressure;
    /** Whether tangential_pressure was restored (from a checkpoint, or
     * carried to a new mesh), so that initialize_active_set() starts from
     * it rather than from the nodal forces. */
    bool shear_carried = false;
    /** Systems that were not symmetric so far: each is assembled anew. */
    std::size_t nonsymmetric_systems = 0;
    /** See carry_over(). */
    bool carried_over = false;
    /** Each node's tractions of the last state update (for the law's
     * equations). */
    std::vector<NodeTraction<dim>> tractions;
    dealii::ConditionalOStream    &pcout;
    dealii::TimerOutput           &timer;
    SystemAdditions<dim>           additions;
    unsigned int                   newton_iterations = 0;
    /** See supports_hold_body(). */
    bool        supports_hold = false;
    std::string material_question;

    /** What a failed solve or a solution that is not a number asks. */
    std::string
    singular_question() const;
  };
} // namespace signorini

#endif
