// HeightObstacle: the gap y - psi(x) (2D) and z - psi(x, y) (3D) of points
// above, on and below flat and curved height functions, the normal the unit
// vector along the last axis, the obstacle of create_obstacle from the
// Obstacle subsection, and the surface that write_vtu writes: the graph of
// psi over the box enlarged by a tenth on each side, read back from the VTU
// text (its points decoded from base64 and zlib).

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <signorini/contact/height_obstacle.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/output/obstacle_output.h>

#include "vtu_arrays.h"
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;

namespace
{
  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "  " << what << ": " << std::scientific << std::setprecision(1)
              << difference << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  template <int dim>
  std::string
  to_string(const Point<dim> &p)
  {
    std::ostringstream s;
    s << '(';
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << p[d];
    return s.str() + ')';
  }

  /** The gap and normal of @p point against @p expected_gap; the normal
   * must be e_{dim-1} whatever @p normal held before. */
  template <int dim>
  void
  check_point(const Obstacle<dim> &obstacle,
              const Point<dim>    &point,
              const double         expected_gap)
  {
    Tensor<1, dim> normal;
    for (unsigned int d = 0; d < dim; ++d)
      normal[d] = 7. + d; // overwritten by gap()
    const double   gap = obstacle.gap(point, normal);
    Tensor<1, dim> e;
    e[dim - 1] = 1.;
    std::cout << "  point " << to_string(point) << ": gap " << gap
              << ", expected " << expected_gap << ", normal "
              << to_string(Point<dim>(normal)) << '\n';
    report("   |gap - expected|", std::abs(gap - expected_gap), 1e-14);
    report("   |normal - e_last|, ||normal| - 1|",
           std::max((normal - e).norm(), std::abs(normal.norm() - 1.)),
           0.);
  }

  /** The value of attribute @p name in the XML element that starts at
   * @p from. */
  std::string
  attribute(const std::string &xml, std::size_t from, const std::string &name)
  {
    const std::size_t end = xml.find('>', from);
    const std::size_t at  = xml.find(name + "=\"", from);
    if (at == std::string::npos || at > end)
      return "";
    const std::size_t begin = at + name.size() + 2;
    return xml.substr(begin, xml.find('"', begin) - begin);
  }

  /** The points of the VTU text @p xml (vtu_arrays::decode()). */
  std::vector<std::array<double, 3>>
  vtu_points(const std::string &xml)
  {
    const std::size_t points = xml.find("<Points>");
    const std::size_t array  = xml.find("<DataArray", points);
    const std::string type   = attribute(xml, array, "type");
    const std::size_t begin  = xml.find('>', array) + 1;
    const std::string data =
      xml.substr(begin, xml.find("</DataArray>", begin) - begin);
    if (xml.find("vtkZLibDataCompressor") == std::string::npos ||
        attribute(xml, array, "format") != "binary")
      throw std::runtime_error("not a zlib-compressed binary VTU");

    const auto raw =
      vtu_arrays::decode(data, vtu_arrays::Compressor::zlib).bytes;

    std::vector<std::array<double, 3>> result;
    const unsigned int                 width = type == "Float64" ? 8 : 4;
    for (std::size_t i = 0; i + 3 * width <= raw.size(); i += 3 * width)
      {
        std::array<double, 3> p;
        for (unsigned int d = 0; d < 3; ++d)
          if (width == 8)
            std::memcpy(&p[d], raw.data() + i + 8 * d, 8);
          else
            {
              float f;
              std::memcpy(&f, raw.data() + i + 4 * d, 4);
              p[d] = f;
            }
        result.push_back(p);
      }
    return result;
  }

  /** write_vtu over @p box: the counts in the text, the points' extent
   * against the box enlarged by a tenth, and the points on the graph of
   * @p height. */
  template <int dim>
  void
  check_vtu(const HeightObstacle<dim> &obstacle,
            const Function<dim - 1>   &height,
            const BoundingBox<dim>    &box,
            const unsigned int         expected_cells)
  {
    std::ostringstream out;
    write_obstacle_vtu(out, obstacle, box);
    const std::string  xml   = out.str();
    const std::size_t  piece = xml.find("<Piece");
    const unsigned int n_points =
      std::stoul(attribute(xml, piece, "NumberOfPoints"));
    const unsigned int n_cells =
      std::stoul(attribute(xml, piece, "NumberOfCells"));
    std::cout << "  write_vtu over the box "
              << to_string(box.get_boundary_points().first) << " - "
              << to_string(box.get_boundary_points().second) << ": " << n_cells
              << " cells (expected " << expected_cells << "), " << n_points
              << " points (" << (1U << (dim - 1))
              << " per cell: " << expected_cells * (1U << (dim - 1)) << ")\n";
    report("   |cells - expected|",
           std::abs(double(n_cells) - double(expected_cells)),
           0.);

    const auto points = vtu_points(xml);
    report("   |points decoded - NumberOfPoints|",
           std::abs(double(points.size()) - double(n_points)),
           0.);
    // Float32 coordinates: compare to single precision.
    const double tolerance = 1e-6;
    for (unsigned int d = 0; d < dim - 1; ++d)
      {
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (const auto &p : points)
          {
            lo = std::min(lo, p[d]);
            hi = std::max(hi, p[d]);
          }
        const double margin  = 0.1 * box.side_length(d);
        const double want_lo = box.lower_bound(d) - margin,
                     want_hi = box.upper_bound(d) + margin;
        std::cout << "    axis " << d << ": from " << std::setprecision(7) << lo
                  << " to " << hi << std::setprecision(10)
                  << " (single precision), expected " << want_lo << " to "
                  << want_hi << '\n';
        report("   max |extent - box enlarged by a tenth|",
               std::max(std::abs(lo - want_lo), std::abs(hi - want_hi)),
               tolerance);
      }
    double off_graph = 0., off_plane = 0.;
    for (const auto &p : points)
      {
        Point<dim - 1> horizontal;
        for (unsigned int d = 0; d < dim - 1; ++d)
          horizontal[d] = p[d];
        off_graph =
          std::max(off_graph, std::abs(p[dim - 1] - height.value(horizontal)));
        if (dim == 2)
          off_plane = std::max(off_plane, std::abs(p[2]));
      }
    report("   max |last coordinate - psi| over the points",
           off_graph,
           tolerance);
    if (dim == 2)
      report("   max |z| over the points", off_plane, 0.);
  }

