#include <signorini/base/text.h>

#include <cstdio>

namespace signorini
{
  std::string
  number(const double x)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g", x);
    return text;
  }
} // namespace signorini
