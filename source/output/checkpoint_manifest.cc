#include <signorini/output/checkpoint_manifest.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>
#include <zlib.h>

namespace signorini
{
  namespace
  {
    const std::string manifest_magic = "signorini checkpoint 3\n";
    /** The first line of the state files of signorini before checksums. */
    const std::string unchecked_magic = "signorini checkpoint 1\n";
    /** The first line of those whose mesh files held the vectors cell by
     * cell (deal.II's SolutionTransfer), before VertexValues. */
    const std::string cell_values_magic = "signorini checkpoint 2\n";
    /** "crc32 XXXXXXXX\n", the last line. */
    constexpr std::size_t trailer_size = 15;

    std::uint32_t
    crc_of(const char *data, const std::size_t size)
    {
      return crc32_z(crc32_z(0L, Z_NULL, 0),
                     reinterpret_cast<const Bytef *>(data),
                     size);
    }

    std::string
    hex(const std::uint32_t value)
    {
      char text[9];
      std::snprintf(text, sizeof(text), "%08x", value);
      return text;
    }

    /** Reads a manifest's text from a position on. */
    class ManifestReader
    {
    public:
      ManifestReader(const std::string &text, const std::size_t end)
        : text(text)
        , end(end)
      {
      }

      /** The next line without its '\n'; false at the end. */
      bool
      line(std::string &result)
      {
        const std::size_t newline = text.find('\n', position);
        if (newline == std::string::npos || newline >= end)
          return false;
        result   = text.substr(position, newline - position);
        position = newline + 1;
        return true;
      }

      /** "KEY NUMBER" */
      bool
      number(const std::string &key, std::uint64_t &value)
      {
        std::string next;
        if (!line(next) || next.rfind(key + " ", 0) != 0)
          return false;
        char *stop = nullptr;
        errno      = 0;
        value      = std::strtoull(next.c_str() + key.size() + 1, &stop, 10);
        return errno == 0 && stop != next.c_str() + key.size() + 1 &&
               *stop == '\0';
      }

      /** Whether the next line starts with "KEY ". */
      bool
      next_is(const std::string &key) const
      {
        return text.compare(position, key.size() + 1, key + " ") == 0 &&
               position + key.size() + 1 <= end;
      }

      /** "KEY SIZE\n", SIZE bytes and '\n'. */
      bool
      block(const std::string &key, std::string &bytes)
      {
        std::uint64_t size = 0;
        if (!number(key, size) || size > end - position ||
            end - position - size < 1 || text[position + size] != '\n')
          return false;
        bytes = text.substr(position, size);
        position += size + 1;
        return true;
      }

      bool
      at_end() const
      {
        return position == end;
      }

    private:
      const std::string &text;
      const std::size_t  end;
      std::size_t        position = 0;
    };
  } // namespace

  FileChecksum
  checksum_of_file(const std::string  &path,
                   const std::uint64_t offset,
                   const std::uint64_t length)
  {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
      throw std::runtime_error("cannot read '" + path +
                               "': " + std::strerror(errno));
    FileChecksum      checksum;
    std::vector<char> buffer(1 << 20);
    uLong             crc = crc32_z(0L, Z_NULL, 0);
    while (checksum.size < length)
      {
        const std::size_t wanted =
          std::min<std::uint64_t>(buffer.size(), length - checksum.size);
        const ssize_t n =
          ::pread(fd, buffer.data(), wanted, offset + checksum.size);
        if (n < 0 && errno == EINTR)
          continue;
        if (n < 0)
          {
            const int error = errno;
            ::close(fd);
            throw std::runtime_error("cannot read '" + path +
                                     "': " + std::strerror(error));
          }
        if (n == 0)
          break;
        crc = crc32_z(crc, reinterpret_cast<const Bytef *>(buffer.data()), n);
        checksum.size += n;
      }
    ::close(fd);
    checksum.crc = crc;
    return checksum;
  }

  FileChecksum
  checksum_of_file(const std::string &path)
  {
    return checksum_of_file(path, 0, std::numeric_limits<std::uint64_t>::max());
  }

  FileChecksum
  concatenate(const FileChecksum &first, const FileChecksum &second)
  {
    FileChecksum result;
    result.size = first.size + second.size;
    result.crc =
      crc32_combine(first.crc, second.crc, static_cast<z_off_t>(second.size));
    return result;
  }

