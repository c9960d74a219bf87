#include <deal.II/base/data_out_base.h>
#include <deal.II/base/thread_management.h>

#include <signorini/output/file_output.h>

#include <algorithm>
#include <atomic>
#include <lz4.h>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <zlib.h>

namespace signorini
{
  namespace
  {
    /** The size of the blocks that an array is compressed in: large enough
     * to compress about as well as one block per array, small enough to
     * give each thread a few blocks (doc/architecture.md). */
    constexpr std::size_t block_size = 262144;

    /** An array of the file as bytes, and its compressed blocks. */
    struct CompressedArray
    {
      CompressedArray(const void *data, const std::size_t size)
        : data(static_cast<const unsigned char *>(data))
        , size(size)
        , blocks((size + block_size - 1) / block_size)
      {
      }

      const unsigned char                    *data;
      std::size_t                             size;
      std::vector<std::vector<unsigned char>> blocks;
    };

    /** One thread's compressor of blocks: zlib's deflate at its fastest
     * level, or LZ4 (raw blocks, as VTK's vtkLZ4DataCompressor reads them). */
    class BlockCompressor
    {
    public:
      explicit BlockCompressor(const VtuCompression compression)
        : compression(compression)
      {
        if (compression == VtuCompression::zlib)
          {
            ready = deflateInit(&stream, Z_BEST_SPEED) == Z_OK;
            if (ready)
              buffer.resize(deflateBound(&stream, block_size));
          }
        else
          buffer.resize(LZ4_compressBound(block_size));
      }

      ~BlockCompressor()
      {
        if (compression == VtuCompression::zlib && ready)
          deflateEnd(&stream);
      }

      BlockCompressor(const BlockCompressor &) = delete;
      BlockCompressor &
      operator=(const BlockCompressor &) = delete;

      /** Compresses @p size bytes at @p data into @p block; false if the
       * library failed. */
      bool
      compress(const unsigned char        *data,
               const std::size_t           size,
               std::vector<unsigned char> &block)
      {
        // Compressed into a buffer of the largest size a block can take,
        // then copied: a block keeps only the memory it needs.
        std::size_t compressed = 0;
        if (compression == VtuCompression::zlib)
          {
            if (!ready)
              return false;
            deflateReset(&stream);
            stream.next_in   = const_cast<unsigned char *>(data);
            stream.avail_in  = size;
            stream.next_out  = buffer.data();
            stream.avail_out = buffer.size();
            if (deflate(&stream, Z_FINISH) != Z_STREAM_END)
              return false;
            compressed = stream.total_out;
          }
        else
          {
            const int n =
              LZ4_compress_default(reinterpret_cast<const char *>(data),
                                   reinterpret_cast<char *>(buffer.data()),
                                   static_cast<int>(size),
                                   static_cast<int>(buffer.size()));
            if (n <= 0)
              return false;
            compressed = n;
          }
        block.assign(buffer.data(), buffer.data() + compressed);
        return true;
      }

    private:
      VtuCompression             compression;
      z_stream                   stream = {};
      bool                       ready  = true;
      std::vector<unsigned char> buffer;
    };

    /** Compresses the blocks of @p array on @p n_threads threads, each
     * taking the next block not yet taken. */
    void
    compress(CompressedArray     &array,
             const VtuCompression compression,
             const unsigned int   n_threads)
    {
      std::atomic<std::size_t> next(0);
      std::atomic<bool>        failed(false);
      const auto               work = [&]() {
        BlockCompressor compressor(compression);
        for (std::size_t b = next++; b < array.blocks.size(); b = next++)
          {
            const std::size_t start = b * block_size;
            const std::size_t size = std::min(block_size, array.size - start);
            if (!compressor.compress(array.data + start, size, array.blocks[b]))
              failed = true;
          }
      };
      std::vector<dealii::Threads::Task<void>> tasks;
      for (unsigned int t = 1;
           t < std::min<std::size_t>(n_threads, array.blocks.size());
           ++t)
        tasks.push_back(dealii::Threads::new_task(std::function<void()>(work)));
      work();
      for (auto &task : tasks)
        task.join();
      if (failed)
        throw std::runtime_error(
          std::string(compression == VtuCompression::zlib ? "zlib" : "LZ4") +
          " could not compress the VTU data");
    }

