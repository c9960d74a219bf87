#include <signorini/base/statistics_row.h>

#include <cstdio>
#include <stdexcept>

namespace signorini
{
  void
  StatisticsRow::add(const std::string &name, const double value)
  {
    names.push_back(name);
    values.push_back(value);
    counts.push_back(false);
  }

  void
  StatisticsRow::add_count(const std::string &name, const std::uint64_t value)
  {
    names.push_back(name);
    values.push_back(static_cast<double>(value));
    counts.push_back(true);
  }

  double
  StatisticsRow::value(const std::string &name) const
  {
    for (unsigned int i = 0; i < names.size(); ++i)
      if (names[i] == name)
        return values[i];
    throw std::out_of_range("statistics row: no column '" + name + "'");
  }

  std::string
  StatisticsRow::header() const
  {
    std::string text;
    for (unsigned int i = 0; i < names.size(); ++i)
      text += (i > 0 ? "," : "") + names[i];
    return text;
  }

  std::string
  StatisticsRow::line() const
  {
    std::string text;
    char        number[32];
    for (unsigned int i = 0; i < values.size(); ++i)
      {
        if (counts[i])
          std::snprintf(number,
                        sizeof(number),
                        "%llu",
                        static_cast<unsigned long long>(values[i]));
        else
          std::snprintf(number, sizeof(number), "%.10e", values[i]);
        text += (i > 0 ? "," : "") + std::string(number);
      }
    return text;
  }
} // namespace signorini
