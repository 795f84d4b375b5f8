// Body forces and eigenstrains (Loads/Layer k/Body force, Eigenstrain)
// against a closed-form solution.
//
// u_exact is a quadratic displacement and eps* a linear eigenstrain field
// (every component a general polynomial of that degree); then
// sigma = C (eps(u_exact) - eps*) is linear and f = -div sigma constant, both
// computed here from the coefficients with the plane-strain Lame formulas
// (not the library's law). The entries of the layer carry f and eps* as
// muparser expressions, parsed by the Loads subsection into its VolumeLoad.
// Q2 and P2 contain u_exact, and the Gauss rules of the assembly integrate
// the volume terms exactly (polynomials of degree <= 3 per direction), so
// the discrete solution is u_exact to round-off:
//
// 1. One subproblem (ElasticSubproblem, as tests/subproblem_convergence.cc)
//    on the unit square, clamped to u_exact on all sides: Q2 and P2 nodal
//    values within 1e-10 of max |u_exact|; the energy equals the potential
//    energy of the eigenstrained body 1/2 int (eps - eps*) : C (eps - eps*)
//    - int f . u (a Gauss rule of 6 points on the exact fields, here) to
//    1e-10 relative; the stresses of the VTU output (StressPostprocessor)
//    equal sigma = C (eps - eps*) and sigma_zz = lambda tr(eps - eps*) at
//    the Gauss points of every cell to 1e-10 of max |sigma|.
// 2. The same with the top side free of Dirichlet data and loaded by the
//    traction sigma n of the eigenstrained stress: Q2 exact to 1e-10 (the
//    natural boundary condition is that of sigma = C (eps - eps*)).
// 3. Q1 (which does not contain u_exact): L2 error rate 2 +- 0.1 from 16 to
//    32 cells per side.
// 4. The whole program (Study), one layer on (-1, 1)^2, no crack, Sigma
//    glued, all sides clamped to u_exact, Q2: the displacement at every
//    node within 1e-10 of max |u_exact|, the reported energy equals the
//    exact Pi to 1e-10 relative, and the error estimate eta (Kelly's jumps
//    and the cell residual h^2 |f + div sigma_h|^2 of a layer with a volume
//    load; Mesh/Interface terms in the estimator = false) below 1e-8 of
//    (E |eps*|^2 area)^1/2: the residual f + div C (eps(u_h) - eps*)
//    vanishes only if both the body force and the gradient of eps* enter it.
// 5. Zero entries pass no VolumeLoad: "0.0; -0; 0e0" in a layer gives
//    ElasticSubproblem::volume_load() == nullptr.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/drivers/study.h>
#include <bilayer/output/output.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/subproblem/subproblem.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  constexpr double E = 200, nu = 0.28;
  const double     mu     = E / (2 * (1 + nu));
  const double     lambda = 2 * nu * mu / (1 - 2 * nu);

  // u_i = sum_k a[i][k] m_k with the monomials m = (1, x, y, x^2, xy, y^2).
  constexpr double a[2][6] = {
    {1e-3, 0.1e-3, -0.2e-3, 0.3e-3, -0.5e-3, 0.2e-3},
    {-2e-3, -0.3e-3, 0.1e-3, -0.4e-3, 0.25e-3, 0.6e-3}};
  // eps*_c = b[c][0] + b[c][1] x + b[c][2] y for c = 11, 22, 12.
  constexpr double b[3][3] = {{0.2e-3, 0.5e-3, -0.3e-3},
                              {-0.1e-3, 0.2e-3, 0.4e-3},
                              {0.05e-3, 0.3e-3, 0.1e-3}};

  std::array<double, 2>
  u_exact(const Point<2> &p)
  {
    const double          x = p[0], y = p[1];
    const double          m[6] = {1, x, y, x * x, x * y, y * y};
    std::array<double, 2> u{};
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int k = 0; k < 6; ++k)
        u[i] += a[i][k] * m[k];
    return u;
  }

  // d u_i / d x_j.
  double
  grad_u(const unsigned int i, const unsigned int j, const Point<2> &p)
  {
    const double x = p[0], y = p[1];
    return j == 0 ? a[i][1] + 2 * a[i][3] * x + a[i][4] * y :
                    a[i][2] + a[i][4] * x + 2 * a[i][5] * y;
  }

  // eps*_ij.
  double
  eps_star(const unsigned int i, const unsigned int j, const Point<2> &p)
  {
    const unsigned int c = i == j ? i : 2;
    return b[c][0] + b[c][1] * p[0] + b[c][2] * p[1];
  }

  // The elastic strain e = eps(u) - eps* and sigma = 2 mu e + lambda tr e I.
  double
  elastic_strain(const unsigned int i, const unsigned int j, const Point<2> &p)
  {
    return 0.5 * (grad_u(i, j, p) + grad_u(j, i, p)) - eps_star(i, j, p);
  }

  double
  sigma(const unsigned int i, const unsigned int j, const Point<2> &p)
  {
    const double tr = elastic_strain(0, 0, p) + elastic_strain(1, 1, p);
    return 2 * mu * elastic_strain(i, j, p) + (i == j ? lambda * tr : 0.);
  }

  // f = -div sigma (constant): d sigma_ij / d x_j by exact differences of
  // the linear field.
  std::array<double, 2>
  body_force()
  {
    std::array<double, 2> f{};
    const Point<2>        o(0, 0);
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        {
          Point<2> e;
          e[j] = 1;
          f[i] -= sigma(i, j, o + e) - sigma(i, j, o);
        }
    return f;
  }

  std::string
  number(const double v)
  {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v << ")";
    return s.str();
  }

  std::string
  u_text()
  {
    std::string text;
    const char *m[6] = {"1", "x", "y", "x*x", "x*y", "y*y"};
    for (unsigned int i = 0; i < 2; ++i)
      {
        text += i == 0 ? "" : "; ";
        for (unsigned int k = 0; k < 6; ++k)
          text += (k == 0 ? "" : " + ") + number(a[i][k]) + "*" + m[k];
      }
    return text;
  }

  /// The Loads of layer 1: f, eps* and the prescribed u_exact.
  std::string
  loads_text()
  {
    const auto  f = body_force();
    std::string eps;
    for (unsigned int c = 0; c < 3; ++c)
      eps += (c == 0 ? "" : "; ") + number(b[c][0]) + " + " + number(b[c][1]) +
             "*x + " + number(b[c][2]) + "*y";
    return "subsection Loads\n subsection Layer 1\n  set Body force = " +
           number(f[0]) + "; " + number(f[1]) + "\n  set Eigenstrain = " + eps +
           "\n  set Prescribed displacement = " + u_text() + "\n end\nend\n";
  }

  std::string
  material_text()
  {
    std::ostringstream s;
    s << "subsection Materials\n set Number of layers = 1\n"
      << " subsection Layer 1\n  set Young's modulus = " << E
      << "\n  set Poisson's ratio = " << nu << "\n end\nend\n";
    return s.str();
  }

  /// Pi = 1/2 int e : sigma - int f . u over [x0, x1]^2 (6-point Gauss).
  double
  exact_energy(const double x0, const double x1)
  {
    const QGauss<1> gauss(6);
    const auto      f  = body_force();
    double          pi = 0;
    for (unsigned int p = 0; p < gauss.size(); ++p)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const Point<2> x(x0 + (x1 - x0) * gauss.point(p)[0],
                           x0 + (x1 - x0) * gauss.point(q)[0]);
          const double   w =
            gauss.weight(p) * gauss.weight(q) * (x1 - x0) * (x1 - x0);
          double density = 0;
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              density += 0.5 * elastic_strain(i, j, x) * sigma(i, j, x);
          const auto u = u_exact(x);
          pi += (density - f[0] * u[0] - f[1] * u[1]) * w;
        }
    return pi;
  }

  /// The largest |w - u_exact| at the support points of @p sub.
  double
  nodal_error(const ElasticSubproblem &sub, const Vector<double> &w)
  {
    std::vector<Point<2>> points(sub.n_dofs());
    DoFTools::map_dofs_to_support_points(sub.mapping(),
                                         sub.dof_handler(),
                                         points);
    double largest = 0;
    // (The component of each dof from its cell.)
    std::vector<types::global_dof_index> dofs(sub.fe().n_dofs_per_cell());
    for (const auto &cell : sub.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < dofs.size(); ++k)
          {
            const unsigned int c = sub.fe().system_to_component_index(k).first;
            largest =
              std::max(largest,
                       std::abs(w(dofs[k]) - u_exact(points[dofs[k]])[c]));
          }
      }
    return largest;
  }

  /// The largest difference between the stresses of the VTU output and the
  /// exact ones at the Gauss points of @p sub's cells, over max |sigma|.
  double
  stress_error(const ElasticSubproblem &sub, const Vector<double> &w)
  {
    const StressPostprocessor        stresses(sub.laws(), sub.volume_load());
    FEValues<2>                      fe_values(sub.mapping(),
                          sub.fe(),
                          QGauss<2>(3),
                          update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 2>>        grads(fe_values.n_quadrature_points);
    double                           largest = 0, scale = 0;
    for (const auto &cell : sub.dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_gradients(w, grads);
        DataPostprocessorInputs::Vector<2> inputs;
        inputs.evaluation_points = fe_values.get_quadrature_points();
        inputs.solution_gradients.assign(grads.size(),
                                         std::vector<Tensor<1, 2>>(2));
        for (unsigned int q = 0; q < grads.size(); ++q)
          for (unsigned int c = 0; c < 2; ++c)
            inputs.solution_gradients[q][c] = grads[q][c];
        std::vector<Vector<double>> out(grads.size(), Vector<double>(5));
        stresses.evaluate_vector_field(inputs, out);
        for (unsigned int q = 0; q < grads.size(); ++q)
          {
            const Point<2> &x = inputs.evaluation_points[q];
            const double tr = elastic_strain(0, 0, x) + elastic_strain(1, 1, x);
            const double exact[4] = {sigma(0, 0, x),
                                     sigma(1, 1, x),
                                     lambda * tr,
                                     sigma(0, 1, x)};
            for (unsigned int k = 0; k < 4; ++k)
              {
                largest = std::max(largest, std::abs(out[q](k + 1) - exact[k]));
                scale   = std::max(scale, std::abs(exact[k]));
              }
          }
      }
    return largest / scale;
  }

  /// The unit square with bilayer's side ids.
  void
  unit_square(Triangulation<2> &tria, const unsigned int n, const bool simplex)
  {
    if (simplex)
      GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                               {n, n},
                                                               Point<2>(0, 0),
                                                               Point<2>(1, 1));
    else
      GridGenerator::subdivided_hyper_rectangle(tria,
                                                {n, n},
                                                Point<2>(0, 0),
                                                Point<2>(1, 1));
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<2> c = face->center();
          face->set_boundary_id(c[0] < 1e-12     ? BoundaryIds::left :
                                c[0] > 1 - 1e-12 ? BoundaryIds::right :
                                c[1] < 1e-12     ? BoundaryIds::bottom :
                                                   BoundaryIds::top);
        }
  }

  double
  max_u(const double x0, const double x1)
  {
    double largest = 0;
    for (const double x : {x0, x1})
      for (const double y : {x0, x1})
        for (const double v : u_exact(Point<2>(x, y)))
          largest = std::max(largest, std::abs(v));
    return largest;
  }
} // namespace


