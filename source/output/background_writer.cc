#include <signorini/output/background_writer.h>

#include <utility>

namespace signorini
{
  BackgroundWriter::~BackgroundWriter()
  {
    try
      {
        wait();
      }
    catch (...)
      {
      }
  }

  void
  BackgroundWriter::add(std::function<void()> write)
  {
    batch.push_back(std::move(write));
  }

  bool
  BackgroundWriter::queued() const
  {
    return !batch.empty();
  }

  void
  BackgroundWriter::launch()
  {
    wait();
    if (batch.empty())
      return;
    // The writes (and the data they hold) are freed as soon as they are
    // done, not when the next launch() or wait() collects the result.
    running =
      std::async(std::launch::async, [writes = std::move(batch)]() mutable {
        for (const auto &write : writes)
          write();
        writes.clear();
      });
    batch.clear();
  }

  void
  BackgroundWriter::wait()
  {
    if (running.valid())
      running.get();
  }
} // namespace signorini
