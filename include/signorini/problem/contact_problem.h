#ifndef signorini_problem_contact_problem_h
#define signorini_problem_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <signorini/elasticity/cell_stiffness.h>
#include <signorini/elasticity/linear_system_solver.h>
#include <signorini/input/parameters.h>
#include <signorini/output/background_writer.h>
#include <signorini/output/checkpoint.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace signorini
{
  template <int dim>
  class MeshAdaptation;

  /**
   * A vertex of the candidate contact boundary whose vertical displacement is
   * free (not fixed by a Dirichlet condition or a hanging node).
   */
  template <int dim>
  struct ContactNode
  {
    /** Displacement dofs; the last is the vertical (normal) one. */
    std::array<dealii::types::global_dof_index, dim> dofs;
    /** Where the node is [mm]. */
    dealii::Point<dim> position;
    /** Initial gap to the obstacle [mm]. */
    double gap;
    /** Lumped contact-boundary mass, integral of the shape function over
     * the contact boundary [mm^(dim-1)]; set on owned nodes only. */
    double mass = 0.;
    bool   owned;
    /** In the active set (active set method), or penetrating (penalty). */
    bool active = false;
    /** Augmented Lagrangian multiplier, the contact pressure the penalty
     * acts around [MPa]; set on owned nodes only. */
    double multiplier = 0.;
  };

  /** The results of one cycle, one row of statistics.csv. */
  template <int dim>
  struct CycleStatistics
  {
    unsigned int                    cycle;
    unsigned int                    cells;
    dealii::types::global_dof_index dofs;
    unsigned int                    iterations;
    /** Augmented Lagrangian multiplier updates. */
    unsigned int multiplier_updates = 0;
    /** Active set cycle breaking: update by the signs of pressure and gap
     * alone, for the rest of the cycle. */
    bool sign_rule = false;
    /** The penalty parameter epsilon in use at the end [mm/MPa]. */
    double                 penalty_parameter = 0.;
    unsigned int           active_nodes;
    dealii::Tensor<1, dim> contact_force;
    double                 max_penetration;
    double                 estimated_error;
    /** Largest nodal contact pressure [MPa]. */
    double max_pressure = 0.;
    /** Extent along x of the contact nodes [mm]. */
    double contact_width = 0.;
    /** The loads' resultant, the integral of traction and body force [N]. */
    dealii::Tensor<1, dim> applied_force;
    /** Resultant of the reactions at the Dirichlet supports [N]. */
    dealii::Tensor<1, dim> support_reaction;
    /** Integral of the contact pressure over the contact boundary [N]. */
    double integrated_pressure = 0.;
    /** |applied + support reaction + integrated pressure (upwards)| over
     * |applied|: zero for a body in equilibrium. */
    double equilibrium_error = 0.;
    /** Potential energy 1/2 a(u,u) - f(u) [N mm]. */
    double energy = 0.;
    /** Relative errors of max_pressure and contact_width against the
     * Reference (NaN if none). */
    double max_pressure_error  = 0.;
    double contact_width_error = 0.;
    /** Relative energy-norm error against Reference/Energy (NaN if none). */
    double energy_error = 0.;
    /** Relative L2 error of the pressure against Reference/Contact pressure
     * (NaN if none). */
    double                              pressure_error = 0.;
    std::vector<dealii::Tensor<1, dim>> probes;
  };

  /** "active set", "penalty" or "augmented lagrangian", for messages. */
  std::string
  method_name(const ContactParameters::Method method);
  /** @p x with three significant digits. */
  std::string
  number(const double x);

  /** The costs of one cycle, one row of timings.csv. */
  struct CycleTimings
  {
    unsigned int cycle;
    /** Wall time of the contact solve [s]. */
    double contact_solve = 0.;
    /** Wall time of one linear elasticity solve on the same mesh [s]. */
    double linear_solve = 0.;
    /** Wall time since the start, without output and linear_solve [s]. */
    double run_time = 0.;
    /** Peak resident memory, summed over the processes [MB]. */
    double peak_memory = 0.;
  };

  /**
   * The Signorini problem: a linear elastic body, loads and supports, and a
   * rigid obstacle, solved in adaptive cycles. The verbs are those of
   * step-41/42: make_grid, setup_system, assemble_newton_system, solve,
   * update_active_set, refine_grid, output_results, run. The class is split
   * over source/contact_problem/ by concern.
   */
  template <int dim>
  class ContactProblem
  {
  public:
    /** @p parameter_text is the complete parameter set, written to
     * parameters.prm. */
    ContactProblem(const Parameters<dim> &parameters,
                   const std::string     &parameter_text,
                   const MPI_Comm         mpi_communicator);
    ~ContactProblem();

    /** All cycles; throws SolverFailure or InputError. With @p resume,
     * continues after the cycle of the newest checkpoint in the output
     * directory (from cycle 0 if there is none). */
    void
    run(const bool resume = false);


  private:
    // run.cc
    void
    run_cycles(const bool resume);

    // checkpoint.cc
    /** Takes over the output directory (removing what an earlier run left
     * that this run does not continue), writes the obstacle and the
     * parameters, and on @p resume restores the newest checkpoint, adding
     * its run time to @p run_time. Returns the first cycle to compute. */
    unsigned int
    start_output(const bool resume, double &run_time);
    /** Writes the checkpoint of cycle @p cycle (Output/Checkpoint). */
    void
    save_checkpoint(const unsigned int cycle, const double run_time);

    // setup.cc
    void
    make_grid();
    void
    check_boundary_ids(
      const std::vector<dealii::types::boundary_id> &mesh_ids) const;
    void
    setup_system();
    void
    setup_contact_nodes();

    // assembly.cc
    void
    assemble_newton_system();
    void
    assemble_load();
    /** The stiffness matrix with the current constraints (and the penalty
     * for @p penalty_method), and its right-hand side. */
    void
    assemble_matrix(const bool penalty_method);
    void
    assemble_residual();
    /** The internal force vector of one cell, the integral of
     * eps(phi_i) : sigma(u) over the cell @p fe_values was reinit'ed on
     * [N]; returns the cell's strain energy 1/2 a(u,u) [N mm]. */
    double
    assemble_cell_internal_force(const dealii::FEValues<dim> &fe_values,
                                 dealii::Vector<double>      &internal) const;
    /** The load vector of one cell: body force and traction [N]. */
    void
    assemble_cell_load(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      dealii::FEValues<dim>                                        &fe_values,
      dealii::FEFaceValues<dim> &fe_face_values,
      dealii::Vector<double>    &cell_load) const;

    // active_set.cc
    double
    deformed_gap(const ContactNode<dim> &node) const;
    bool
    update_rule(const ContactNode<dim> &node) const;
    void
    initialize_active_set();
    unsigned int
    activate_first_contact();
    double
    compute_contact_forces();
    unsigned int
    update_active_set();
    std::pair<unsigned int, std::size_t>
    active_set_signature() const;

    // solve.cc
    /** One linear solve of the Newton system; iterative solvers stop at
     * Linear solver/Tolerance on the @p final_step of an iteration, at the
     * looser Newton tolerance while the active set may still change. */
    void
    solve(const bool final_step);

    // methods.cc
    /** One cycle's contact problem by the chosen method, with its remedies. */
    void
    solve_contact_problem(const unsigned int cycle);
    void
    solve_penalty(const unsigned int cycle);
    void
    solve_augmented_lagrangian(const unsigned int cycle);
    /** Semismooth Newton iterations until the active set settles; for the
     * augmented Lagrangian method, with the multipliers fixed. */
    void
    solve_newton(const unsigned int cycle);
    /** Augmented Lagrangian: sets the multipliers to the current pressure;
     * returns the largest change relative to the largest pressure. */
    double
    update_multipliers();

    // refinement.cc
    void
    estimate_error();
    void
    refine_grid();

    // postprocessing.cc
    void
    evaluate_contact_zone(CycleStatistics<dim> &row) const;
    void
    evaluate_balance_and_energy(CycleStatistics<dim> &row) const;
    void
    write_contact_pressure_table(const unsigned int cycle) const;

    // benchmark.cc
    /** Wall time of assembling and solving the Newton system of the
     * converged active set anew, with the same linear solver [s]: one linear
     * elasticity solve on this mesh. Leaves the solution as it was. */
    double
    time_linear_solve();
    /** Adds this cycle's row to timings.csv. */
    void
    write_timings(const CycleTimings &row);

    // output.cc
    void
    write_obstacle_and_parameters() const;
    /** The displacement at @p point, if a locally owned cell holds it. */
    bool
    evaluate_displacement(const dealii::Point<dim> &point,
                          dealii::Tensor<1, dim>   &value) const;
    void
    record_statistics(const unsigned int cycle);
    /** The series' records after the cycles written so far: file name
     * (solution.pvd, statistics.csv) and text. */
    std::map<std::string, std::string>
    series_records() const;
    /** Writes the cycle's VTU file (on one process in the background, with
     * the records queued after it) and its records. */
    void
    output_results(const unsigned int cycle);

    const Parameters<dim>     &parameters;
    const std::string          parameter_text;
    MPI_Comm                   mpi_communicator;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        timer;

    /** Where each cycle's mesh comes from. */
    std::unique_ptr<MeshAdaptation<dim>>        mesh_adaptation;
    std::unique_ptr<dealii::Triangulation<dim>> triangulation;
    bool                                        simplex = false;
    std::unique_ptr<dealii::FiniteElement<dim>> fe;
    const dealii::Mapping<dim>                 *mapping = nullptr;
    dealii::Quadrature<dim>                     quadrature;
    dealii::Quadrature<dim - 1>                 face_quadrature;
    dealii::DoFHandler<dim>                     dof_handler;
    dealii::IndexSet                            locally_owned_dofs;
    dealii::IndexSet                            locally_relevant_dofs;
    /** Dofs on a Dirichlet boundary in a fixed component: where the
     * support reactions act. */
    dealii::IndexSet support_dofs;

    /** Hanging nodes and Dirichlet data; fixed within a cycle. */
    dealii::AffineConstraints<double> fixed_constraints;
    /** fixed_constraints plus the active contact nodes at the obstacle. */
    dealii::AffineConstraints<double> constraints;

    /** Cell stiffness matrices, computed once per cell shape. */
    CellStiffness<dim>                     cell_stiffness;
    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    dealii::TrilinosWrappers::MPI::Vector  system_rhs;
    /** system_rhs without the augmented Lagrangian multipliers' share. */
    dealii::TrilinosWrappers::MPI::Vector base_rhs;
    /** The solver, with the factorisation of system_matrix. */
    LinearSystemSolver linear_system_solver;
    /** What system_matrix was assembled for: the active set and epsilon;
     * while they stay, the matrix and its factorisation are reused. */
    bool matrix_assembled = false;
    std::pair<std::pair<unsigned int, std::size_t>, double> assembled_for;
    /** Displacement [mm], with ghost entries. */
    dealii::TrilinosWrappers::MPI::Vector solution;
    /** K u - f with the contact set free: the obstacle's nodal force [N]. */
    dealii::TrilinosWrappers::MPI::Vector residual;
    /** The traction on this mesh: Boundary conditions/Traction, or the
     * uniform one of the Traction resultant. */
    const dealii::Function<dim>           *traction = nullptr;
    std::unique_ptr<dealii::Function<dim>> uniform_traction;
    /** External load vector f [N]. */
    dealii::TrilinosWrappers::MPI::Vector load;
    /** Contact pressure [MPa] at the vertical dofs of contact nodes, with
     * ghost entries. */
    dealii::TrilinosWrappers::MPI::Vector pressure;

    std::vector<ContactNode<dim>> contact_nodes;
    double                        complementarity_constant = 0.;
    /** The penalty (and augmented Lagrangian) compliance epsilon in use on
     * this cycle [mm/MPa]. */
    double       penalty_parameter  = 0.;
    unsigned int multiplier_updates = 0;
    /** Active set cycle breaking: update by the signs of pressure and gap
     * alone, for the rest of the cycle. */
    bool sign_rule = false;
    /** Gaps below this count as touching: round-off in the body's size. */
    double                touching_tolerance = 0.;
    unsigned int          newton_iterations  = 0;
    dealii::Vector<float> estimated_error_per_cell;

    std::vector<CycleStatistics<dim>>           cycle_statistics;
    std::vector<CycleTimings>                   cycle_timings;
    std::vector<std::pair<double, std::string>> written_cycles;
    std::unique_ptr<Checkpoint>                 checkpoint;
    /** Last, so that it is destroyed first: the files being written in the
     * background refer to the members above. */
    BackgroundWriter background_writer;
  };
} // namespace signorini

#endif
