// The thermal patch test (issue 32): one layer (Materials/Number of layers
// = 1), a uniform temperature change dT and the displacement that frees the
// in-plane stresses prescribed on Gamma_D (clamped left and right), no
// traction. The 3-D thermal strain alpha dT under the plane state leaves
// the free in-plane strain eps_f (docs/problem.md, "Thermal loads"):
//  - isotropic plane strain (eps_zz = 0): sigma_p = 0 and eps_zz = 0 give
//    sigma_zz = -E alpha dT and eps_f = alpha dT (1 + nu) I;
//  - isotropic plane stress (sigma_zz = 0): eps_f = alpha dT I, sigma_zz = 0;
//  - orthotropic plane strain at 30 degrees: in the material axes, with the
//    3-D compliance S (S_11 = 1/E_1, S_13 = -nu_13/E_1, S_23 = -nu_23/E_2,
//    S_33 = 1/E_3), eps_zz = 0 = S_33 sigma_zz + alpha_3 dT gives sigma_zz
//    = -E_3 alpha_3 dT and eps_f,i = S_i3 sigma_zz + alpha_i dT (i = 1, 2),
//    turned to x-y by R(30 degrees): eps_f = R diag(eps_f,1, eps_f,2) R^T;
//    computed here from S, not by the law.
// The finite elements contain w = eps_f x, so the discrete solution is w,
// and (every check against the scale s = E_max alpha dT, alpha the largest
// coefficient):
//  - the in-plane stresses of the VTU output (StressPostprocessor) at the
//    Gauss points of every cell of both subproblems are below 1e-12 s,
//  - its sigma_zz is the value above to 1e-12 s,
//  - the energy (of the plane problem with the plane eigenstrain, without
//    the constant out-of-plane term) is below 1e-12 s |eps_f| area,
//  - |G| at both tips below 1e-12 s |eps_f| and the run accepted;
//  - the same scene without the temperature change is stressed (its
//    largest in-plane stress exceeds 0.1 s).
// Scenes on (-1, 1)^2 (area 4), crack (-0.5, 0.5), Q1, 8 cells along Sigma.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/drivers/study.h>
#include <bilayer/output/output.h>
#include <bilayer/parameters/parameters.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  constexpr double area = 4;

  /// One case: the material entries of layer 1, the temperature change, the
  /// free strain (e11, e22, e12) and the expected sigma_zz.
  struct Case
  {
    std::string           name;
    std::string           material;
    double                dT;
    std::array<double, 3> free_strain;
    double                sigma_zz;
    double                scale; // E_max alpha_max dT
  };

  std::string
  scene_text(const Case &c, const bool thermal)
  {
    const auto        &e = c.free_strain;
    std::ostringstream s;
    s.precision(17);
    s << "subsection Materials\n set Number of layers = 1\n"
      << " subsection Layer 1\n"
      << c.material << " end\nend\n"
      << "subsection Mesh\n set Cells along Sigma = 8\n"
      << " set Polynomial degree of layer 1 = 1\nend\n"
      << "subsection Loads\n set Temperature change = " << (thermal ? c.dT : 0)
      << "\n subsection Layer 1\n  set Prescribed displacement = " << e[0]
      << "*x + " << e[2] << "*y; " << e[2] << "*x + " << e[1] << "*y\n"
      << " end\nend\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-12\nend\n"
      << "subsection Output\n set Output directory = results_thermal_patch\n"
      << " set Write VTU = false\n set Terminal output = checks\nend\n";
    return s.str();
  }

  /// The largest |in-plane stress| and |sigma_zz - @p szz| of the VTU output
  /// at the Gauss points of @p sub.
  std::array<double, 2>
  stress_errors(const ElasticSubproblem &sub,
                const Vector<double>    &w,
                const double             szz)
  {
    const StressPostprocessor        stresses(sub.laws(), sub.volume_load());
    FEValues<2>                      fe_values(sub.mapping(),
                          sub.fe(),
                          QGauss<2>(sub.fe().degree + 1),
                          update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 2>>        grads(fe_values.n_quadrature_points);
    std::array<double, 2>            largest = {{0, 0}};
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
        for (const auto &v : out)
          {
            for (const unsigned int i : {1u, 2u, 4u})
              largest[0] = std::max(largest[0], std::abs(v(i)));
            largest[1] = std::max(largest[1], std::abs(v(3) - szz));
          }
      }
    return largest;
  }

  void
  patch(const Case &c)
  {
    const auto  &e = c.free_strain;
    const double e_norm =
      std::sqrt(e[0] * e[0] + e[1] * e[1] + 2 * e[2] * e[2]);
    std::ostringstream sink;
    Study study(scene_from_string(scene_text(c, true), "thermal_patch"), sink);
    const bool            accepted = study.run();
    std::array<double, 2> error    = {{0, 0}};
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      {
        const auto e_sd =
          stress_errors(study.subproblem(Layer::first, sd),
                        study.solutions()[Layout::index(Layer::first, sd)],
                        c.sigma_zz);
        error[0] = std::max(error[0], e_sd[0]);
        error[1] = std::max(error[1], e_sd[1]);
      }
    const CycleRecord &r         = study.records().back();
    double             largest_G = 0;
    for (const EnergyReleaseRate &g : r.release)
      largest_G =
        std::max(largest_G, std::isfinite(g.G) ? std::abs(g.G) : 1e300);
    std::ofstream("measured.txt", std::ios::app)
      << c.name << ": in-plane stress / s = " << error[0] / c.scale
      << ", |sigma_zz - expected| / s = " << error[1] / c.scale << " (expected "
      << c.sigma_zz << "), |Pi| / (s |eps_f| area) = "
      << std::abs(r.energy) / (c.scale * e_norm * area)
      << ", |G| / (s |eps_f|) = " << largest_G / (c.scale * e_norm)
      << std::endl;
    std::cout << c.name << ": accepted: " << yes(accepted) << std::endl;
    std::cout << c.name << ": in-plane output stresses below 1e-12 s: "
              << yes(error[0] < 1e-12 * c.scale) << std::endl;
    std::cout << c.name << ": output sigma_zz the expected value to 1e-12 s: "
              << yes(error[1] < 1e-12 * c.scale) << std::endl;
    std::cout << c.name << ": energy below 1e-12 s |eps_f| area: "
              << yes(std::abs(r.energy) < 1e-12 * c.scale * e_norm * area)
              << std::endl;
    std::cout << c.name << ": G below 1e-12 s |eps_f| at both tips: "
              << yes(r.release.size() == 2 &&
                     largest_G < 1e-12 * c.scale * e_norm)
              << std::endl;

    std::ostringstream plain_sink;
    Study plain(scene_from_string(scene_text(c, false), "thermal_patch"),
                plain_sink);
    plain.run();
    const auto plain_error = stress_errors(
      plain.subproblem(Layer::first, Subdomain::minus),
      plain.solutions()[Layout::index(Layer::first, Subdomain::minus)],
      0);
    std::cout << c.name
              << ": without the temperature change the largest in-plane "
                 "stress exceeds 0.1 s: "
              << yes(plain_error[0] > 0.1 * c.scale) << std::endl;
  }

  /// The orthotropic case: the free strain and sigma_zz from the 3-D
  /// compliance in the material axes, turned by @p angle.
  Case
  orthotropic_case()
  {
    const double E1 = 150, E2 = 60, E3 = 40, nu12 = 0.25, nu13 = 0.3,
                 nu23 = 0.35, G12 = 30, angle = 30;
    const double a1 = 2e-6, a2 = 3e-5, a3 = 1.5e-5, dT = 80;
    const double S13 = -nu13 / E1, S23 = -nu23 / E2, S33 = 1 / E3;
    const double szz = -a3 * dT / S33;
    const double f1  = S13 * szz + a1 * dT;
    const double f2  = S23 * szz + a2 * dT;
    const double t   = angle * numbers::PI / 180;
    const double c = std::cos(t), s = std::sin(t);
    // R diag(f1, f2) R^T, R = [[c, -s], [s, c]].
    const std::array<double, 3> free = {
      {c * c * f1 + s * s * f2, s * s * f1 + c * c * f2, c * s * (f1 - f2)}};
    std::ostringstream m;
    m.precision(17);
    m << "  set Law = orthotropic\n  set E_1 = " << E1 << "\n  set E_2 = " << E2
      << "\n  set E_3 = " << E3 << "\n  set nu_12 = " << nu12
      << "\n  set nu_13 = " << nu13 << "\n  set nu_23 = " << nu23
      << "\n  set G_12 = " << G12 << "\n  set Orientation angle = " << angle
      << "\n  set Thermal expansion = " << a1 << ", " << a2 << ", " << a3
      << "\n";
    return {"orthotropic plane strain, 30 degrees",
            m.str(),
            dT,
            free,
            szz,
            E1 * a2 * dT};
  }
} // namespace


int
main()
{
  std::ofstream("measured.txt", std::ios::trunc) << "";
  const double E = 200, nu = 0.28, alpha = 1e-5, dT = 100;
  const double strain = (1 + nu) * alpha * dT;
  patch({"isotropic plane strain",
         "  set Thermal expansion = 1e-5\n",
         dT,
         {{strain, strain, 0}},
         -E * alpha * dT,
         E * alpha * dT});
  patch({"isotropic plane stress",
         "  set Plane state = plane stress\n  set Thermal expansion = 1e-5\n",
         dT,
         {{alpha * dT, alpha * dT, 0}},
         0,
         E * alpha * dT});
  patch(orthotropic_case());
}
