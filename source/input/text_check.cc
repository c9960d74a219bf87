#include <signorini/input/text_check.h>

#include <cstdio>
#include <vector>

namespace signorini
{
  namespace text_check
  {
    namespace
    {
      /** A character of UTF-8 text, or a byte that is not one. */
      struct Character
      {
        /** The code point; for a byte that is not UTF-8, the byte. */
        unsigned int code = 0;
        /** Its bytes. */
        std::size_t size  = 1;
        bool        valid = true;
      };

      /** The character that starts at byte @p i of @p bytes. */
      Character
      decode_utf8(const std::string &bytes, const std::size_t i)
      {
        const auto byte = [&](const std::size_t k) -> unsigned int {
          return static_cast<unsigned char>(bytes[k]);
        };
        const unsigned int first = byte(i);
        Character          c;
        c.code = first;
        if (first < 0x80)
          return c;
        std::size_t  size = 0;
        unsigned int code = 0, lowest = 0;
        if ((first & 0xE0) == 0xC0)
          size = 2, code = first & 0x1F, lowest = 0x80;
        else if ((first & 0xF0) == 0xE0)
          size = 3, code = first & 0x0F, lowest = 0x800;
        else if ((first & 0xF8) == 0xF0)
          size = 4, code = first & 0x07, lowest = 0x10000;
        c.valid = false;
        if (size == 0 || i + size > bytes.size())
          return c;
        for (std::size_t k = 1; k < size; ++k)
          {
            if ((byte(i + k) & 0xC0) != 0x80)
              return c;
            code = (code << 6) | (byte(i + k) & 0x3F);
          }
        // Overlong forms, surrogates and code points beyond Unicode are not
        // UTF-8.
        if (code < lowest || (code >= 0xD800 && code <= 0xDFFF) ||
            code > 0x10FFFF)
          return c;
        return {code, size, true};
      }

      /** "U+00A0". */
      std::string
      code_point(const unsigned int code)
      {
        char text[16];
        std::snprintf(text, sizeof(text), "U+%04X", code);
        return text;
      }

      /** "\x1b". */
      std::string
      byte_escape(const unsigned int byte)
      {
        char text[8];
        std::snprintf(text, sizeof(text), "\\x%02x", byte);
        return text;
      }

      /** A character that looks like white space or punctuation of a
       * parameter file but is not, with its name and what to write
       * instead. */
      struct Lookalike
      {
        unsigned int first, last;
        const char  *name;
        const char  *instead;
        /** Whether it shows nothing on a terminal. */
        bool invisible;
      };

      const Lookalike lookalikes[] = {
        {0x0080, 0x009F, "a control character", "delete it", true},
        {0x00A0, 0x00A0, "a no-break space", "write a space", true},
        {0x00AD, 0x00AD, "a soft hyphen", "delete it", true},
        {0x1680, 0x1680, "an Ogham space mark", "write a space", true},
        {0x2000, 0x200A, "a typographic space", "write a space", true},
        {0x200B, 0x200B, "a zero-width space", "delete it", true},
        {0x200C, 0x200D, "a zero-width joiner", "delete it", true},
        {0x200E, 0x200F, "a direction mark", "delete it", true},
        {0x2010, 0x2015, "a dash", "write '-'", false},
        {0x2018, 0x201B, "a typographic quote", "write '", false},
        {0x201C, 0x201F, "a typographic double quote", "write \"", false},
        {0x2028, 0x2029, "a line separator", "write a line break", true},
        {0x202A, 0x202E, "a direction control", "delete it", true},
        {0x202F, 0x202F, "a narrow no-break space", "write a space", true},
        {0x205F, 0x205F, "a mathematical space", "write a space", true},
        {0x2060, 0x2064, "a word joiner", "delete it", true},
        {0x2066, 0x2069, "a direction control", "delete it", true},
        {0x2212, 0x2212, "a minus sign", "write '-'", false},
        {0x3000, 0x3000, "an ideographic space", "write a space", true},
        {0xFEFF, 0xFEFF, "a byte-order mark", "delete it", true}};

      const Lookalike *
      lookalike(const unsigned int code)
      {
        for (const auto &l : lookalikes)
          if (code >= l.first && code <= l.last)
            return &l;
        return nullptr;
      }

