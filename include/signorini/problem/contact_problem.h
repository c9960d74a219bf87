#ifndef signorini_problem_contact_problem_h
#define signorini_problem_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <signorini/contact/contact_formulation.h>
#include <signorini/contact/contact_law.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/contact/newton_driver.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/elastic_operator.h>
#include <signorini/elasticity/loads.h>
#include <signorini/output/background_writer.h>
#include <signorini/output/checkpoint.h>
#include <signorini/output/run_record.h>
#include <signorini/problem/parameters.h>

#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace signorini
{
  struct VtuPiece;

  /**
   * The Signorini problem: a linear elastic body, loads and supports, and a
   * rigid obstacle, solved in adaptive cycles, in the verbs of step-42:
   * setup_system, solve, refine_grid, output_results, run, with a
   * quasi-static load history replayed on each cycle's mesh. It owns the
   * cycle's state (displacement, contact pressure, error indicators) and
   * connects the rooms that do the work: the Discretisation, the
   * ElasticOperator, the Obstacle and the ContactSurface, the
   * ContactLaw and the ContactFormulation with their NewtonDriver
   * (assemble_newton_system, solve, update_active_set), the postprocessing, and
   * the RunRecord with its checkpoints.
   */
  template <int dim>
  class ContactProblem
  {
  public:
    ContactProblem(const Parameters<dim> &parameters,
                   const MPI_Comm         mpi_communicator);

    /** All cycles; throws SolverFailure or InputError. With @p resume,
     * continues after the cycle or the load step of the newest checkpoint
     * in the output directory (from cycle 0 if there is none). */
    void
    run(const bool resume = false);

  private:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    // run.cc
    void
    run_cycles(const bool resume);
    /** The loads, the Dirichlet data (the constraints anew, once there is a
     * mesh) and the obstacles at the pseudo-time @p t of the load history.
     * Throws InputError where one is not finite. */
    void
    set_time(const double t);
    /** Wall time [s] on the slowest process (collective). */
    double
    wall_time() const;
    /** The contact problem of one cycle (of one load step) by the
     * formulation. */
    void
    solve(const unsigned int cycle);
    void
    estimate_error();
    void
    refine_grid();

    // load_steps.cc
    /** Cycle @p cycle's load history from step @p first_step on: from zero
     * displacement and pressure if it is 1, else from the state of the
     * step before (restored from its checkpoint). Each step but the last is
     * solved, estimated, recorded, written (output_step()) and
     * checkpointed, with the run time @p run_time at the cycle's start
     * (wall time @p start) added to its own; then the last step is solved,
     * and run_cycles() finishes it as a cycle without a history. */
    void
    solve_history(const unsigned int cycle,
                  const unsigned int first_step,
                  const double       run_time,
                  const double       start);
    /** Starts load step @p step of the history: the loads, constraints,
     * obstacles and contact surface at its time, and NewtonDriver's
     * start_step(). */
    void
    start_load_step(const unsigned int step);

    // setup.cc
    /** The operator, contact surface and vectors of the current mesh. */
    void
    setup_system();

    // output.cc
    /** Writes parameters.prm, obstacle.vtu (the obstacles at the end of
     * the load history) and, with a load history, the chart script
     * force_displacement.gnuplot. */
    void
    write_obstacle_and_parameters() const;
    /** The gnuplot script that draws the final cycle's force-displacement
     * curves from force_displacement.csv. */
    void
    write_force_displacement_chart(std::ostream &out) const;
    /** The statistics row of load step @p step of cycle @p cycle (the
     * columns step and time only with a load history, which also gets its
     * force-displacement row). */
    void
    record_statistics(const unsigned int cycle, const unsigned int step);
    /** Writes the cycle's VTU file (on one process in the background, with
     * the records queued after it) and its records; in the final cycle of
     * a load history also its last step's history file. */
    void
    output_results(const unsigned int cycle);
    /** After load step @p step (not the last) of cycle @p cycle: in the
     * final cycle the step's history file, and the records so far (on one
     * process queued for the background writer, which the caller
     * launches). */
    void
    output_step(const unsigned int cycle, const unsigned int step);
    /** The current solution's fields as a VTU piece of this process. */
    std::shared_ptr<const VtuPiece>
    solution_piece();
    /** Writes @p piece as BASE.vtu (one process: queued for the background
     * writer, compressed on @p threads threads) or BASE.pvtu with a piece
     * per process (collective); returns the name of the file. */
    std::string
    write_solution(const std::shared_ptr<const VtuPiece> &piece,
                   const std::string                     &base,
                   const unsigned int                     threads);
    /** Writes the series' records as they are now (one process: queued for
     * the background writer). */
    void
    write_records();

    // resume.cc
    /** Takes over the output directory (removing what an earlier run left
     * that this run does not continue) and writes the obstacle and the
     * parameters. Returns the point (a cycle, or a load step within one) of
     * the checkpoint to resume after, on @p resume, if there is one. */
    std::optional<CheckpointPoint>
    start_output(const bool resume);
    /** Restores the run record, the tables, the mesh and the state after
     * @p point from its checkpoint, adding its run time to @p run_time:
     * after a cycle the mesh to refine, with the last step's displacement,
     * pressure and error indicators; after a load step the cycle's mesh
     * with what the next step starts from (the displacement, the pressure,
     * and with friction the shear tractions). */
    void
    restore_checkpoint(const CheckpointPoint &point, double &run_time);
    /** Whether this run writes checkpoints (Output/Checkpoint, and a mesh
     * that is not remeshed by Gmsh). */
    bool
    writes_checkpoints() const;
    /** Writes the checkpoint at @p point, after a cycle or a load step
     * (Output/Checkpoint); throws std::runtime_error naming the file and the
     * reason if a piece is not written whole. */
    void
    save_checkpoint(const CheckpointPoint &point, const double run_time);
    /** After a failure or an interruption, once nothing is written any
     * more: removes the temporaries of unfinished writes and the pieces of
     * an incomplete checkpoint (process 0). */
    void
    tidy_output() const;

    // benchmark.cc
    /** Wall time of assembling and solving the Newton system of the
     * converged active set anew, with the same linear solver [s]: one linear
     * elasticity solve on this mesh. Leaves the solution as it was. */
    double
    time_linear_solve();
    /** Adds this cycle's row to timings.csv. */
    void
    write_timings(const CycleTimings &row);

    const Parameters<dim>     &parameters;
    MPI_Comm                   mpi_communicator;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput        timer;

    Discretisation<dim>                      discretisation;
    Loads<dim>                               loads;
    std::unique_ptr<ElasticOperator<dim>>    elastic_operator;
    std::unique_ptr<ObstacleSet<dim>>        obstacle;
    ContactSurface<dim>                      contact_surface;
    std::unique_ptr<ContactLaw<dim>>         law;
    std::unique_ptr<ContactFormulation<dim>> formulation;

    /** Displacement [mm] and contact pressure [MPa] (at the contact nodes'
     * scalar dofs), with ghost entries. */
    VectorType            solution;
    VectorType            pressure;
    NewtonDriver<dim>     newton;
    dealii::Vector<float> estimated_error_per_cell;

    RunRecord record;
    /** The last cycle whose results and checkpoint are written, if any. */
    std::optional<unsigned int> finished_cycle;
    /** The last load step within a cycle whose results and checkpoint are
     * written, if any. */
    std::optional<CheckpointPoint> finished_step;
    std::unique_ptr<Checkpoint>    checkpoint;
    /** Last, so that it is destroyed first: the files being written in the
     * background refer to the members above. */
    BackgroundWriter background_writer;
  };
} // namespace signorini

#endif
