#ifndef signorini_input_parameter_file_h
#define signorini_input_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/input/input_error.h>

#include <optional>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * A parameter file and the files it includes, read once into one text
   * that ParameterHandler parses from memory, with the place of each of its
   * lines, so that errors read "FILE:LINE: what is wrong".
   *
   * Lines are read as ParameterHandler reads them: comments after '#',
   * continuation lines ending in '\'. The text of an included file takes the
   * place of its `include` line. Included files are named relative to the
   * folder of the top file, at any depth (as ParameterHandler opens them
   * when the current folder is that one); the current folder is not
   * changed. Errors name the top file as it was given and an included file
   * as its `include` line names it, except errors of the `include` lines,
   * which name the included file's path from the current folder.
   *
   * Files whose name ends in .xml or .json are left to ParameterHandler,
   * which reads them whole (they have no `include` lines).
   */
  class ParameterFile
  {
  public:
    /**
     * Reads @p file and the files it includes. Throws an InputError at
     * "FILE:LINE" of an `include` line that closes a cycle of includes,
     * names a directory, or names a file that cannot be opened; at
     * "FILE:LINE:COLUMN" of a byte that is not text, or of a character
     * outside a comment that only looks like a space, a quote or a minus
     * (see text_check::first_unexpected); for a file whose name does not
     * end in .prm, .xml or .json; and for a .prm file that, with the
     * files it includes, sets no entry. A byte-order mark at the start of
     * a file is skipped.
     */
    explicit ParameterFile(const std::string &file);

    /**
     * Reads the entries into @p prm, whose entries are declared; with
     * @p skip_undefined, entries and subsections that are not declared are
     * skipped. Throws an InputError for the first error in the order of the
     * text, located at "FILE:LINE" if it is one of a line.
     */
    void
    parse(dealii::ParameterHandler &prm,
          const bool                skip_undefined = false) const;

    /** The folders in which relative file names in entries are looked for,
     * in order: the top file's folder, then those of the included files,
     * in the order they are included, each once. */
    const std::vector<std::string> &
    folders() const;

    /** "FILE:LINE" of the last line that sets @p entry ("Subsection/Name")
     * if that line is in an included file (FILE as its `include` line
     * names it); empty otherwise. */
    std::optional<std::string>
    included_setting(const std::string &entry) const;

  private:
    /** A line of the text: what ParameterHandler reads, the name of the
     * file it is from as ParameterHandler would name it, and its number
     * there as ParameterHandler gives it. */
    struct Line
    {
      std::string  text;
      std::string  file;
      unsigned int number;
    };

    /** An included file whose `subsection` and `end` lines do not balance,
     * which ParameterHandler refuses at its end. */
    struct Unbalanced
    {
      /** The lines of the text before the end of that file. */
      std::size_t n_lines;
      /** The depth of subsections open there. */
      std::size_t depth;
      InputError  error;
    };

    class Reader;

    /** The error of the message of a ParameterHandler exception, located
     * in the file and line that the message's line of the text is from. */
    InputError
    located(const std::string &message) const;

    /** The file as given. */
    std::string file;
    /** Its absolute path, the name under which ParameterHandler reads it. */
    std::string path;
    /** Whether ParameterHandler reads the file itself (.xml, .json). */
    bool whole = false;
    /** Whether the file's name ends in .prm, .xml or .json, the formats
     * ParameterHandler reads. */
    bool known = false;
    /** Whether a line of the text sets an entry. */
    bool                      sets_entries = false;
    std::vector<Line>         lines;
    std::optional<Unbalanced> unbalanced;
    std::vector<std::string>  folder_list;
  };
} // namespace signorini

#endif
