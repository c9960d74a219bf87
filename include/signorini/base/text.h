#ifndef signorini_base_text_h
#define signorini_base_text_h

#include <string>

namespace signorini
{
  /** @p x with three significant digits, for messages. */
  std::string
  number(const double x);
} // namespace signorini

#endif