    /** Appends the base64 encoding of @p size bytes at @p data to @p out. */
    void
    append_base64(std::string         &out,
                  const unsigned char *data,
                  const std::size_t    size)
    {
      static const char digits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::size_t position = out.size();
      out.resize(position + 4 * ((size + 2) / 3));
      std::size_t i = 0;
      for (; i + 3 <= size; i += 3)
        {
          const unsigned int bits =
            (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
          out[position++] = digits[bits >> 18];
          out[position++] = digits[(bits >> 12) & 63];
          out[position++] = digits[(bits >> 6) & 63];
          out[position++] = digits[bits & 63];
        }
      if (i < size)
        {
          const unsigned int bits =
            (data[i] << 16) | (i + 1 < size ? data[i + 1] << 8 : 0);
          out[position++] = digits[bits >> 18];
          out[position++] = digits[(bits >> 12) & 63];
          out[position++] = i + 1 < size ? digits[(bits >> 6) & 63] : '=';
          out[position++] = '=';
        }
    }

    /** Writes @p array as VTK reads a compressed binary array: the base64
     * of the header (the number of blocks, the size of a block and of the
     * last one, the compressed size of each), then that of the blocks, one
     * stream of base64 across them (no copy of them joined). */
    void
    write_array(std::ostream &out, const CompressedArray &array)
    {
      if (array.size == 0)
        return;
      std::vector<std::uint32_t> header = {
        static_cast<std::uint32_t>(array.blocks.size()),
        static_cast<std::uint32_t>(block_size),
        static_cast<std::uint32_t>(array.size -
                                   (array.blocks.size() - 1) * block_size)};
      for (const auto &block : array.blocks)
        header.push_back(static_cast<std::uint32_t>(block.size()));
      std::string text;
      append_base64(text,
                    reinterpret_cast<const unsigned char *>(header.data()),
                    header.size() * sizeof(std::uint32_t));
      out << text;
      // Whole groups of three bytes per block; the rest carried into the
      // next one.
      unsigned char carried[3];
      std::size_t   n_carried = 0;
      for (const auto &block : array.blocks)
        {
          std::size_t i = 0;
          while (n_carried > 0 && n_carried < 3 && i < block.size())
            carried[n_carried++] = block[i++];
          text.clear();
          if (n_carried == 3)
            {
              append_base64(text, carried, 3);
              n_carried = 0;
            }
          const std::size_t whole = i + (block.size() - i) / 3 * 3;
          append_base64(text, block.data() + i, whole - i);
          out << text;
          for (i = whole; i < block.size(); ++i)
            carried[n_carried++] = block[i];
        }
      text.clear();
      append_base64(text, carried, n_carried);
      out << text;
    }

    /** The fields of @p piece in the order of the file (and of deal.II's
     * DataOut): the vectors, then the scalars. */
    std::vector<const VtuPiece::Field *>
    ordered_fields(const VtuPiece &piece)
    {
      std::vector<const VtuPiece::Field *> fields;
      for (const bool vectors : {true, false})
        for (const auto &field : piece.fields)
          if ((field.n_components > 1) == vectors)
            fields.push_back(&field);
      return fields;
    }
  } // namespace

  void
  write_vtu(std::ostream        &out,
            const VtuPiece      &piece,
            const VtuCompression compression,
            const unsigned int   n_threads)
  {
    // deal.II's header, which names zlib's compressor.
    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    std::ostringstream header;
    dealii::DataOutBase::write_vtu_header(header, flags);
    std::string text = header.str();
    if (compression == VtuCompression::lz4)
      {
        const std::string zlib = "vtkZLibDataCompressor";
        const auto        at   = text.find(zlib);
        if (at == std::string::npos)
          throw std::logic_error("deal.II's VTU header names no compressor");
        text.replace(at, zlib.size(), "vtkLZ4DataCompressor");
      }
    out << text;
    const auto fields = ordered_fields(piece);
    if (piece.types.empty())
      {
        // What deal.II writes for a process without cells: a valid piece
        // that names the fields.
        out << "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\" >\n"
            << "<Cells>\n"
            << "<DataArray type=\"UInt8\" Name=\"types\"></DataArray>\n"
            << "</Cells>\n"
            << "  <PointData Scalars=\"scalars\">\n";
        for (const auto *field : fields)
          out << "    <DataArray type=\"Float32\" Name=\"" << field->name
              << (field->n_components > 1 ? "\" NumberOfComponents=\"3" : "")
              << "\"></DataArray>\n";
        out << "  </PointData>\n"
            << "</Piece>\n";
      }
    else
      {
        // One array at a time, compressed, written and freed: the file's
        // compressed data is never held whole.
        const auto write = [&](const auto &values) {
          CompressedArray array(values.data(),
                                values.size() * sizeof(values[0]));
          compress(array, compression, n_threads);
          write_array(out, array);
        };

        const std::string binary = "\" format=\"binary\">\n";
        out << "<Piece NumberOfPoints=\"" << piece.points.size() / 3
            << "\" NumberOfCells=\"" << piece.types.size() << "\" >\n"
            << "  <Points>\n"
            << "    <DataArray type=\"Float32\" NumberOfComponents=\"3"
            << binary;
        write(piece.points);
        out << "\n    </DataArray>\n"
            << "  </Points>\n\n"
            << "  <Cells>\n"
            << "    <DataArray type=\"Int32\" Name=\"connectivity" << binary;
        write(piece.connectivity);
        out << "\n    </DataArray>\n"
            << "    <DataArray type=\"Int32\" Name=\"offsets" << binary;
        write(piece.offsets);
        out << "\n    </DataArray>\n"
            << "    <DataArray type=\"UInt8\" Name=\"types" << binary;
        write(piece.types);
        out << "\n    </DataArray>\n"
            << "  </Cells>\n"
            << "  <PointData Scalars=\"scalars\">\n";
        for (unsigned int f = 0; f < fields.size(); ++f)
          {
            out << "    <DataArray type=\"Float32\" Name=\"" << fields[f]->name
                << (fields[f]->n_components > 1 ? "\" NumberOfComponents=\"3" :
                                                  "")
                << binary;
            write(fields[f]->values);
            out << "\n    </DataArray>\n";
          }
        out << "  </PointData>\n"
            << " </Piece>\n";
      }
    dealii::DataOutBase::write_vtu_footer(out);
    out << std::flush;
  }

  void
  write_pvtu_record(std::ostream                   &out,
                    const std::vector<std::string> &pieces,
                    const VtuPiece                 &piece)
  {
    std::vector<std::string> names;
    std::vector<std::tuple<
      unsigned int,
      unsigned int,
      std::string,
      dealii::DataComponentInterpretation::DataComponentInterpretation>>
      vectors;
    for (const auto *field : ordered_fields(piece))
      {
        if (field->n_components > 1)
          vectors.emplace_back(
            names.size(),
            names.size() + field->n_components - 1,
            field->name,
            dealii::DataComponentInterpretation::component_is_part_of_vector);
        for (unsigned int c = 0; c < field->n_components; ++c)
          names.push_back(field->name);
      }
    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    dealii::DataOutBase::write_pvtu_record(out, pieces, names, vectors, flags);
  }
} // namespace signorini
