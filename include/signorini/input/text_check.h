#ifndef signorini_input_text_check_h
#define signorini_input_text_check_h

#include <optional>
#include <string>

namespace signorini
{
  /**
   * What a file that should be text holds instead, and where: the checks
   * that a parameter file, the files it includes and a .msh mesh pass
   * before they are parsed, so that a binary file, a file in another
   * encoding or an invisible character is named as such rather than as a
   * line that "could not be parsed". Every check reads each byte once.
   */
  namespace text_check
  {
    /** The first character of a text that is not what it should be. */
    struct Problem
    {
      /** Line and column (in characters, from 1). */
      unsigned int line   = 0;
      unsigned int column = 0;
      /** What it is, e.g. "a NUL byte", "a no-break space U+00A0". */
      std::string what;
      /** Whether the file is not text at all (binary, or not UTF-8), as
       * opposed to text with an unwanted character. */
      bool binary = false;
    };

    /**
     * The first byte of @p bytes that UTF-8 text cannot hold: a NUL byte or
     * a byte that is not UTF-8 (the file is binary), else the first control
     * character other than tab, line feed and carriage return.
     */
    std::optional<Problem>
    first_non_text(const std::string &bytes);

    /**
     * The first non-text byte of a parameter file (as first_non_text()) or
     * the first character outside a comment (the text from '#' to the end
     * of the line) that looks like white space or punctuation of a
     * parameter file but is not: a no-break space, a zero-width space, a
     * byte-order mark (except at the start of the file), a typographic
     * quote or dash, a minus sign U+2212, and the like.
     */
    std::optional<Problem>
    first_unexpected(const std::string &bytes);

    /** Whether @p bytes starts with the UTF-8 byte-order mark. */
    bool
    starts_with_bom(const std::string &bytes);

    /**
     * @p text fit for a one-line message on a terminal: valid UTF-8
     * characters that print are kept; control characters, bytes that are
     * not UTF-8 and invisible characters become escapes ("\x00", "\xff",
     * "<U+00A0>"); a text longer than @p max_length characters keeps its
     * beginning and end around a note of how much was left out.
     */
    std::string
    printable(const std::string &text, const std::size_t max_length = 400);
  } // namespace text_check
} // namespace signorini

#endif
