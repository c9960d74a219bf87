#ifndef signorini_output_file_output_h
#define signorini_output_file_output_h

// The VTU files are written with write_atomically().
#include <signorini/output/atomic_file.h>

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace signorini
{
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

  /** How the arrays of a VTU file are compressed; VTK (ParaView) reads
   * both. */
  enum class VtuCompression
  {
    /** LZ4: about 15 times faster than zlib, files about 40 % larger. */
    lz4,
    /** zlib at its fastest level: the smallest files. */
    zlib
  };

  /**
   * Writes @p piece as a VTU file, its arrays compressed by @p compression
   * in blocks (as VTK itself writes them), each compressed on its own: here
   * on @p n_threads threads.
   */
  void
  write_vtu(std::ostream   &out,
            const VtuPiece &piece,
            VtuCompression  compression,
            unsigned int    n_threads);

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
