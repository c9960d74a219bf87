#ifndef signorini_output_checkpoint_manifest_h
#define signorini_output_checkpoint_manifest_h

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace signorini
{
  /** The size of a file and the CRC-32 (zlib's) of its bytes. */
  struct FileChecksum
  {
    std::uint64_t size = 0;
    std::uint32_t crc  = 0;
  };

  /** The checksum of the file @p path, read whole; throws
   * std::runtime_error ("cannot read 'PATH': REASON") if it cannot be read.
   */
  FileChecksum
  checksum_of_file(const std::string &path);

  /** The checksum of @p length bytes of the file @p path from @p offset on
   * (fewer if the file ends before); throws as checksum_of_file(). */
  FileChecksum
  checksum_of_file(const std::string  &path,
                   const std::uint64_t offset,
                   const std::uint64_t length);

  /** The checksum of the bytes of @p first followed by those of
   * @p second. */
  FileChecksum
  concatenate(const FileChecksum &first, const FileChecksum &second);

  /**
   * The text of a checkpoint's state file, which is also its manifest:
   * written last and whole, it lists every other piece of the checkpoint
   * (the mesh files that deal.II and p4est write) with its size and CRC-32,
   * holds the parameter text of the run and the run's state, and ends with
   * the CRC-32 of everything before it. A checkpoint is intact when its
   * state file ends with a matching checksum and every piece it lists has
   * its size and checksum.
   */
  struct CheckpointManifest
  {
    /** A piece of the checkpoint: a file name in the output directory. */
    struct Piece
    {
      std::string  name;
      FileChecksum checksum;
    };

    unsigned int cycle = 0;
    /** The load step after which the checkpoint was written within its
     * cycle (a line "step N" after the cycle's); none for one written after
     * the cycle. */
    std::optional<unsigned int> step;
    std::vector<Piece>          pieces;
    std::string                 parameters;
    std::string                 state;

    /** The text of the state file. */
    std::string
    text() const;

    /**
     * Reads @p text, the bytes of a state file, into this manifest. Returns
     * what is wrong with it ("truncated (...)", "damaged (...)", "not a
     * signorini checkpoint"), or an empty string if it is whole.
     */
    std::string
    read(const std::string &text);

    /**
     * Checks every piece in @p directory against its size and checksum.
     * Returns "PATH: what is wrong" for the first piece that is missing,
     * truncated or damaged, or an empty string if all are intact.
     */
    std::string
    verify_pieces(const std::string &directory) const;
  };
} // namespace signorini

#endif
