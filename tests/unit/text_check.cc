// The checks of text input: where the first byte that is not text, or the
// first character that only looks like white space or punctuation, is, and
// what it is; messages made printable.

#include <signorini/input/text_check.h>

#include <iostream>
#include <string>

using namespace signorini;

namespace
{
  /** Prints the problem of @p bytes as @p check finds it. */
  template <typename Check>
  void
  show(const std::string &name, const std::string &bytes, const Check &check)
  {
    std::cout << "  " << name << ": ";
    if (const auto problem = check(bytes))
      std::cout << problem->line << ':' << problem->column << ' '
                << (problem->binary ? "binary " : "") << problem->what << '\n';
    else
      std::cout << "text\n";
  }
} // namespace

int
main()
{
  const std::string nbsp = "\xc2\xa0", bom = "\xef\xbb\xbf";
  const std::pair<const char *, std::string> cases[] = {
    {"ASCII", "set a = 1\nset b = 2\n"},
    {"UTF-8 comment", "# \xce\xbd = 0.3, 10 \xc3\x97 1 mm\nset a = 1\n"},
    {"UTF-8 value", "set Directory = r\xc3\xa9sultats\n"},
    {"CRLF", "set a = 1\r\nset b = 2\r\n"},
    {"tab", "set\ta = 1\n"},
    {"BOM at start", bom + "set a = 1\n"},
    {"BOM later", "set a = 1\n" + bom + "set b = 2\n"},
    {"no-break space", "set a" + nbsp + "= 1\n"},
    {"no-break space in comment", "set a = 1 # a" + nbsp + "b\n"},
    {"zero-width space", "set a = 1\u200b\n"},
    {"minus sign",
     "set a = \u2212"
     "1\n"},
    {"typographic quote", "set Young\u2019s modulus = 1\n"},
    {"column after a 2-byte character", "# \xc3\xa9\n\xc3\xa9" + nbsp + "\n"},
    {"NUL", std::string("set a = 1\nset b\0 = 2\n", 18)},
    {"NUL after a control character", std::string("\x1b[0m\nx\0", 7)},
    {"control character", "set a = 1\x1b[0m\n"},
    {"Latin-1", "set a = r\xe9sultats\n"},
    {"truncated UTF-8", "set a = \xc3"},
    {"overlong UTF-8", "set a = \xc0\xaf\n"},
    {"surrogate", "set a = \xed\xa0\x80\n"},
    {"beyond U+10FFFF", "set a = \xf4\x90\x80\x80\n"},
    {"DEL", "set a = 1\x7f\n"}};

  std::cout << "first_non_text:\n";
  for (const auto &[name, bytes] : cases)
    show(name, bytes, text_check::first_non_text);
  std::cout << "first_unexpected:\n";
  for (const auto &[name, bytes] : cases)
    show(name, bytes, text_check::first_unexpected);

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
}
