// CheckpointManifest, the text of a checkpoint's state file: read back as
// written; every truncation and every single-bit change of the text
// refused (CRC-32 detects every error of one bit); a state file of the
// format before checksums named as such. checksum_of_file against the
// CRC-32 check value of "123456789" (0xcbf43926); the checksums of slices
// of a file joined equal the whole file's. verify_pieces on pieces intact,
// shorter, longer, changed and missing. Each is checked (PASS, or "yes"),
// not only printed.

#include <signorini/output/checkpoint_manifest.h>

#include "checks.h"
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

using namespace signorini;
namespace fs = std::filesystem;

namespace
{
  void
  write_file(const std::string &path, const std::string &bytes)
  {
    std::ofstream(path, std::ios::binary) << bytes;
  }

  /** The first words of a fault, up to its parenthesis. */
  std::string
  kind(const std::string &fault)
  {
    return fault.substr(0, fault.find(" ("));
  }
} // namespace

int
main()
{
  const std::string directory = "pieces";
  fs::remove_all(directory);
  fs::create_directory(directory);

  write_file(directory + "/check.txt", "123456789");
  const auto check = checksum_of_file(directory + "/check.txt");
  std::printf("checksum_of_file(\"123456789\"): size %llu, crc32 %08x "
              "(check value cbf43926): %s\n",
              static_cast<unsigned long long>(check.size),
              check.crc,
              check.crc == 0xcbf43926u && check.size == 9 ? "PASS" : "FAIL");
  if (check.crc != 0xcbf43926u || check.size != 9)
    checks::failed();

  std::string mesh(5000, ' ');
  for (unsigned int i = 0; i < mesh.size(); ++i)
    mesh[i] = static_cast<char>((31 * i + i / 7) % 256);
  const std::string info = "version 4\n";
  write_file(directory + "/checkpoint-03.mesh", mesh);
  write_file(directory + "/checkpoint-03.mesh.info", info);

  // The checksums of slices, as the processes of a parallel run compute
  // them, joined: that of the whole file, for any number of slices.
  for (const unsigned int n : {1u, 2u, 3u, 7u, 6000u})
    {
      FileChecksum joined;
      for (unsigned int i = 0; i < n; ++i)
        joined = concatenate(joined,
                             checksum_of_file(directory + "/checkpoint-03.mesh",
                                              5000ull * i / n,
                                              5000ull * (i + 1) / n -
                                                5000ull * i / n));
      const auto whole = checksum_of_file(directory + "/checkpoint-03.mesh");
      std::printf("%u slices joined: size %llu, crc32 %08x, whole %08x: %s\n",
                  n,
                  static_cast<unsigned long long>(joined.size),
                  joined.crc,
                  whole.crc,
                  joined.crc == whole.crc && joined.size == 5000 ? "PASS" :
                                                                   "FAIL");
      if (joined.crc != whole.crc || joined.size != 5000)
        checks::failed();
    }

  CheckpointManifest written;
  written.cycle      = 3;
  written.parameters = "set Dimension = 2\nsubsection Output\nend\n";
  written.state      = std::string("binary\0state\n\xff", 14);
  for (const std::string name :
       {"checkpoint-03.mesh", "checkpoint-03.mesh.info"})
    written.pieces.push_back({name, checksum_of_file(directory + "/" + name)});
  const std::string text = written.text();

  CheckpointManifest read;
  const std::string  fault = read.read(text);
  const bool         same =
    fault.empty() && read.cycle == 3 && read.parameters == written.parameters &&
    read.state == written.state && read.pieces.size() == 2 &&
    read.pieces[0].name == "checkpoint-03.mesh" &&
    read.pieces[0].checksum.size == 5000 &&
    read.pieces[1].checksum.crc == written.pieces[1].checksum.crc;
  std::cout << "read back (" << text.size()
            << " bytes): " << (same ? "PASS" : "FAIL " + fault) << '\n';
  if (!same)
    checks::failed();

  std::map<std::string, unsigned int> truncations;
  for (std::size_t size = 0; size < text.size(); ++size)
    truncations[kind(CheckpointManifest().read(text.substr(0, size)))] += 1;
  std::cout << "every truncation refused (" << text.size() << "):\n";
  for (const auto &[what, count] : truncations)
    std::cout << "  " << (what.empty() ? "ACCEPTED" : what) << ": " << count
              << '\n';
  checks::expect("none accepted", truncations.count("") == 0);

  std::map<std::string, unsigned int> flips;
  for (std::size_t i = 0; i < text.size(); ++i)
    for (unsigned int bit = 0; bit < 8; ++bit)
      {
        std::string changed = text;
        changed[i] ^= static_cast<char>(1u << bit);
        flips[kind(CheckpointManifest().read(changed))] += 1;
      }
  std::cout << "every one-bit change refused (" << 8 * text.size() << "):\n";
  for (const auto &[what, count] : flips)
    std::cout << "  " << (what.empty() ? "ACCEPTED" : what) << ": " << count
              << '\n';
  checks::expect("none accepted", flips.count("") == 0);

  // Older formats and other files refused, each with its own reason.
  const auto refused = [](const std::string &label,
                          const std::string &text,
                          const std::string &words) {
    const std::string fault = CheckpointManifest().read(text);
    std::cout << label << ": " << fault << '\n';
    if (fault.find(words) == std::string::npos)
      {
        std::cout << "  FAILED: not \"" << words << "\"\n";
        checks::failed();
      }
  };
  refused("format 1",
          "signorini checkpoint 1\ncycle 3\n",
          "written by an earlier signorini, without checksums");
  refused("format 2",
          "signorini checkpoint 2\ncycle 3\n",
          "written by an earlier signorini, which stored the solution cell");
  {
    // A whole state file of format 2: its own checksum matches.
    const std::string body =
      "signorini checkpoint 2\n" +
      text.substr(text.find('\n') + 1, text.size() - 15 - text.find('\n') - 1);
    write_file(directory + "/format2.txt", body);
    char crc[16];
    std::snprintf(crc,
                  sizeof(crc),
                  "crc32 %08x\n",
                  checksum_of_file(directory + "/format2.txt").crc);
    refused("format 2, whole",
            body + crc,
            "written by an earlier signorini, which stored the solution cell");
  }
  refused("other text", "hello\n", "not a signorini checkpoint");

  // Each case's fault must name the piece and say what is wrong with it.
  const auto verify = [&](const std::string &label,
                          const std::string &piece,
                          const std::string &words) {
    const std::string fault = read.verify_pieces(directory);
    std::cout << "  " << label << ": " << (fault.empty() ? "(no fault)" : fault)
              << '\n';
    if (words.empty() ? !fault.empty() :
                        fault.find(directory + "/" + piece + ": " + words) ==
                          std::string::npos)
      {
        std::cout << "  FAILED: not \"" << piece << ": " << words << "\"\n";
        checks::failed();
      }
  };
  std::cout << "verify_pieces:\n";
  verify("intact", "", "");
  write_file(directory + "/checkpoint-03.mesh", mesh.substr(0, 4000));
  verify("shorter", "checkpoint-03.mesh", "truncated (4000 of 5000 bytes)");
  write_file(directory + "/checkpoint-03.mesh", mesh + "m");
  verify("longer", "checkpoint-03.mesh", "damaged (5001 bytes");
  std::string changed = mesh;
  changed[2500] ^= 1;
  write_file(directory + "/checkpoint-03.mesh", changed);
  verify("changed", "checkpoint-03.mesh", "damaged");
  write_file(directory + "/checkpoint-03.mesh", mesh);
  fs::remove(directory + "/checkpoint-03.mesh.info");
  verify("missing", "checkpoint-03.mesh.info", "missing");
  fs::remove_all(directory);
}
