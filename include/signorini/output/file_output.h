#ifndef signorini_output_file_output_h
#define signorini_output_file_output_h

#include <cstdint>
#include <functional>
#include <mpi.h>
#include <ostream>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * Writes @p path whole or not at all: @p write fills a temporary file
   * beside it, which is renamed to @p path once complete. A reader never
   * sees a half-written file, and an earlier version stays intact if
   * writing fails. Every write is checked: on failure the temporary file is
   * removed and a std::runtime_error names the file and the system's reason
   * ("cannot write 'out/solution-03.vtu': No space left on device"), also
   * when @p write stopped with an exception because its stream failed.
   */
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &write);

  /**
   * Runs @p write on every process and throws on every process if it
   * failed on any, so that no process is left waiting for one that gave up;
   * each throws the message of the first process that failed, so that
   * process 0 reports it. Also a barrier: what one process wrote is complete
   * afterwards.
   */
  void
  write_collectively(const MPI_Comm               mpi_communicator,
                     const std::function<void()> &write);

  /**
   * One piece of a VTU file of linear cells, laid out as deal.II's DataOut
   * lays out its patches: every cell has points of its own (one per vertex),
   * so that a field may jump between cells, and the point data is given per
   * point. The arrays are those of the file, in its types.
   */
  struct VtuPiece
  {
    /** A point field: @p n_components values per point (1, or 3 for a
     * vector, which ParaView then offers for Warp By Vector). */
    struct Field
    {
      std::string        name;
      unsigned int       n_components;
      std::vector<float> values;
    };

    /** Three coordinates per point. */
    std::vector<float> points;
    /** Each cell's points, in VTK's vertex order. */
    std::vector<std::int32_t> connectivity;
    /** The end of each cell's points in connectivity. */
    std::vector<std::int32_t> offsets;
    /** The VTK cell type of each cell. */
    std::vector<std::uint8_t> types;
    std::vector<Field>        fields;
  };

  /**
   * Writes @p piece as a VTU file, its arrays compressed with zlib at its
   * fastest level in blocks (as VTK itself writes them), each compressed on
   * its own: here on @p n_threads threads.
   */
  void
  write_vtu(std::ostream &out, const VtuPiece &piece, unsigned int n_threads);

  /**
   * Writes the PVTU record that joins the VTU files @p pieces, each with the
   * fields of @p piece.
   */
  void
  write_pvtu_record(std::ostream                   &out,
                    const std::vector<std::string> &pieces,
                    const VtuPiece                 &piece);
} // namespace signorini

#endif
