#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <signorini/base/text.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

#include <array>
#include <cctype>
#include <cmath>
#include <iostream>
#include <sstream>


namespace signorini
{
  template <int dim>
  ParsedFunction<dim>::ParsedFunction(const unsigned int n_components,
                                      const std::string &entry,
                                      const std::string &text,
                                      const bool         time_dependent)
    : dealii::FunctionParser<dim>(n_components)
    , entry(entry)
    , text(text)
    , zero(true)
    , uses_time(time_dependent && names_variable(text, "t"))
  {
    for (const auto &expression : parse::split(text, ';'))
      {
        std::istringstream in(expression);
        double             value = 1.;
        in >> value;
        if (!in || value != 0. || !(in >> std::ws).eof())
          zero = false;
      }
  }

  template <int dim>
  double
  ParsedFunction<dim>::value(const dealii::Point<dim> &p,
                             const unsigned int        component) const
  {
    const double v = dealii::FunctionParser<dim>::value(p, component);
    if (!std::isfinite(v) && watching)
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (!non_finite)
          non_finite = NonFinite{p, v, this->get_time()};
      }
    return v;
  }

  template <int dim>
  void
  ParsedFunction<dim>::watch()
  {
    watching = true;
  }

  template <int dim>
  void
  ParsedFunction<dim>::check_finite(const MPI_Comm comm) const
  {
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int first =
      dealii::Utilities::MPI::min(non_finite ? rank : n_ranks, comm);
    if (first == n_ranks)
      return;
    // The point, value and time of the first process that has one, on
    // all.
    std::array<double, dim + 2> where{};
    if (rank == first)
      {
        for (unsigned int d = 0; d < dim; ++d)
          where[d] = non_finite->point[d];
        where[dim]     = non_finite->value;
        where[dim + 1] = non_finite->time;
      }
    MPI_Bcast(where.data(), dim + 2, MPI_DOUBLE, first, comm);
    std::string point;
    for (unsigned int d = 0; d < dim; ++d)
      point += (d == 0 ? "" : ", ") + number(where[d]);
    throw InputError(
      entry,
      "'" + text + "' evaluates to " +
        (std::isnan(where[dim]) ? std::string("nan") : number(where[dim])) +
        " at (" + point + ")" +
        (uses_time ? ", t = " + number(where[dim + 1]) : std::string()));
  }

  bool
  names_variable(const std::string &text, const std::string &name)
  {
    const auto identifier = [](const char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    for (std::size_t begin = 0; begin < text.size();)
      {
        if (!identifier(text[begin]))
          {
            ++begin;
            continue;
          }
        std::size_t end = begin;
        while (end < text.size() && identifier(text[end]))
          ++end;
        if (text.compare(begin, end - begin, name) == 0 &&
            end - begin == name.size())
          return true;
        begin = end;
      }
    return false;
  }

  template <int dim>
  void
  initialize_parser(dealii::FunctionParser<dim>         &function,
                    const std::string                   &variables,
                    const std::vector<std::string>      &expressions,
                    const std::map<std::string, double> &constants,
                    const bool                           time_dependent,
                    const std::string                   &entry,
                    const std::string                   &text)
  {
    // deal.II lets muparser describe a parse error on std::cerr over several
    // lines; keep that quiet and report the parser's own sentence once.
    std::ostringstream muted;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(muted.rdbuf());
    try
      {
        auto all_constants = constants;
        all_constants.emplace("pi", dealii::numbers::PI);
        function.initialize(variables,
                            expressions,
                            all_constants,
                            time_dependent);
        // muparser reports some errors only on evaluation:
        dealii::Vector<double> values(function.n_components);
        function.vector_value(dealii::Point<dim>(), values);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const dealii::ExceptionBase &error)
      {
        std::cerr.rdbuf(cerr_buffer);
        std::string       message = one_line(error);
        const std::string said    = "The parser said: ";
        if (message.find(said) != std::string::npos)
          message = message.substr(message.find(said) + said.size());
        throw InputError(entry, "cannot parse '" + text + "': " + message);
      }
  }

  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_function(const std::string                   &text,
                 const unsigned int                   n_components,
                 const std::string                   &entry,
                 const std::map<std::string, double> &constants,
                 const bool                           time_dependent)
  {
    auto expressions = parse::split(text, ';');
    if (expressions.size() == 1 && n_components > 1)
      expressions.assign(n_components, expressions[0]);
    if (expressions.size() != n_components)
      throw InputError(entry,
                       "'" + text + "' should hold " +
                         std::to_string(n_components) +
                         " expressions separated by ';' (or one for all)");

    const std::string variables =
      std::string(dim == 1 ? "x" : (dim == 2 ? "x,y" : "x,y,z")) +
      (time_dependent ? ",t" : "");
    auto function = std::make_unique<ParsedFunction<dim>>(n_components,
                                                          entry,
                                                          text,
                                                          time_dependent);
    initialize_parser<dim>(*function,
                           variables,
                           expressions,
                           constants,
                           time_dependent,
                           entry,
                           text);
    function->watch();
    return function;
  }

  template <int dim>
  bool
  vanishes(const dealii::Function<dim> &function)
  {
    const auto parsed = dynamic_cast<const ParsedFunction<dim> *>(&function);
    return parsed && parsed->vanishes();
  }

  template <int dim>
  void
  check_finite(const dealii::Function<dim> &function, const MPI_Comm comm)
  {
    if (const auto parsed =
          dynamic_cast<const ParsedFunction<dim> *>(&function))
      parsed->check_finite(comm);
  }

  template class ParsedFunction<1>;
  template class ParsedFunction<2>;
  template class ParsedFunction<3>;
  template void
  check_finite(const dealii::Function<2> &, const MPI_Comm);
  template void
  check_finite(const dealii::Function<3> &, const MPI_Comm);
  template bool
  vanishes(const dealii::Function<2> &);
  template bool
  vanishes(const dealii::Function<3> &);
  template std::unique_ptr<dealii::FunctionParser<1>>
  parse_function<1>(const std::string &,
                    unsigned int,
                    const std::string &,
                    const std::map<std::string, double> &,
                    bool);
  template std::unique_ptr<dealii::FunctionParser<2>>
  parse_function<2>(const std::string &,
                    unsigned int,
                    const std::string &,
                    const std::map<std::string, double> &,
                    bool);
  template std::unique_ptr<dealii::FunctionParser<3>>
  parse_function<3>(const std::string &,
                    unsigned int,
                    const std::string &,
                    const std::map<std::string, double> &,
                    bool);
  template void
  initialize_parser<1>(dealii::FunctionParser<1> &,
                       const std::string &,
                       const std::vector<std::string> &,
                       const std::map<std::string, double> &,
                       bool,
                       const std::string &,
                       const std::string &);
} // namespace signorini
