#ifndef signorini_output_background_writer_h
#define signorini_output_background_writer_h

#include <functional>
#include <future>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * Writes a cycle's files on a thread of their own while the next cycle
   * computes: on one process the second core compresses and writes the VTU
   * file, which otherwise took as long as refining the mesh. The writes of a
   * cycle are queued with add() and started together with launch(); they
   * run in the order queued (the VTU file before the PVD record that lists
   * it, the checkpoint state last), with no MPI calls, so the files on disk
   * agree at every moment. wait() returns when they are done and rethrows
   * their failure.
   */
  class BackgroundWriter
  {
  public:
    BackgroundWriter() = default;

    /** Waits for the running writes; their failure is dropped (the
     * destructor runs when another failure unwinds the run). */
    ~BackgroundWriter();

    BackgroundWriter(const BackgroundWriter &) = delete;
    BackgroundWriter &
    operator=(const BackgroundWriter &) = delete;

    /** Queues @p write for the next launch(). */
    void
    add(std::function<void()> write);

    /** Whether writes are queued and not yet launched. */
    bool
    queued() const;

    /** Waits for the writes launched before, then starts the queued ones. */
    void
    launch();

    /** Waits for the launched writes; rethrows the exception of one that
     * failed (the later ones of its batch are not attempted). */
    void
    wait();

  private:
    std::vector<std::function<void()>> batch;
    std::future<void>                  running;
  };
} // namespace signorini

#endif