  void
  two_dimensions()
  {
    std::cout << "2D, flat psi = -0.25 (Functions::ConstantFunction<1>):\n";
    const Functions::ConstantFunction<1> flat(-0.25);
    const HeightObstacle<2>              plane(flat);
    std::cout << "  entry: " << plane.entry() << '\n';
    check_point<2>(plane, Point<2>(0.3, 1.), 1.25);
    check_point<2>(plane, Point<2>(-7., -0.25), 0.);
    check_point<2>(plane, Point<2>(2.5, -1.), -0.75);

    std::cout << "2D, cylinder psi = -sqrt(4 - x^2) (FunctionParser<1>):\n";
    FunctionParser<1> cylinder_height(1);
    cylinder_height.initialize("x", "-sqrt(4 - x^2)", {});
    const HeightObstacle<2> cylinder(cylinder_height);
    check_point<2>(cylinder, Point<2>(1., 0.), std::sqrt(3.));
    check_point<2>(cylinder, Point<2>(1.2, -1.6), 0.);
    check_point<2>(cylinder, Point<2>(0., -2.5), -0.5);
    check_point<2>(cylinder, Point<2>(-1.6, -1.5), 1.2 - 1.5);

    check_vtu<2>(cylinder,
                 cylinder_height,
                 BoundingBox<2>({Point<2>(-1., 0.), Point<2>(1., 0.5)}),
                 400);
    check_vtu<2>(plane,
                 flat,
                 BoundingBox<2>({Point<2>(0., 0.), Point<2>(5., 1.)}),
                 400);
  }

  void
  three_dimensions()
  {
    std::cout << "3D, flat psi = 0.1 (Functions::ConstantFunction<2>):\n";
    const Functions::ConstantFunction<2> flat(0.1);
    const HeightObstacle<3>              plane(flat);
    check_point<3>(plane, Point<3>(0.3, -0.4, 1.1), 1.);
    check_point<3>(plane, Point<3>(5., 6., 0.1), 0.);
    check_point<3>(plane, Point<3>(0., 0., -0.4), -0.5);

    std::cout << "3D, sphere psi = -sqrt(9 - x^2 - y^2) (FunctionParser<2>):\n";
    FunctionParser<2> sphere_height(1);
    sphere_height.initialize("x,y", "-sqrt(9 - x^2 - y^2)", {});
    const HeightObstacle<3> sphere(sphere_height);
    check_point<3>(sphere, Point<3>(0., 0., 0.), 3.);
    check_point<3>(sphere, Point<3>(1., 2., -2.), 0.);
    check_point<3>(sphere, Point<3>(2., -1., -2.5), 2. - 2.5);

    std::cout << "3D, saddle psi = x y / 2 (FunctionParser<2>):\n";
    FunctionParser<2> saddle_height(1);
    saddle_height.initialize("x,y", "x*y/2", {});
    const HeightObstacle<3> saddle(saddle_height);
    check_point<3>(saddle, Point<3>(2., 3., 3.5), 0.5);
    check_point<3>(saddle, Point<3>(-2., 3., -3.), 0.);

    check_vtu<3>(sphere,
                 sphere_height,
                 BoundingBox<3>(
                   {Point<3>(-1., -0.5, 0.), Point<3>(1., 1.5, 2.)}),
                 80 * 80);
  }

  template <int dim>
  void
  from_parameters(const std::string &height,
                  const Point<dim>  &point,
                  const double       expected)
  {
    ParameterHandler prm;
    ObstacleParameters<dim>::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Obstacle\n  set Height = " + height + "\nend\n");
    ObstacleParameters<dim> parameters;
    parameters.parse_parameters(prm);
    const auto  obstacles = create_obstacles(parameters);
    const auto &obstacle  = (*obstacles)[0];
    std::cout << "create_obstacle<" << dim << ">, Height = " << height
              << ", HeightObstacle: "
              << (obstacles->size() == 1 &&
                      dynamic_cast<const HeightObstacle<dim> *>(&obstacle) ?
                    "yes" :
                    "no")
              << ", contact ids:";
    for (const auto id : parameters.contact_ids)
      std::cout << ' ' << int(id);
    std::cout << '\n';
    check_point<dim>(obstacle, point, expected);
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  two_dimensions();
  three_dimensions();
  from_parameters<2>("-sqrt(4 - x^2)", Point<2>(1.2, 0.4), 2.);
  from_parameters<3>("0.5*x - y", Point<3>(2., 1., 0.25), 0.25);
}
