// write_vtu() decoded again: each DataArray is the base64 of its header
// (number of blocks, block size, last block's size, compressed sizes), then
// the base64 of its zlib or LZ4 blocks streamed one after the other. Arrays
// of one and of several 256 kB blocks, with either compressor (which the
// file must name), on one thread and on two, must give back their bytes
// exactly; among them, block boundaries where the base64 carries one byte
// and two bytes into the next block must occur. An empty piece must stay a
// valid file.

#include <signorini/output/file_output.h>

#include "checks.h"
#include "vtu_arrays.h"
#include <cmath>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace signorini;

namespace
{
  /** Which of 0, 1, 2 the compressed bytes before a block boundary came
   * to modulo 3 (1 and 2: the base64 carried a byte or two across). */
  bool carried[3] = {false, false, false};

  /** The bytes of the DataArray whose text is @p text; none if it does
   * not decode. */
  std::vector<unsigned char>
  decoded(const std::string &text, const vtu_arrays::Compressor compressor)
  {
    try
      {
        const auto  array = vtu_arrays::decode(text, compressor);
        std::size_t at    = 0;
        for (std::size_t b = 0; b + 1 < array.compressed_sizes.size(); ++b)
          {
            at += array.compressed_sizes[b];
            carried[at % 3] = true;
          }
        return array.bytes;
      }
    catch (const std::exception &)
      {
        return {};
      }
  }

  /** The texts of the binary DataArrays of @p file, in order. */
  std::vector<std::string>
  arrays(const std::string &file)
  {
    std::vector<std::string> found;
    const std::string        open = "format=\"binary\">\n";
    std::size_t              at   = file.find(open);
    while (at != std::string::npos)
      {
        at += open.size();
        found.push_back(file.substr(at, file.find('\n', at) - at));
        at = file.find(open, at);
      }
    return found;
  }

  template <class T>
  bool
  same(const std::vector<unsigned char> &bytes, const std::vector<T> &values)
  {
    return bytes.size() == values.size() * sizeof(T) &&
           std::memcmp(bytes.data(), values.data(), bytes.size()) == 0;
  }
} // namespace

int
main()
{
  // Points enough for several blocks; values that compress unevenly so
  // that the compressed blocks' sizes vary.
  for (const unsigned int n_points : {16u, 30000u, 70000u})
    {
      VtuPiece piece;
      for (unsigned int i = 0; i < 3 * n_points; ++i)
        piece.points.push_back(static_cast<float>(std::sin(0.37 * i) * i));
      for (unsigned int c = 0; c < n_points / 8; ++c)
        {
          for (unsigned int k = 0; k < 8; ++k)
            piece.connectivity.push_back(8 * c + k);
          piece.offsets.push_back(8 * (c + 1));
          piece.types.push_back(12);
        }
      VtuPiece::Field field{"displacement", 3, {}};
      for (unsigned int i = 0; i < 3 * n_points; ++i)
        field.values.push_back(static_cast<float>((i * 7919u) % 1000) / 7.f);
      piece.fields.push_back(field);
      for (const auto compression : {VtuCompression::zlib, VtuCompression::lz4})
        for (const unsigned int threads : {1u, 2u})
          {
            std::ostringstream out;
            write_vtu(out, piece, compression, threads);
            const auto named = compression == VtuCompression::zlib ?
                                 vtu_arrays::Compressor::zlib :
                                 vtu_arrays::Compressor::lz4;
            bool       all   = false;
            try
              {
                all = vtu_arrays::compressor(out.str()) == named;
              }
            catch (const std::exception &)
              {
              }
            const auto texts = arrays(out.str());
            all              = all && texts.size() == 5 &&
                  same(decoded(texts[0], named), piece.points) &&
                  same(decoded(texts[1], named), piece.connectivity) &&
                  same(decoded(texts[2], named), piece.offsets) &&
                  same(decoded(texts[3], named), piece.types) &&
                  same(decoded(texts[4], named), field.values);
            std::cout << n_points << " points, "
                      << (compression == VtuCompression::zlib ? "zlib" : "lz4")
                      << ", " << threads << " thread(s), "
                      << (3 * n_points * 4 + 262143) / 262144
                      << " block(s) of points: "
                      << (all ? "decoded exactly" : "FAILED") << std::endl;
            if (!all)
              checks::failed();
          }
    }

  std::cout << "block boundaries after 1 and 2 bytes of a base64 group: "
            << (carried[1] && carried[2] ? "both met" : "FAILED: not both met")
            << std::endl;
  if (!carried[1] || !carried[2])
    checks::failed();

  VtuPiece empty;
  empty.fields.push_back({"displacement", 3, {}});
  std::ostringstream out;
  write_vtu(out, empty, VtuCompression::lz4, 1);
  const bool valid =
    out.str().find("NumberOfPoints=\"0\"") != std::string::npos &&
    out.str().find("</VTKFile>") != std::string::npos;
  std::cout << "empty piece: " << (valid ? "valid" : "FAILED") << std::endl;
  if (!valid)
    checks::failed();
}