  std::string
  CheckpointManifest::text() const
  {
    std::string result = manifest_magic;
    result += "cycle " + std::to_string(cycle) + "\n";
    // Only a checkpoint within a cycle has a step line: one after a cycle
    // is as before load steps had checkpoints.
    if (step)
      result += "step " + std::to_string(*step) + "\n";
    result += "pieces " + std::to_string(pieces.size()) + "\n";
    for (const auto &piece : pieces)
      result += "piece " + piece.name + " " +
                std::to_string(piece.checksum.size) + " " +
                hex(piece.checksum.crc) + "\n";
    result += "parameters " + std::to_string(parameters.size()) + "\n";
    result += parameters + "\n";
    result += "state " + std::to_string(state.size()) + "\n";
    result += state + "\n";
    result += "crc32 " + hex(crc_of(result.data(), result.size())) + "\n";
    return result;
  }

  std::string
  CheckpointManifest::read(const std::string &text)
  {
    const std::string earlier =
      "written by an earlier signorini, which stored the solution cell by "
      "cell";
    const std::size_t size = text.size();
    const bool        has_trailer =
      size >= manifest_magic.size() + trailer_size &&
      text.compare(size - trailer_size, 6, "crc32 ") == 0 &&
      text.back() == '\n' &&
      text.find_first_not_of("0123456789abcdef", size - 9) == size - 1;
    if (!has_trailer)
      {
        if (text.rfind(manifest_magic, 0) == 0)
          return "truncated (" + std::to_string(size) +
                 " bytes, without the checksum that ends it)";
        if (text.rfind(unchecked_magic, 0) == 0)
          return "written by an earlier signorini, without checksums";
        if (text.rfind(cell_values_magic, 0) == 0)
          return earlier;
        if (size == 0)
          return "empty";
        return "not a signorini checkpoint";
      }
    const std::uint32_t saved =
      std::strtoul(text.c_str() + size - 9, nullptr, 16);
    if (saved != crc_of(text.data(), size - trailer_size))
      return "damaged (its contents do not match the checksum written with "
             "them)";
    if (text.rfind(cell_values_magic, 0) == 0)
      return earlier;

    ManifestReader reader(text, size - trailer_size);
    std::string    line;
    std::uint64_t  saved_cycle = 0, saved_step = 0, n_pieces = 0;
    if (!reader.line(line) || line + "\n" != manifest_magic ||
        !reader.number("cycle", saved_cycle))
      return "not a checkpoint this signorini can read";
    const bool has_step = reader.next_is("step");
    if ((has_step && !reader.number("step", saved_step)) ||
        !reader.number("pieces", n_pieces) || n_pieces > 1000)
      return "not a checkpoint this signorini can read";
    cycle = saved_cycle;
    step  = has_step ? std::optional<unsigned int>(saved_step) : std::nullopt;
    pieces.clear();
    for (std::uint64_t i = 0; i < n_pieces; ++i)
      {
        Piece              piece;
        char               name[256], crc[9];
        unsigned long long size = 0;
        if (!reader.line(line) ||
            std::sscanf(
              line.c_str(), "piece %255s %llu %8s", name, &size, crc) != 3)
          return "not a checkpoint this signorini can read";
        piece.name          = name;
        piece.checksum.size = size;
        piece.checksum.crc  = std::strtoul(crc, nullptr, 16);
        pieces.push_back(piece);
      }
    if (!reader.block("parameters", parameters) ||
        !reader.block("state", state) || !reader.at_end())
      return "not a checkpoint this signorini can read";
    return "";
  }

  std::string
  CheckpointManifest::verify_pieces(const std::string &directory) const
  {
    for (const auto &piece : pieces)
      {
        const std::string path = directory + "/" + piece.name;
        struct stat       status;
        if (::stat(path.c_str(), &status) != 0)
          return path + ": missing (" + std::strerror(errno) +
                 "), a piece of the checkpoint of " +
                 (step ? "step " + std::to_string(*step) + " of " : "") +
                 "cycle " + std::to_string(cycle);
        const std::uint64_t size = status.st_size;
        if (size < piece.checksum.size)
          return path + ": truncated (" + std::to_string(size) + " of " +
                 std::to_string(piece.checksum.size) + " bytes)";
        if (size > piece.checksum.size)
          return path + ": damaged (" + std::to_string(size) + " bytes, " +
                 std::to_string(piece.checksum.size) + " were written)";
        FileChecksum found;
        try
          {
            found = checksum_of_file(path);
          }
        catch (const std::exception &failure)
          {
            return failure.what();
          }
        if (found.crc != piece.checksum.crc ||
            found.size != piece.checksum.size)
          return path +
                 ": damaged (its bytes do not match the checksum written "
                 "with them)";
      }
    return "";
  }
} // namespace signorini