      /** Whether the byte @p code is a control character that text may
       * hold. */
      bool
      allowed_control(const unsigned int code)
      {
        return code == '\t' || code == '\n' || code == '\r';
      }

      /** What a scan looks for: bytes that are not text; also control
       * characters; also lookalikes outside comments. */
      enum class Look
      {
        binary,
        controls,
        lookalikes
      };

      /** The first problem of @p bytes of the kinds @p look asks for. */
      std::optional<Problem>
      scan_text(const std::string &bytes, const Look look)
      {
        unsigned int line = 1, column = 0;
        bool         comment = false;
        std::size_t  i       = starts_with_bom(bytes) ? 3 : 0;
        for (; i < bytes.size();)
          {
            const Character c = decode_utf8(bytes, i);
            ++column;
            Problem problem;
            problem.line   = line;
            problem.column = column;
            if (!c.valid)
              {
                problem.what = "not UTF-8 text: the byte " +
                               byte_escape(c.code) +
                               " (save the file as UTF-8)";
                problem.binary = true;
                return problem;
              }
            if (c.code == 0)
              {
                problem.what   = "not a text file: a NUL byte";
                problem.binary = true;
                return problem;
              }
            if ((c.code < 0x20 || c.code == 0x7F) && !allowed_control(c.code) &&
                look != Look::binary)
              {
                problem.what = "the control character " + byte_escape(c.code) +
                               "; delete it";
                return problem;
              }
            if (look == Look::lookalikes && !comment)
              if (const auto l = lookalike(c.code))
                {
                  problem.what =
                    std::string(l->name) + " " + code_point(c.code) +
                    (l->invisible ? " (invisible)" : "") + "; " + l->instead;
                  return problem;
                }
            if (c.code == '#')
              comment = true;
            if (c.code == '\n')
              {
                ++line;
                column  = 0;
                comment = false;
              }
            i += c.size;
          }
        return {};
      }
    } // namespace

    bool
    starts_with_bom(const std::string &bytes)
    {
      return bytes.compare(0, 3, "\xEF\xBB\xBF") == 0;
    }

    std::optional<Problem>
    first_non_text(const std::string &bytes)
    {
      auto problem = scan_text(bytes, Look::controls);
      if (problem && !problem->binary)
        if (const auto binary = scan_text(bytes, Look::binary))
          return binary;
      return problem;
    }

    std::optional<Problem>
    first_unexpected(const std::string &bytes)
    {
      // A binary file is called binary, whatever comes first.
      auto problem = scan_text(bytes, Look::lookalikes);
      if (problem && !problem->binary)
        if (const auto binary = scan_text(bytes, Look::binary))
          return binary;
      return problem;
    }

    std::string
    printable(const std::string &text, const std::size_t max_length)
    {
      // One printable unit per character, then the long ones shortened.
      std::vector<std::string> units;
      for (std::size_t i = 0; i < text.size();)
        {
          const Character c = decode_utf8(text, i);
          if (!c.valid || c.code == 0x7F)
            units.push_back(byte_escape(c.code));
          else if (c.code == '\t')
            units.emplace_back(" ");
          else if (c.code < 0x20)
            units.push_back(byte_escape(c.code));
          else if (const auto l = lookalike(c.code); l && l->invisible)
            units.push_back("<" + code_point(c.code) + ">");
          else
            units.push_back(text.substr(i, c.size));
          i += c.size;
        }
      std::string result;
      if (units.size() <= max_length)
        {
          for (const auto &unit : units)
            result += unit;
          return result;
        }
      const std::size_t head = max_length * 2 / 3, tail = max_length / 4;
      for (std::size_t k = 0; k < head; ++k)
        result += units[k];
      // Long runs counted in thousands: the count does not change with the
      // length of a path in the message.
      const std::size_t left_out = units.size() - head - tail;
      result += " [... " +
                (left_out < 1000 ?
                   std::to_string(left_out) :
                   "about " + std::to_string((left_out + 500) / 1000) + "k") +
                " characters left out ...] ";
      for (std::size_t k = units.size() - tail; k < units.size(); ++k)
        result += units[k];
      return result;
    }
  } // namespace text_check
} // namespace signorini
