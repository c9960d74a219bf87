#ifndef signorini_output_checkpoint_h
#define signorini_output_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>
#include <optional>
#include <string>

namespace signorini
{
  /** Whether runs write checkpoints: entry `Output/Checkpoint`. */
  struct CheckpointParameters
  {
    bool enabled = true;

    /** Declares the entry, with the default of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The checkpoint files of a run in its output directory: after cycle CC,
   * checkpoint-CC.mesh* (the distributed mesh with the data attached to its
   * cells, written by deal.II) and checkpoint-CC.state, written whole and
   * last, which makes the checkpoint complete. The state holds the
   * parameter text of the run that wrote it and the caller's state as
   * bytes. Only the newest complete checkpoint is kept.
   */
  class Checkpoint
  {
  public:
    Checkpoint(const std::string &directory,
               const std::string &parameter_text,
               const MPI_Comm     mpi_communicator);

    /** The name of cycle @p cycle's mesh file, without the suffixes deal.II
     * appends. */
    std::string
    mesh_file(const unsigned int cycle) const;

    /** The name of cycle @p cycle's state file. */
    std::string
    state_file(const unsigned int cycle) const;

    /**
     * The newest complete checkpoint in the directory, if any, on every
     * process: its cycle, with its state available from state(). Throws an
     * InputError naming the state file if it cannot be read or was written
     * by a different parameter set (naming the first entry that differs).
     */
    std::optional<unsigned int>
    find_latest();

    /** The caller's state of the checkpoint found by find_latest(). */
    const std::string &
    state() const;

    /**
     * Completes the checkpoint of cycle @p cycle, whose mesh the caller has
     * saved: process 0 writes the state file whole, then every other
     * checkpoint is removed. Collective; throws std::runtime_error on every
     * process if writing fails on one.
     */
    void
    write_state(const unsigned int cycle, const std::string &state) const;

    /** write_state() on process 0 alone, without communication: for one
     * process, from the background writer. Throws std::runtime_error if
     * writing fails. */
    void
    write_state_file(const unsigned int cycle, const std::string &state) const;

  private:
    const std::string directory;
    const std::string parameter_text;
    MPI_Comm          mpi_communicator;
    std::string       found_state;
  };
} // namespace signorini

#endif