int
main()
{
  std::ofstream("measured.txt", std::ios::trunc) << "";
  // The scene's Loads into a VolumeLoad, as the program reads them.
  const Scene scene =
    scene_from_string(material_text() + loads_text(), "volume_load_exact");
  const std::unique_ptr<VolumeLoad> volume =
    scene.loads.volume_load(Layer::first, 1.0);
  const auto prescribed = scene.loads.prescribed_function(Layer::first);
  std::cout << "the layer has a body force and an eigenstrain: "
            << yes(volume && volume->has_body_force() &&
                   volume->has_eigenstrain())
            << std::endl;
  const LayerMaterial material{E, nu};

  // 1., 2. Q2 and P2, clamped everywhere; Q2 with the traction on top.
  for (const int variant : {0, 1, 2})
    {
      const bool       simplex         = variant == 1;
      const bool       traction_on_top = variant == 2;
      Triangulation<2> tria;
      unit_square(tria, 4, simplex);
      ElasticSubproblem sub(Layer::first, Subdomain::minus, tria, 2, material);
      FunctionParser<2> top(2);
      {
        // sigma n on the top side (n = (0, 1)): (sigma_xy, sigma_yy),
        // linear in x there (y = 1).
        const Point<2> p0(0, 1), p1(1, 1);
        const double   s0x = sigma(0, 1, p0), s1x = sigma(0, 1, p1);
        const double   s0y = sigma(1, 1, p0), s1y = sigma(1, 1, p1);
        top.initialize("x,y",
                       number(s0x) + " + " + number(s1x - s0x) + "*x; " +
                         number(s0y) + " + " + number(s1y - s0y) + "*x",
                       {});
      }
      const Functions::ZeroFunction<2>       zero(2);
      const std::vector<const Function<2> *> traction = {&zero,
                                                         &zero,
                                                         &zero,
                                                         &top};
      const std::vector<bool> clamped = {true, true, true, !traction_on_top};
      sub.setup(
        clamped, *prescribed, traction, "Amesos_Mumps", false, volume.get());
      Vector<double> w;
      sub.solve(Vector<double>(), w);
      const std::string name = traction_on_top ?
                                 "Q2, traction sigma n on top" :
                                 (simplex ? "P2, clamped" : "Q2, clamped");
      std::ofstream("measured.txt", std::ios::app)
        << name
        << ": nodal error / max |u| = " << nodal_error(sub, w) / max_u(0, 1)
        << ", |Pi_h - Pi| / |Pi| = "
        << (traction_on_top ? 0. :
                              std::abs(sub.energy(w) - exact_energy(0, 1)) /
                                std::abs(exact_energy(0, 1)))
        << (traction_on_top ? " (not computed)" : "")
        << ", stress error / max |sigma| = " << stress_error(sub, w)
        << std::endl;
      std::cout << name << ": nodal error within 1e-10 of max |u|: "
                << yes(nodal_error(sub, w) <= 1e-10 * max_u(0, 1)) << std::endl;
      if (!traction_on_top)
        {
          const double pi = exact_energy(0, 1);
          std::cout << name
                    << ": energy equals the eigenstrained potential energy to "
                       "1e-10: "
                    << yes(std::abs(sub.energy(w) - pi) <= 1e-10 * std::abs(pi))
                    << std::endl;
          std::cout << name
                    << ": output stresses C (eps - eps*) within 1e-10 of the "
                       "largest: "
                    << yes(stress_error(sub, w) <= 1e-10) << std::endl;
        }
    }

  // 3. Q1: L2 rate 2.
  {
    double previous = 0, rate = 0;
    for (unsigned int n = 8; n <= 32; n *= 2)
      {
        Triangulation<2> tria;
        unit_square(tria, n, false);
        ElasticSubproblem sub(
          Layer::first, Subdomain::minus, tria, 1, material);
        const Functions::ZeroFunction<2>       zero(2);
        const std::vector<const Function<2> *> traction(4, &zero);
        sub.setup({true, true, true, true},
                  *prescribed,
                  traction,
                  "Amesos_Mumps",
                  false,
                  volume.get());
        Vector<double> w;
        sub.solve(Vector<double>(), w);
        Vector<float> cellwise(tria.n_active_cells());
        VectorTools::integrate_difference(sub.mapping(),
                                          sub.dof_handler(),
                                          w,
                                          *prescribed,
                                          cellwise,
                                          QGauss<2>(4),
                                          VectorTools::L2_norm);
        const double l2 =
          VectorTools::compute_global_error(tria,
                                            cellwise,
                                            VectorTools::L2_norm);
        if (previous > 0)
          rate = std::log2(previous / l2);
        previous = l2;
      }
    std::ofstream("measured.txt", std::ios::app)
      << "Q1: L2 rate " << rate << std::endl;
    std::cout << "Q1: L2 rate 2 +- 0.1: " << yes(std::abs(rate - 2) < 0.1)
              << std::endl;
  }

  // 4. The program: one layer, no crack, Q2.
  {
    std::ostringstream text;
    text << material_text() << loads_text()
         << "subsection Geometry\n set Crack interval on Sigma = 0, 0\n"
         << " set Clamped sides = left, right, bottom, top\nend\n"
         << "subsection Mesh\n set Cells along Sigma = 4\n"
         << " set Polynomial degree of layer 1 = 2\n"
         << " set Interface terms in the estimator = false\nend\n"
         << "subsection Solver\n set Method = active set\n"
         << " set Tolerance = 1e-12\nend\n"
         << "subsection Output\n set Output directory = results_exact\n"
         << " set Write VTU = false\n set Terminal output = checks\nend\n";
    std::ostringstream sink;
    Study      study(scene_from_string(text.str(), "volume_load_exact"), sink);
    const bool accepted = study.run();
    double     error    = 0;
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      error = std::max(
        error,
        nodal_error(study.subproblem(Layer::first, sd),
                    study.solutions()[Layout::index(Layer::first, sd)]));
    const CycleRecord &record = study.records().back();
    const double       pi     = exact_energy(-1, 1);
    double             eps2   = 0;
    for (unsigned int c = 0; c < 3; ++c)
      eps2 += (c == 2 ? 2 : 1) * b[c][0] * b[c][0];
    std::ofstream("measured.txt", std::ios::app)
      << "program: nodal error / max |u| = " << error / max_u(-1, 1)
      << ", |Pi_h - Pi| / |Pi| = "
      << std::abs(record.energy - pi) / std::abs(pi)
      << ", eta / (E |eps*|^2 area)^1/2 = "
      << record.eta / std::sqrt(E * eps2 * 4) << std::endl;
    std::cout << "program: run accepted: " << yes(accepted) << std::endl;
    std::cout << "program: nodal error within 1e-10 of max |u|: "
              << yes(error <= 1e-10 * max_u(-1, 1)) << std::endl;
    std::cout << "program: energy equals the exact Pi to 1e-10: "
              << yes(std::abs(record.energy - pi) <= 1e-10 * std::abs(pi))
              << std::endl;
    std::cout << "program: eta (Kelly and the cell residual) below 1e-8 of "
                 "(E |eps*|^2 area)^1/2: "
              << yes(record.eta >= 0 &&
                     record.eta <= 1e-8 * std::sqrt(E * eps2 * 4))
              << std::endl;
  }

  // 5. Zero entries: no VolumeLoad.
  {
    const Scene zeros = scene_from_string(
      "subsection Loads\n subsection Layer 1\n"
      "  set Body force = 0.0; -0\n  set Eigenstrain = 0e0; 0.; 0\n"
      " end\nend\nsubsection Mesh\n set Cells along Sigma = 4\nend\n"
      "subsection Output\n set Output directory = results_zeros\n"
      " set Write VTU = false\n set Terminal output = checks\nend\n",
      "zeros");
    std::ostringstream sink;
    Study              study(zeros, sink);
    study.run();
    bool none = !zeros.loads.has_volume_load(Layer::first) &&
                !zeros.loads.volume_load(Layer::first, 1);
    for (const Layer layer : {Layer::first, Layer::second})
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        none = none && study.subproblem(layer, sd).volume_load() == nullptr;
    std::cout << "zero entries give no VolumeLoad to any subproblem: "
              << yes(none) << std::endl;
  }
}
