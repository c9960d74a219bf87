// The parse:: helpers of parameter-file lists: the values of valid texts and
// the entry and message of the InputError of invalid ones. The values are
// printed with 6 decimals; they are also checked exactly.

#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

#include "checks.h"
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace signorini;

namespace
{
  /** Runs @p parse on @p text and prints its result or its error. */
  void
  check(const std::string                             &text,
        const std::function<std::string(std::string)> &parse)
  {
    std::cout << "  \"" << text << "\" -> ";
    try
      {
        std::cout << parse(text) << '\n';
      }
    catch (const InputError &error)
      {
        std::cout << "InputError [" << error.entry << "]: " << error.what()
                  << '\n';
      }
  }

  template <int dim>
  std::string
  to_string(const dealii::Point<dim> &p)
  {
    std::string s = "(";
    for (unsigned int d = 0; d < dim; ++d)
      s += (d ? ", " : "") + std::to_string(p[d]);
    return s + ")";
  }

  template <typename Container>
  std::string
  join(const Container &items)
  {
    std::string s     = "{";
    bool        first = true;
    for (const auto &item : items)
      {
        s += (first ? "" : "|") + std::string(item);
        first = false;
      }
    return s + "}";
  }
} // namespace

int
main()
{
  std::cout << "split(',') (items between |):\n";
  for (const std::string text :
       {"", " ", "a", "a,b", " a , b ", "a,,b", ",a,", "\ta\t,  b c ,"})
    check(text,
          [](const std::string &t) { return join(parse::split(t, ',')); });

  std::cout << "point<2>:\n";
  for (const std::string text : {"1, 2",
                                 " -1.5e-3 ,4 ",
                                 "1e3,0",
                                 "1",
                                 "1, 2, 3",
                                 "",
                                 "1, x",
                                 "1, 2mm",
                                 "1,, 2",
                                 "nan, 1",
                                 "1e999, 0"})
    check(text, [](const std::string &t) {
      return to_string(parse::point<2>(t, "Geometry/Center"));
    });
  std::cout << "point<3>:\n";
  for (const std::string text : {"0, 0.25, -8", "0, 0.25"})
    check(text, [](const std::string &t) {
      return to_string(parse::point<3>(t, "Geometry/Center"));
    });

  std::cout << "point_list<2>:\n";
  for (const std::string text :
       {"", "10, 0; 5, 1", "10, 0; 5, 1;", "  ;  ", "10, 0; 5", "1, 2, 3"})
    check(text, [](const std::string &t) {
      std::string s;
      for (const auto &p : parse::point_list<2>(t, "Output/Probes"))
        s += to_string(p) + " ";
      return "[ " + s + "]";
    });
  std::cout << "point_list<3>:\n";
  check("1, 2, 3; 4, 5, 6", [](const std::string &t) {
    std::string s;
    for (const auto &p : parse::point_list<3>(t, "Output/Probes"))
      s += to_string(p) + " ";
    return "[ " + s + "]";
  });

  std::cout << "boundary_ids:\n";
  for (const std::string text :
       {"", "0", "0, 2", "2, 0, 2", "255", "256", "-1", "1.5", "one"})
    check(text, [](const std::string &t) {
      std::string s;
      for (const auto id : parse::boundary_ids(t, "Boundary/Fixed"))
        s += std::to_string(id) + " ";
      return "{ " + s + "}";
    });

  std::cout << "unsigned_list, 2 values:\n";
  for (const std::string text : {"20, 2",
                                 " 1 ,1 ",
                                 "20",
                                 "20, 2, 1",
                                 "0, 2",
                                 "-3, 2",
                                 "2.5, 2",
                                 "a, 2",
                                 "1e10, 2",
                                 "inf, 2"})
    check(text, [](const std::string &t) {
      std::string s;
      for (const auto n : parse::unsigned_list(t, 2, "Geometry/Repetitions"))
        s += std::to_string(n) + " ";
      return "[ " + s + "]";
    });

  for (const unsigned int dim : {2u, 3u})
    {
      std::cout << "components, dim " << dim << ":\n";
      for (const std::string text :
           {"x", "y", "xy", "y x", "x, y", "all", "z", "xyz", "", "All", "u"})
        check(text, [dim](const std::string &t) {
          // "x-z" for x and z: digits would be compared as numbers.
          const auto  mask = parse::components(t, dim, "Boundary/Components");
          std::string s;
          for (unsigned int d = 0; d < mask.size(); ++d)
            s += mask[d] ? static_cast<char>('x' + d) : '-';
          return s;
        });
    }

  std::cout << "in_range:\n";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::string, parse::Range>> ranges = {
    {"positive", parse::Range::positive()},
    {"at_least(0)", parse::Range::at_least(0.)},
    {"at_least(1)", parse::Range::at_least(1.)},
    {"open(-1, 0.5)", parse::Range::open(-1., 0.5)},
    {"closed_open(0, 1)", parse::Range::closed_open(0., 1.)},
    {"Range()", parse::Range()}};
  for (const auto &[name, range] : ranges)
    for (const double value : {-1., 0., 1e-300, 0.4999999, 0.5, 1., inf, nan})
      {
        std::ostringstream label;
        label << std::setprecision(10) << name << " " << value;
        check(label.str(), [&](const std::string &) {
          std::ostringstream result;
          result << std::setprecision(10)
                 << parse::in_range(value, range, "Section/Entry", "why");
          return result.str();
        });
      }

  std::cout << "parse_function<2>, vanishes() (loads that are not "
               "integrated):\n";
  for (const std::string text :
       {"0; 0", "0", " 0 ; -0.0 ", "0e5;0", "0; 1e-30", "0*x; 0", "0; 0; 0"})
    check(text, [](const std::string &t) {
      const auto f = parse_function<2>(t, 2, "Boundary conditions/Body force");
      return std::string(vanishes(*f) ? "vanishes" : "does not vanish");
    });

  std::cout << "InputError::at:\n";
  const InputError error = InputError::at("scene.prm:12", "unknown entry");
  std::cout << "  entry [" << error.entry << "], location [" << error.location
            << "], what: " << error.what() << '\n';

  std::cout << "exact values:\n";
  checks::expect("point<2>(\" -1.5e-3 ,4 \") = (-1.5e-3, 4)",
                 parse::point<2>(" -1.5e-3 ,4 ", "Geometry/Center") ==
                   dealii::Point<2>(-1.5e-3, 4.));
  checks::expect("point<2>(\"1e3,0\") = (1000, 0)",
                 parse::point<2>("1e3,0", "Geometry/Center") ==
                   dealii::Point<2>(1000., 0.));
  checks::expect("point<3>(\"0, 0.25, -8\") = (0, 0.25, -8)",
                 parse::point<3>("0, 0.25, -8", "Geometry/Center") ==
                   dealii::Point<3>(0., 0.25, -8.));
  {
    const auto list = parse::point_list<2>("10, 0; 5, 1;", "Output/Probes");
    checks::expect("point_list<2>(\"10, 0; 5, 1;\") = (10, 0), (5, 1)",
                   list.size() == 2 && list[0] == dealii::Point<2>(10., 0.) &&
                     list[1] == dealii::Point<2>(5., 1.));
  }
  checks::expect("boundary_ids(\"2, 0, 2\") = {0, 2}",
                 parse::boundary_ids("2, 0, 2", "Boundary/Fixed") ==
                   std::set<dealii::types::boundary_id>{0, 2});
  checks::expect("unsigned_list(\" 1 ,1 \", 2) = (1, 1)",
                 parse::unsigned_list(" 1 ,1 ", 2, "Geometry/Repetitions") ==
                   std::vector<unsigned int>{1, 1});
  checks::expect("in_range keeps 1e-300 and 0.4999999 as they are",
                 parse::in_range(1e-300,
                                 parse::Range::positive(),
                                 "Section/Entry") == 1e-300 &&
                   parse::in_range(0.4999999,
                                   parse::Range::open(-1., 0.5),
                                   "Section/Entry") == 0.4999999);
  {
    bool named = false;
    try
      {
        parse::in_range(0.5, parse::Range::open(-1., 0.5), "Section/Entry");
      }
    catch (const InputError &error)
      {
        named = error.entry == "Section/Entry";
      }
    checks::expect("in_range(0.5, open(-1, 0.5)) refused, naming the entry",
                   named);
  }
}
