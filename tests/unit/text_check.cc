// The checks of text input: where the first byte that is not text, or the
// first character that only looks like white space or punctuation, is, and
// what it is; messages made printable. The line and column of each
// problem (columns count characters, not bytes) and whether it makes the
// file binary are checked against those written in the table below.

#include <signorini/input/text_check.h>

#include "checks.h"
#include <iostream>
#include <string>

using namespace signorini;

namespace
{
  /** Prints the problem of @p bytes as @p check finds it; returns
   * whether it is at @p expected ("LINE:COLUMN", "LINE:COLUMN binary" or
   * "text"). */
  template <typename Check>
  bool
  show(const std::string &name,
       const std::string &bytes,
       const Check       &check,
       const std::string &expected)
  {
    std::cout << "  " << name << ": ";
    std::string found = "text";
    if (const auto problem = check(bytes))
      {
        found = std::to_string(problem->line) + ':' +
                std::to_string(problem->column) +
                (problem->binary ? " binary" : "");
        std::cout << problem->line << ':' << problem->column << ' '
                  << (problem->binary ? "binary " : "") << problem->what
                  << '\n';
      }
    else
      std::cout << "text\n";
    if (found != expected)
      std::cout << "  FAILED: expected " << expected << '\n';
    return found == expected;
  }
} // namespace

int
main()
{
  const std::string nbsp = "\xc2\xa0", bom = "\xef\xbb\xbf";
  // Name, bytes, where first_non_text and first_unexpected find a problem.
  struct Case
  {
    const char *name;
    std::string bytes, non_text, unexpected;
  };
  const Case cases[] = {
    {"ASCII", "set a = 1\nset b = 2\n", "text", "text"},
    {"UTF-8 comment",
     "# \xce\xbd = 0.3, 10 \xc3\x97 1 mm\nset a = 1\n",
     "text",
     "text"},
    {"UTF-8 value", "set Directory = r\xc3\xa9sultats\n", "text", "text"},
    {"CRLF", "set a = 1\r\nset b = 2\r\n", "text", "text"},
    {"tab", "set\ta = 1\n", "text", "text"},
    {"BOM at start", bom + "set a = 1\n", "text", "text"},
    {"BOM later", "set a = 1\n" + bom + "set b = 2\n", "text", "2:1"},
    {"no-break space", "set a" + nbsp + "= 1\n", "text", "1:6"},
    {"no-break space in comment",
     "set a = 1 # a" + nbsp + "b\n",
     "text",
     "text"},
    {"zero-width space", "set a = 1\u200b\n", "text", "1:10"},
    {"minus sign",
     "set a = \u2212"
     "1\n",
     "text",
     "1:9"},
    {"typographic quote", "set Young\u2019s modulus = 1\n", "text", "1:10"},
    {"column after a 2-byte character",
     "# \xc3\xa9\n\xc3\xa9" + nbsp + "\n",
     "text",
     "2:2"},
    {"NUL",
     std::string("set a = 1\nset b\0 = 2\n", 18),
     "2:6 binary",
     "2:6 binary"},
    {"NUL after a control character",
     std::string("\x1b[0m\nx\0", 7),
     "2:2 binary",
     "2:2 binary"},
    {"control character", "set a = 1\x1b[0m\n", "1:10", "1:10"},
    {"Latin-1", "set a = r\xe9sultats\n", "1:10 binary", "1:10 binary"},
    {"truncated UTF-8", "set a = \xc3", "1:9 binary", "1:9 binary"},
    {"overlong UTF-8", "set a = \xc0\xaf\n", "1:9 binary", "1:9 binary"},
    {"surrogate", "set a = \xed\xa0\x80\n", "1:9 binary", "1:9 binary"},
    {"beyond U+10FFFF",
     "set a = \xf4\x90\x80\x80\n",
     "1:9 binary",
     "1:9 binary"},
    {"DEL", "set a = 1\x7f\n", "1:10", "1:10"}};

  bool where = true;
  std::cout << "first_non_text:\n";
  for (const auto &c : cases)
    where &= show(c.name, c.bytes, text_check::first_non_text, c.non_text);
  std::cout << "first_unexpected:\n";
  for (const auto &c : cases)
    where &= show(c.name, c.bytes, text_check::first_unexpected, c.unexpected);
  checks::expect("each problem where the table says", where);

  std::cout << "printable:\n";
  for (const std::string &text : {std::string("plain \xce\xbd \xc3\x97"),
                                  std::string("tab\there"),
                                  std::string("nul\0cut", 7),
                                  std::string("esc\x1b[31mred"),
                                  std::string("bytes \xff\xfe end"),
                                  "no-break" + nbsp + "space",
                                  "bom" + bom,
                                  std::string("DEL\x7f")})
    std::cout << "  [" << text_check::printable(text) << "]\n";
  std::string long_text;
  for (unsigned int i = 0; i < 1000; ++i)
    long_text += std::to_string(i % 10);
  const std::string shortened = text_check::printable(long_text, 40);
  std::cout << "  1000 digits, at most 40: [" << shortened << "] ("
            << shortened.size() << " characters)\n";
  std::cout << "  40 digits, at most 40: ["
            << text_check::printable(long_text.substr(0, 40), 40) << "]\n";
  // What is kept: the first and the last digits, at most 40 in all, and the
  // number of those left out between them.
  const auto        gap  = shortened.find(" [... ");
  const auto        rest = shortened.find(" characters left out ...] ");
  const std::string head = shortened.substr(0, gap);
  const std::string tail =
    rest == std::string::npos ? "" : shortened.substr(rest + 26);
  checks::expect(
    "1000 digits: the first and last kept, at most 40, the rest counted",
    gap != std::string::npos && rest != std::string::npos &&
      head.size() + tail.size() <= 40 &&
      long_text.compare(0, head.size(), head) == 0 &&
      long_text.compare(1000 - tail.size(), tail.size(), tail) == 0 &&
      shortened.substr(gap + 6, rest - gap - 6) ==
        std::to_string(1000 - head.size() - tail.size()));
  checks::expect("40 digits kept whole",
                 text_check::printable(long_text.substr(0, 40), 40) ==
                   long_text.substr(0, 40));
}
