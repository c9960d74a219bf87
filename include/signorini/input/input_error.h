#ifndef signorini_input_input_error_h
#define signorini_input_input_error_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * A problem with the user's input: the entry it concerns (as
   * "Subsection/Entry") or the place in a file ("FILE:LINE"), and what is
   * wrong. The program reports it as one line and exits with status 1.
   */
  class InputError : public std::runtime_error
  {
  public:
    /** An error in the value of @p entry of the parameter file. */
    InputError(const std::string &entry, const std::string &message);

    /** An error at @p location, e.g. "FILE:LINE", of no particular entry. */
    static InputError
    at(const std::string &location, const std::string &message);

    /** The entry the error concerns, empty if none. */
    std::string entry;
    /** Where the error is, empty for the parameter file as a whole. */
    std::string location;
  };

  /** A value that is legal but unusual: the entry it concerns and what the
   * results will suffer from. */
  struct InputWarning
  {
    std::string entry;
    std::string message;
  };

  /** Records a warning about @p entry ("Subsection/Entry"). The program
   * prints the warnings recorded while the parameters are read, each as
   * one line "signorini: warning: FILE: entry 'ENTRY': MESSAGE", before
   * the first cycle. */
  void
  warn(const std::string &entry, const std::string &message);

  /** The warnings recorded since the last call, in order; forgets them. */
  std::vector<InputWarning>
  take_warnings();

  /** The additional information of a deal.II exception as one line. */
  std::string
  one_line(const dealii::ExceptionBase &error);

  /** Parsers for the list formats used in parameter files. Each throws an
   * InputError that names @p entry. */
  namespace parse
  {
    /** The values a number of an entry may take: an interval whose ends
     * each belong to it or not. Infinite ends are never reached: a value
     * must be finite. */
    struct Range
    {
      double lower          = -std::numeric_limits<double>::infinity();
      bool   lower_included = true;
      double upper          = std::numeric_limits<double>::infinity();
      bool   upper_included = true;

      /** (0, inf). */
      static Range
      positive();
      /** [@p lower, inf). */
      static Range
      at_least(const double lower);
      /** (@p lower, @p upper). */
      static Range
      open(const double lower, const double upper);
      /** [@p lower, @p upper). */
      static Range
      closed_open(const double lower, const double upper);

      /** Whether @p value is finite and in the range. */
      bool
      contains(const double value) const;

      /** The range in words: "positive", "at least 0", "above -1 and below
       * 0.5", ... */
      std::string
      text() const;
    };

    /** @p value, if it is a finite number in @p range; else throws an
     * InputError naming @p entry ("must be positive, not 0"), with
     * @p why, if given, in parentheses after the range. */
    double
    in_range(const double       value,
             const Range       &range,
             const std::string &entry,
             const std::string &why = "");

    /** @p text as a finite number ("0.5", "1e-3"); throws naming @p entry
     * for text that is not a number ("'abc' is not a number") or not a
     * finite one ("'inf' is not a finite number"). */
    double
    number(const std::string &text, const std::string &entry);

    /** "x0, x1[, x2]" with exactly @p dim coordinates, each a finite
     * number. */
    template <int dim>
    dealii::Point<dim>
    point(const std::string &text, const std::string &entry);

    /** A ';'-separated list of points, e.g. "10, 0; 5, 1". Empty text gives an
     * empty list. */
    template <int dim>
    std::vector<dealii::Point<dim>>
    point_list(const std::string &text, const std::string &entry);

    /** A ','-separated list of boundary ids, e.g. "0, 2". */
    std::set<dealii::types::boundary_id>
    boundary_ids(const std::string &text, const std::string &entry);

    /** A ','-separated list of @p n unsigned integers ("20, 2"). */
    std::vector<unsigned int>
    unsigned_list(const std::string &text,
                  const unsigned int n,
                  const std::string &entry);

    /** Displacement components as letters ("x", "xy", "y z") or "all". */
    std::vector<bool>
    components(const std::string &text,
               const unsigned int dim,
               const std::string &entry);

    /** Split at @p separator and trim white space; empty items are dropped. */
    std::vector<std::string>
    split(const std::string &text, const char separator);
  } // namespace parse
} // namespace signorini

#endif
