#include <deal.II/base/mpi.h>

#include <signorini/output/atomic_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <streambuf>
#include <unistd.h>
#include <vector>

namespace signorini
{
  namespace
  {
    /** A stream buffer that writes to a file descriptor and keeps the
     * errno of the first write that failed; later writes are refused. */
    class FileBuffer : public std::streambuf
    {
    public:
      explicit FileBuffer(const int fd)
        : fd(fd)
        , buffer(65536)
      {
        setp(buffer.data(), buffer.data() + buffer.size());
      }

      /** The errno of the first failure, 0 if none. */
      int error = 0;

    protected:
      int_type
      overflow(const int_type c) override
      {
        if (!flush())
          return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof()))
          {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
          }
        return traits_type::not_eof(c);
      }

      std::streamsize
      xsputn(const char *data, const std::streamsize size) override
      {
        if (size <= epptr() - pptr())
          {
            std::memcpy(pptr(), data, size);
            pbump(static_cast<int>(size));
            return size;
          }
        // Large blocks go to the file directly.
        if (!flush() || !write_all(data, size))
          return 0;
        return size;
      }

      int
      sync() override
      {
        return flush() ? 0 : -1;
      }

    private:
      bool
      flush()
      {
        const bool written = write_all(pbase(), pptr() - pbase());
        setp(buffer.data(), buffer.data() + buffer.size());
        return written;
      }

      bool
      write_all(const char *data, std::size_t size)
      {
        while (size > 0 && error == 0)
          {
            const ssize_t written = ::write(fd, data, size);
            if (written < 0 && errno == EINTR)
              continue;
            if (written <= 0)
              error = written < 0 ? errno : EIO;
            else
              {
                data += written;
                size -= written;
              }
          }
        return error == 0;
      }

      const int         fd;
      std::vector<char> buffer;
    };

    /** "cannot write 'PATH': REASON" with the text of @p error (errno). */
    std::runtime_error
    write_failure(const std::string &path, const int error)
    {
      return std::runtime_error("cannot write '" + path + "'" +
                                (error != 0 ?
                                   ": " + std::string(std::strerror(error)) :
                                   std::string()));
    }
  } // namespace

  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".part";
    const int         fd =
      ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
      throw write_failure(path, errno);
    int error = 0;
    try
      {
        FileBuffer   buffer(fd);
        std::ostream out(&buffer);
        try
          {
            write(out);
            out.flush();
          }
        catch (...)
          {
            // A writer that stopped because its stream failed (deal.II's
            // ExcIO) is reported by the stream's reason.
            if (buffer.error == 0)
              throw;
          }
        error = buffer.error;
        if (error == 0 && !out)
          error = EIO;
      }
    catch (...)
      {
        ::close(fd);
        std::remove(temporary.c_str());
        throw;
      }
    if (::close(fd) != 0 && error == 0)
      error = errno;
    if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0)
      error = errno;
    if (error != 0)
      {
        std::remove(temporary.c_str());
        throw write_failure(path, error);
      }
  }

  void
  write_collectively(const MPI_Comm               mpi_communicator,
                     const std::function<void()> &write)
  {
    std::string error;
    try
      {
        write();
      }
    catch (const std::exception &failure)
      {
        error = failure.what();
        if (error.empty())
          error = "a process could not write its output";
      }
    // Every process reports the failure of the first process that failed.
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int first_failed =
      dealii::Utilities::MPI::min(error.empty() ?
                                    n_ranks :
                                    dealii::Utilities::MPI::this_mpi_process(
                                      mpi_communicator),
                                  mpi_communicator);
    if (first_failed < n_ranks)
      throw std::runtime_error(n_ranks == 1 ?
                                 error :
                                 dealii::Utilities::MPI::broadcast(
                                   mpi_communicator, error, first_failed));
  }
} // namespace signorini
