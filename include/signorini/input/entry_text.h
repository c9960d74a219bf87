#ifndef signorini_input_entry_text_h
#define signorini_input_entry_text_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <signorini/input/input_error.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * Values written as the text of a parameter entry, the form in which
   * `declare_parameters` gives the defaults of a default-constructed
   * parameter struct to ParameterHandler. Each text reads back as the same
   * value with the parsers of the `parse` namespace.
   */
  namespace entry_text
  {
    /** The shortest decimal text that reads back as @p value: exponent form
     * ("2.1e5", "1e-12") where it is shorter, plain form ("0.3", "0.03")
     * otherwise. */
    std::string
    of(const double value);

    /** The decimal digits of @p value. */
    std::string
    of(const unsigned int value);

    /** "true" or "false". */
    std::string
    of(const bool value);

    /** @p value itself. */
    std::string
    of(const std::string &value);

    /** Not a bool: a string literal is an std::string. */
    std::string
    of(const char *value) = delete;

    /** The number, or the empty text if there is none. */
    std::string
    of(const std::optional<double> &value);

    /** "x, y[, z]". */
    template <int dim>
    std::string
    of(const dealii::Point<dim> &point);

    /** Points separated by "; ", e.g. "10, 0; 5, 1". */
    template <int dim>
    std::string
    of(const std::vector<dealii::Point<dim>> &points);

    /** Integers separated by ", ", e.g. "20, 2". */
    std::string
    of(const std::vector<unsigned int> &values);
  } // namespace entry_text

  /**
   * The values an entry chooses from (the values of an enum, say) with
   * their names in a parameter file, in the order in which
   * `--print-parameters` lists them, each perhaps with a description.
   * pattern() makes the entry a Patterns::Selection of the names; name()
   * gives the default's text; value() maps the selected name back to its
   * value; documentation() describes every choice.
   */
  template <typename T>
  class Choices
  {
  public:
    Choices(std::initializer_list<std::pair<T, std::string>> choices)
      : choices(choices)
    {
    }

    /** Choices with their descriptions: (value, name, what it does). */
    Choices(
      std::initializer_list<std::tuple<T, std::string, std::string>> described)
    {
      for (const auto &[value, name, description] : described)
        {
          choices.emplace_back(value, name);
          descriptions.push_back(description);
        }
    }

    /** "name: description; name: description." for the choices that have
     * a description. */
    std::string
    documentation() const
    {
      std::string text;
      for (unsigned int i = 0; i < descriptions.size(); ++i)
        text += (text.empty() ? "" : "; ") + choices[i].second + ": " +
                descriptions[i];
      return text + ".";
    }

    /** The Patterns::Selection of the names: "first|second|...". */
    dealii::Patterns::Selection
    pattern() const
    {
      std::string names;
      for (const auto &choice : choices)
        names += (names.empty() ? "" : "|") + choice.second;
      return dealii::Patterns::Selection(names);
    }

    /** The name of @p value; throws std::logic_error if it has none. */
    const std::string &
    name(const T &value) const
    {
      for (const auto &choice : choices)
        if (choice.first == value)
          return choice.second;
      throw std::logic_error("a choice without a name");
    }

    /** The value named @p text; throws an InputError naming @p entry
     * ("Subsection/Entry") if no value has that name. */
    T
    value(const std::string &text, const std::string &entry) const
    {
      std::string names;
      for (const auto &choice : choices)
        if (choice.second == text)
          return choice.first;
        else
          names += (names.empty() ? "" : ", ") + choice.second;
      throw InputError(entry, "'" + text + "' is not one of " + names);
    }

  private:
    std::vector<std::pair<T, std::string>> choices;
    std::vector<std::string>               descriptions;
  };
} // namespace signorini

#endif
