// write_vtu() decoded again: each DataArray is the base64 of its header
// (number of blocks, block size, last block's size, compressed sizes), then
// the base64 of its zlib blocks streamed one after the other. Arrays of one
// and of several 256 kB blocks, on one thread and on two, must give back
// their bytes exactly; among them, block boundaries where the base64 carries
// one byte and two bytes into the next block must occur. An empty piece
// must stay a valid file.

#include <signorini/output/file_output.h>

#include "checks.h"
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>
#include <zlib.h>

using namespace signorini;

namespace
{
  /** Which of 0, 1, 2 the compressed bytes before a block boundary came
   * to modulo 3 (1 and 2: the base64 carried a byte or two across). */
  bool carried[3] = {false, false, false};

  std::vector<unsigned char>
  from_base64(const std::string &text)
  {
    static const std::string digits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> bytes;
    unsigned int               bits = 0, n_bits = 0;
    for (const char c : text)
      {
        if (c == '=')
          break;
        bits = (bits << 6) | static_cast<unsigned int>(digits.find(c));
        n_bits += 6;
        if (n_bits >= 8)
          {
            n_bits -= 8;
            bytes.push_back(static_cast<unsigned char>(bits >> n_bits));
            bits &= (1u << n_bits) - 1;
          }
      }
    return bytes;
  }

  /** The bytes of the DataArray whose text is @p text. */
  std::vector<unsigned char>
  decode(const std::string &text)
  {
    // The header's base64 stands alone: 3 + n_blocks numbers of 4 bytes.
    const auto    first = from_base64(text.substr(0, 8));
    std::uint32_t n_blocks;
    std::memcpy(&n_blocks, first.data(), 4);
    const std::size_t header_bytes = 4 * (3 + n_blocks);
    const std::size_t header_chars = 4 * ((header_bytes + 2) / 3);
    const auto        header       = from_base64(text.substr(0, header_chars));
    std::vector<std::uint32_t> numbers(3 + n_blocks);
    std::memcpy(numbers.data(), header.data(), header_bytes);
    const auto compressed = from_base64(text.substr(header_chars));
    std::vector<unsigned char> bytes;
    std::size_t                at = 0;
    for (std::uint32_t b = 0; b < n_blocks; ++b)
      {
        uLongf size = (b + 1 == n_blocks) ? numbers[2] : numbers[1];
        std::vector<unsigned char> block(size);
        if (uncompress(block.data(),
                       &size,
                       compressed.data() + at,
                       numbers[3 + b]) != Z_OK)
          return {};
        at += numbers[3 + b];
        if (b + 1 < n_blocks)
          carried[at % 3] = true;
        bytes.insert(bytes.end(), block.begin(), block.begin() + size);
      }
    return at == compressed.size() ? bytes : std::vector<unsigned char>();
  }

  /** The texts of the binary DataArrays of @p file, in order. */
  std::vector<std::string>
  arrays(const std::string &file)
  {
    std::vector<std::string> found;
    const std::string        open = "format=\"binary\">\n", close = "\n";
    for (std::size_t at = file.find(open); at != std::string::npos;
         at             = file.find(open, at))
      {
                    at += open.size();
                    found.push_back(file.substr(at, file.find(close, at) - at));
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
      for (const unsigned int threads : {1u, 2u})
        {
          std::ostringstream out;
          write_vtu(out, piece, threads);
          const auto texts = arrays(out.str());
          const bool all   = texts.size() == 5 &&
                           same(decode(texts[0]), piece.points) &&
                           same(decode(texts[1]), piece.connectivity) &&
                           same(decode(texts[2]), piece.offsets) &&
                           same(decode(texts[3]), piece.types) &&
                           same(decode(texts[4]), field.values);
          std::cout << n_points << " points, " << threads << " thread(s), "
                    << (3 * n_points * 4 + 262143) / 262144
                    << " block(s) of points: "
                    << (all ? "decoded exactly" : "FAILED") << std::endl;
        }
    }

  std::cout << "block boundaries after 1 and 2 bytes of a base64 group: "
            << (carried[1] && carried[2] ? "both met" : "FAILED: not both met")
            << std::endl;

  VtuPiece empty;
  empty.fields.push_back({"displacement", 3, {}});
  std::ostringstream out;
  write_vtu(out, empty, 1);
  std::cout << "empty piece: "
            << (out.str().find("NumberOfPoints=\"0\"") != std::string::npos &&
                    out.str().find("</VTKFile>") != std::string::npos ?
                  "valid" :
                  "FAILED")
            << std::endl;
}
