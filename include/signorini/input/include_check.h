#ifndef signorini_input_include_check_h
#define signorini_input_include_check_h

#include <string>
#include <vector>

namespace signorini
{
  /**
   * Follows the `include` lines of the parameter file @p file, and of the
   * files it includes, before deal.II's ParameterHandler reads them: that
   * parser recurses without end on a cycle of includes and reads a
   * directory as an empty file. Lines are read as ParameterHandler reads
   * them (comments after '#', continuation lines ending in '\'); included
   * files are named relative to the folder of @p file, as ParameterHandler
   * opens them there.
   *
   * Throws an InputError located at "FILE:LINE" of the `include` line for
   * an include that closes a cycle, names a directory, or names a file that
   * cannot be opened. FILE is @p file for the top file and the included
   * file's path from the current folder otherwise.
   *
   * Returns the folders of the included files, in the order they are
   * included, each once.
   */
  std::vector<std::string>
  check_includes(const std::string &file);
} // namespace signorini

#endif
