#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <sstream>

namespace signorini
{
  InputError::InputError(const std::string &entry, const std::string &message)
    : std::runtime_error(message)
    , entry(entry)
  {
  }

  InputError
  InputError::at(const std::string &location, const std::string &message)
  {
    InputError error("", message);
    error.location = location;
    return error;
  }

  namespace
  {
    std::mutex                recorded_warnings_mutex;
    std::vector<InputWarning> recorded_warnings;
  } // namespace

  void
  warn(const std::string &entry, const std::string &message)
  {
    std::lock_guard<std::mutex> lock(recorded_warnings_mutex);
    recorded_warnings.push_back({entry, message});
  }

  std::vector<InputWarning>
  take_warnings()
  {
    std::lock_guard<std::mutex> lock(recorded_warnings_mutex);
    std::vector<InputWarning>   taken;
    taken.swap(recorded_warnings);
    return taken;
  }

  std::string
  one_line(const dealii::ExceptionBase &error)
  {
    std::ostringstream info;
    error.print_info(info);
    std::string message;
    for (const char c : info.str())
      if (!std::isspace(static_cast<unsigned char>(c)))
        message += c;
      else if (!message.empty() && message.back() != ' ')
        message += ' ';
    while (!message.empty() && message.back() == ' ')
      message.pop_back();
    return message;
  }

  namespace parse
  {
    std::vector<std::string>
    split(const std::string &text, const char separator)
    {
      std::vector<std::string> items;
      std::string::size_type   begin = 0;
      while (begin <= text.size())
        {
          const auto end  = std::min(text.find(separator, begin), text.size());
          auto       item = text.substr(begin, end - begin);
          item.erase(0, item.find_first_not_of(" \t"));
          item.erase(item.find_last_not_of(" \t") + 1);
          if (!item.empty())
            items.push_back(item);
          begin = end + 1;
        }
      return items;
    }

    namespace
    {
      double
      to_double(const std::string &text, const std::string &entry)
      {
        char        *end   = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0')
          throw InputError(entry, "'" + text + "' is not a number");
        if (!std::isfinite(value))
          throw InputError(entry, "'" + text + "' is not a finite number");
        return value;
      }

      /** @p value in a message: as written in a parameter file. */
      std::string
      shown_value(const double value)
      {
        if (std::isnan(value))
          return "nan";
        if (std::isinf(value))
          return value > 0 ? "inf" : "-inf";
        return entry_text::of(value);
      }
    } // namespace

    double
    number(const std::string &text, const std::string &entry)
    {
      std::string trimmed = text;
      trimmed.erase(0, trimmed.find_first_not_of(" \t"));
      trimmed.erase(trimmed.find_last_not_of(" \t") + 1);
      return to_double(trimmed, entry);
    }

    Range
    Range::positive()
    {
      return {0., false};
    }

    Range
    Range::at_least(const double lower)
    {
      return {lower, true};
    }

    Range
    Range::open(const double lower, const double upper)
    {
      return {lower, false, upper, false};
    }

    Range
    Range::closed_open(const double lower, const double upper)
    {
      return {lower, true, upper, false};
    }

    bool
    Range::contains(const double value) const
    {
      return std::isfinite(value) &&
             (lower_included ? value >= lower : value > lower) &&
             (upper_included ? value <= upper : value < upper);
    }

    std::string
    Range::text() const
    {
      const bool bounded_below = std::isfinite(lower);
      const bool bounded_above = std::isfinite(upper);
      if (bounded_below && !bounded_above && lower == 0.)
        return lower_included ? "zero or positive" : "positive";
      std::string text;
      if (bounded_below)
        text = (lower_included ? "at least " : "above ") + shown_value(lower);
      if (bounded_above)
        text += (bounded_below ? " and " : "") +
                std::string(upper_included ? "at most " : "below ") +
                shown_value(upper);
      return text.empty() ? "a finite number" : text;
    }

    double
    in_range(const double       value,
             const Range       &range,
             const std::string &entry,
             const std::string &why)
    {
      if (!range.contains(value))
        throw InputError(entry,
                         "must be " +
                           (std::isfinite(value) ? range.text() :
                                                   "a finite number") +
                           (why.empty() ? "" : " (" + why + ")") + ", not " +
                           shown_value(value));
      return value;
    }

    template <int dim>
    dealii::Point<dim>
    point(const std::string &text, const std::string &entry)
    {
      const auto coordinates = split(text, ',');
      if (coordinates.size() != dim)
        throw InputError(entry,
                         "'" + text + "' is not a point with " +
                           std::to_string(dim) + " coordinates");
      dealii::Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = to_double(coordinates[d], entry);
      return p;
    }

    template <int dim>
    std::vector<dealii::Point<dim>>
    point_list(const std::string &text, const std::string &entry)
    {
      std::vector<dealii::Point<dim>> points;
      for (const auto &item : split(text, ';'))
        points.push_back(point<dim>(item, entry));
      return points;
    }

    std::set<dealii::types::boundary_id>
    boundary_ids(const std::string &text, const std::string &entry)
    {
      std::set<dealii::types::boundary_id> ids;
      for (const auto &item : split(text, ','))
        {
          const double value = to_double(item, entry);
          if (value < 0 || value > 255 || value != static_cast<int>(value))
            throw InputError(entry, "'" + item + "' is not a boundary id");
          ids.insert(static_cast<dealii::types::boundary_id>(value));
        }
      return ids;
    }

    std::vector<unsigned int>
    unsigned_list(const std::string &text,
                  const unsigned int n,
                  const std::string &entry)
    {
      const auto items = split(text, ',');
      if (items.size() != n)
        throw InputError(entry,
                         "'" + text + "' should hold " + std::to_string(n) +
                           " positive integers");
      std::vector<unsigned int> values;
      for (const auto &item : items)
        {
          const double value = to_double(item, entry);
          if (value < 1 || value > std::numeric_limits<unsigned int>::max() ||
              value != static_cast<unsigned int>(value))
            throw InputError(entry, "'" + item + "' is not a positive integer");
          values.push_back(static_cast<unsigned int>(value));
        }
      return values;
    }

    std::vector<bool>
    components(const std::string &text,
               const unsigned int dim,
               const std::string &entry)
    {
      std::vector<bool> mask(dim, false);
      if (text == "all")
        return std::vector<bool>(dim, true);
      for (const char c : text)
        {
          if (std::isspace(static_cast<unsigned char>(c)) || c == ',')
            continue;
          const int d = c - 'x';
          if (d < 0 || d >= static_cast<int>(dim))
            throw InputError(entry,
                             std::string("component '") + c +
                               "' is not one of " +
                               (dim == 2 ? "x, y" : "x, y, z") + " or 'all'");
          mask[d] = true;
        }
      if (std::find(mask.begin(), mask.end(), true) == mask.end())
        throw InputError(entry, "no component given in '" + text + "'");
      return mask;
    }

    template dealii::Point<1>
    point<1>(const std::string &, const std::string &);
    template dealii::Point<2>
    point<2>(const std::string &, const std::string &);
    template dealii::Point<3>
    point<3>(const std::string &, const std::string &);
    template std::vector<dealii::Point<2>>
    point_list<2>(const std::string &, const std::string &);
    template std::vector<dealii::Point<3>>
    point_list<3>(const std::string &, const std::string &);
  } // namespace parse
} // namespace signorini
