#ifndef signorini_base_statistics_row_h
#define signorini_base_statistics_row_h

#include <cstdint>
#include <string>
#include <vector>

namespace signorini
{
  /** One row of statistics.csv: named columns in their order. */
  class StatisticsRow
  {
  public:
    /** Adds a column written as a number with 11 significant digits. */
    void
    add(const std::string &name, const double value);

    /** Adds a column written as a whole number. */
    void
    add_count(const std::string &name, const std::uint64_t value);

    /** The value of the column @p name; throws std::out_of_range if the row
     * has no such column. */
    double
    value(const std::string &name) const;

    /** The header line (names separated by ','). */
    std::string
    header() const;

    /** The row as a line of statistics.csv. */
    std::string
    line() const;

    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &names &values &counts;
    }

  private:
    std::vector<std::string> names;
    std::vector<double>      values;
    /** Whether each column is a whole number. */
    std::vector<bool> counts;
  };
} // namespace signorini

#endif
