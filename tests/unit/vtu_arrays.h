// Decoding the arrays of a VTU file as signorini and deal.II write them
// (binary, zlib- or LZ4-compressed), for the unit tests that read them back.
#ifndef signorini_tests_unit_vtu_arrays_h
#define signorini_tests_unit_vtu_arrays_h

#include <cctype>
#include <cstdint>
#include <cstring>
#include <lz4.h>
#include <stdexcept>
#include <string>
#include <vector>
#include <zlib.h>

namespace vtu_arrays
{
  /** Decodes base64 (padding '=' ends a block; whitespace skipped). */
  inline std::vector<unsigned char>
  base64_decode(const std::string &text)
  {
    static const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> bytes;
    unsigned int               buffer = 0, bits = 0;
    for (const char c : text)
      {
        const auto k = alphabet.find(c);
        if (k == std::string::npos)
          {
            bits = buffer = 0; // '=' or whitespace: a block ends
            continue;
          }
        buffer = (buffer << 6) | k;
        bits += 6;
        if (bits >= 8)
          {
            bits -= 8;
            bytes.push_back((buffer >> bits) & 0xff);
          }
      }
    return bytes;
  }

  /** A decoded array: its bytes, and the compressed size of each block. */
  struct Array
  {
    std::vector<unsigned char> bytes;
    std::vector<std::uint32_t> compressed_sizes;
  };

  /** The compressors a VTU file names in its VTKFile element. */
  enum class Compressor
  {
    zlib,
    lz4
  };

  /** The compressor that the VTU text @p file names; throws if none. */
  inline Compressor
  compressor(const std::string &file)
  {
    const auto end = file.find("<UnstructuredGrid>");
    if (file.find("compressor=\"vtkZLibDataCompressor\"") < end)
      return Compressor::zlib;
    if (file.find("compressor=\"vtkLZ4DataCompressor\"") < end)
      return Compressor::lz4;
    throw std::runtime_error("no compressor named");
  }

  /**
   * The text @p data of a compressed binary DataArray decoded: the base64
   * of a header of UInt32 (number of blocks, block size, last block size,
   * compressed sizes), then the base64 of the blocks compressed by
   * @p compressor. Throws if the decompression fails or the blocks do not
   * fill the data exactly.
   */
  inline Array
  decode(const std::string &data, const Compressor compressor)
  {
    // The header alone: 3 + n_blocks UInt32, base64 in its own block.
    std::string trimmed;
    for (const char c : data)
      if (!std::isspace(static_cast<unsigned char>(c)))
        trimmed += c;
    const auto    first = base64_decode(trimmed.substr(0, 8));
    std::uint32_t n_blocks;
    std::memcpy(&n_blocks, first.data(), 4);
    const unsigned int header_bytes = 4 * (3 + n_blocks);
    const unsigned int header_chars = 4 * ((header_bytes + 2) / 3);
    const auto         header = base64_decode(trimmed.substr(0, header_chars));
    std::vector<std::uint32_t> h(3 + n_blocks);
    std::memcpy(h.data(), header.data(), header_bytes);
    const auto compressed = base64_decode(trimmed.substr(header_chars));

    Array       array;
    std::size_t offset = 0;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        uLongf size = (b + 1 < n_blocks || h[2] == 0) ? h[1] : h[2];
        std::vector<unsigned char> block(size);
        if (offset + h[3 + b] > compressed.size())
          throw std::runtime_error("blocks beyond the data");
        if (compressor == Compressor::zlib)
          {
            if (uncompress(block.data(),
                           &size,
                           compressed.data() + offset,
                           h[3 + b]) != Z_OK)
              throw std::runtime_error("zlib failed");
          }
        else if (LZ4_decompress_safe(reinterpret_cast<const char *>(
                                       compressed.data() + offset),
                                     reinterpret_cast<char *>(block.data()),
                                     h[3 + b],
                                     size) != static_cast<int>(size))
          throw std::runtime_error("LZ4 failed");
        array.bytes.insert(array.bytes.end(),
                           block.begin(),
                           block.begin() + size);
        array.compressed_sizes.push_back(h[3 + b]);
        offset += h[3 + b];
      }
    if (offset != compressed.size())
      throw std::runtime_error("compressed data left over");
    return array;
  }
} // namespace vtu_arrays

#endif
