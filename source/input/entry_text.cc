#include <signorini/input/entry_text.h>

#include <charconv>

namespace signorini
{
  namespace entry_text
  {
    std::string
    of(const double value)
    {
      // std::to_chars without a precision gives the shortest text that
      // reads back as the same double.
      char              buffer[64];
      const auto        plain = std::to_chars(buffer,
                                       buffer + sizeof(buffer),
                                       value,
                                       std::chars_format::fixed);
      const std::string fixed(buffer, plain.ptr);
      const auto        exponent_form = std::to_chars(buffer,
                                               buffer + sizeof(buffer),
                                               value,
                                               std::chars_format::scientific);
      // "2.1e+05" -> "2.1e5", "1e-12" stays.
      const std::string scientific(buffer, exponent_form.ptr);
      const auto        e = scientific.find('e');
      const std::string compact =
        scientific.substr(0, e) + "e" +
        std::to_string(std::stoi(scientific.substr(e + 1)));
      return compact.size() < fixed.size() ? compact : fixed;
    }

    std::string
    of(const unsigned int value)
    {
      return std::to_string(value);
    }

    std::string
    of(const bool value)
    {
      return value ? "true" : "false";
    }

    std::string
    of(const std::string &value)
    {
      return value;
    }

    std::string
    of(const std::optional<double> &value)
    {
      return value ? of(*value) : "";
    }

    template <int dim>
    std::string
    of(const dealii::Point<dim> &point)
    {
      std::string text;
      for (unsigned int d = 0; d < dim; ++d)
        text += (d == 0 ? "" : ", ") + of(point[d]);
      return text;
    }

    template <int dim>
    std::string
    of(const std::vector<dealii::Point<dim>> &points)
    {
      std::string text;
      for (const auto &point : points)
        text += (text.empty() ? "" : "; ") + of(point);
      return text;
    }

    std::string
    of(const std::vector<unsigned int> &values)
    {
      std::string text;
      for (const auto value : values)
        text += (text.empty() ? "" : ", ") + of(value);
      return text;
    }

    template std::string
    of(const dealii::Point<2> &);
    template std::string
    of(const dealii::Point<3> &);
    template std::string
    of(const std::vector<dealii::Point<2>> &);
    template std::string
    of(const std::vector<dealii::Point<3>> &);
  } // namespace entry_text
} // namespace signorini
