#ifndef signorini_output_checkpoint_h
#define signorini_output_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/output/checkpoint_manifest.h>

#include <mpi.h>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

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
   * Where in a run a checkpoint was written: after a cycle, or after a load
   * step (not the last) within it. Checkpoints are ordered as they are
   * written: the steps of cycle k, then cycle k itself.
   */
  struct CheckpointPoint
  {
    unsigned int cycle = 0;
    /** The load step after which the checkpoint was written within the
     * cycle; none: after the cycle (its last step). */
    std::optional<unsigned int> step;

    /** Whether this checkpoint is written before @p other. */
    bool
    operator<(const CheckpointPoint &other) const;

    bool
    operator==(const CheckpointPoint &other) const;

    /** "CC" or "CC-SSS", as in the file names. */
    std::string
    suffix() const;
  };

  /** "cycle 4", or "step 2 of cycle 4". */
  std::ostream &
  operator<<(std::ostream &out, const CheckpointPoint &point);

  /**
   * The checkpoint files of a run in its output directory: after cycle CC,
   * checkpoint-CC.mesh* (the distributed mesh with the data attached to its
   * cells, written by deal.II and p4est) and checkpoint-CC.state, written
   * whole and last, which makes the checkpoint complete; after load step
   * SSS within cycle CC, checkpoint-CC-SSS.mesh* and checkpoint-CC-SSS.state
   * likewise. The state file is
   * the checkpoint's manifest (CheckpointManifest): the size and CRC-32 of
   * every mesh piece, the parameter text of the run that wrote it and the
   * caller's state, closed by its own checksum. Only the newest complete
   * checkpoint is kept; an older one is removed once a newer one is
   * complete.
   */
  class Checkpoint
  {
  public:
    Checkpoint(const std::string &directory,
               const std::string &parameter_text,
               const MPI_Comm     mpi_communicator);

    /** The name of the mesh file of the checkpoint at @p point, without
     * the suffixes deal.II appends. */
    std::string
    mesh_file(const CheckpointPoint &point) const;

    /** The name of the state file of the checkpoint at @p point. */
    std::string
    state_file(const CheckpointPoint &point) const;

    /**
     * The newest intact checkpoint in the directory, if any, on every
     * process: its point, with its state available from state(). Every
     * piece is checked against its size and checksum before anything reads
     * it. A newer checkpoint without its state file (a run stopped while
     * writing it) is passed over with a line on standard output; one that is
     * damaged or truncated with a warning line on standard error naming the
     * file and what is wrong. If none is intact and one is damaged, throws
     * an InputError naming the newest fault; also if the intact one was
     * written by a different parameter set (naming the first entry that
     * differs).
     */
    std::optional<CheckpointPoint>
    find_latest();

    /** The caller's state of the checkpoint found by find_latest(). */
    const std::string &
    state() const;

    /**
     * Checks, on process 0 alone, that the mesh of @p point, which
     * every process has just saved, was written whole: deal.II and p4est do
     * not report a write cut short by the file-size limit or a full file
     * system, so the pieces are checked against both. @p save_failure is
     * the message of a failure the save reported, if any. On failure the
     * pieces are removed (the previous checkpoint stays complete) and a
     * std::runtime_error names the file and the reason.
     */
    void
    check_mesh_pieces(const CheckpointPoint &point,
                      const std::string     &save_failure) const;

    /**
     * Completes the checkpoint at @p point, whose mesh the caller has
     * saved: every process reads a slice of each mesh piece for its
     * checksum, process 0 writes the state file whole, then every older
     * checkpoint is removed. Collective; throws std::runtime_error on every
     * process if reading or writing fails on one.
     */
    void
    write_state(const CheckpointPoint &point, const std::string &state) const;

    /** write_state() on process 0 alone, without communication: for one
     * process, from the background writer. Reads the mesh pieces for their
     * checksums. Throws std::runtime_error if reading or writing fails. */
    void
    write_state_file(const CheckpointPoint &point,
                     const std::string     &state) const;

    /** Removes, on process 0 alone, the pieces of checkpoints without a
     * state file (whose writing failed or was stopped): what is left is
     * the newest complete checkpoint. */
    void
    remove_incomplete() const;

  private:
    /** The names of the mesh pieces of the checkpoint at @p point in the
     * directory. */
    std::vector<std::string>
    mesh_pieces(const CheckpointPoint &point) const;

    /** Writes the state file of @p point with the checksums of its
     * @p pieces, then removes every older checkpoint. */
    void
    write_manifest(const CheckpointPoint                        &point,
                   const std::string                            &state,
                   const std::vector<CheckpointManifest::Piece> &pieces) const;

    const std::string directory;
    const std::string parameter_text;
    MPI_Comm          mpi_communicator;
    std::string       found_state;
  };
} // namespace signorini

#endif
