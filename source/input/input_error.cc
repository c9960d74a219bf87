#include <signorini/input/input_error.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
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
        return value;
      }
    } // namespace

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
          if (value < 1 || value != static_cast<unsigned int>(value))
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
