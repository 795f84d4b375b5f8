// The eigenstrain patch test: a uniform eigenstrain eps* with the matching
// displacement w = eps* x (w_i = eps*_ij x_j) prescribed on Gamma_D and no
// traction leaves the body stress free, sigma = C (eps(w) - eps*) = 0,
// whatever the materials: the finite elements contain w, so the discrete
// solution is w, and
//  - the stresses of the VTU output (StressPostprocessor: sigma, sigma_zz,
//    von Mises) at the Gauss points of every cell of every subproblem are
//    below 1e-12 E |eps*|,
//  - the energy of the eigenstrained body 1/2 int (eps - eps*) : C (eps -
//    eps*) is below 1e-12 E |eps*|^2 area (it is 0; without the constant
//    1/2 int eps* : C eps* it would be minus that: -E* < 0),
//  - the crack (closed, no load across it) releases nothing: |G| below
//    1e-12 E |eps*|^2 L at both tips,
//  - the error estimate (Kelly's jumps, the Sigma residual with sigma =
//    C (eps - eps*), the cell residual) is below 1e-10 (E |eps*|^2
//    area)^1/2,
//  - the run is accepted.
// |eps*| is the Frobenius norm, E the larger Young's modulus, area = 4.
// Scenes on (-1, 1)^2, crack (-0.5, 0.5), clamped left and right:
// 1. one layer (Materials/Number of layers = 1), Q1;
// 2. two layers of different materials with the same eigenstrain, Q2;
// 3. scene 2 refined adaptively (three cycles: the estimator with a volume
//    load drives the refinement), every cycle as above.
// The same scenes without the eigenstrain (and the same prescribed
// displacement) are stressed: their largest stress exceeds 0.1 E |eps*|.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/drivers/study.h>
#include <bilayer/output/output.h>
#include <bilayer/parameters/parameters.h>

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
  constexpr double e11 = 1e-3, e22 = -2e-3, e12 = 5e-4;
  const double     eps_norm = std::sqrt(e11 * e11 + e22 * e22 + 2 * e12 * e12);
  constexpr double E_max    = 200; // Example 1's layer 1
  constexpr double area     = 4;

  std::string
  scene_text(const unsigned int layers,
             const unsigned int degree,
             const bool         adaptive,
             const bool         eigenstrain)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Materials\n set Number of layers = " << layers << "\nend\n"
      << "subsection Mesh\n set Cells along Sigma = 8\n"
      << " set Polynomial degree of layer 1 = " << degree << "\n"
      << " set Polynomial degree of layer 2 = " << degree << "\n"
      << (adaptive ? " set Refinement = adaptive\n set Number of cycles = 3\n" :
                     "")
      << "end\n"
      << "subsection Loads\n set Constants = e11 = " << e11 << "; e22 = " << e22
      << "; e12 = " << e12 << "\n";
    for (unsigned int l = 1; l <= layers; ++l)
      s << " subsection Layer " << l << "\n"
        << (eigenstrain ? "  set Eigenstrain = e11; e22; e12\n" : "")
        << "  set Prescribed displacement = e11*x + e12*y; e12*x + e22*y\n"
        << " end\n";
    s << "end\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-12\nend\n"
      << "subsection Output\n set Output directory = results_patch\n"
      << " set Write VTU = false\n set Terminal output = checks\nend\n";
    return s.str();
  }

  /// The largest |stress_xx|, |stress_yy|, |stress_zz|, |stress_xy| and von
  /// Mises of the VTU output at the Gauss points of @p sub.
  double
  largest_stress(const ElasticSubproblem &sub, const Vector<double> &w)
  {
    const StressPostprocessor        stresses(sub.laws(), sub.volume_load());
    FEValues<2>                      fe_values(sub.mapping(),
                          sub.fe(),
                          QGauss<2>(sub.fe().degree + 1),
                          update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, 2>>        grads(fe_values.n_quadrature_points);
    double                           largest = 0;
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
          largest = std::max(largest, v.linfty_norm());
      }
    return largest;
  }

  void
  patch(const std::string &name,
        const unsigned int layers,
        const unsigned int degree,
        const bool         adaptive)
  {
    std::ostringstream sink;
    Study study(scene_from_string(scene_text(layers, degree, adaptive, true),
                                  "eigenstrain_patch"),
                sink);
    const bool accepted = study.run();
    double     stress   = 0;
    for (const Layer layer : {Layer::first, Layer::second})
      if (layer == Layer::first || layers == 2)
        for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
          stress = std::max(
            stress,
            largest_stress(study.subproblem(layer, sd),
                           study.solutions()[Layout::index(layer, sd)]));
    bool energy = true, released = true, estimate = true;
    for (const CycleRecord &r : study.records())
      {
        energy = energy && std::abs(r.energy) <
                             1e-12 * E_max * eps_norm * eps_norm * area;
        for (const EnergyReleaseRate &g : r.release)
          released = released && std::isfinite(g.G) &&
                     std::abs(g.G) < 1e-12 * E_max * eps_norm * eps_norm;
        estimate = estimate && r.eta < 1e-10 * std::sqrt(E_max * eps_norm *
                                                         eps_norm * area);
      }
    {
      // The numbers, for the report (not compared: measured.txt in the
      // test's directory).
      double largest_energy = 0, largest_G = 0, largest_eta = 0;
      for (const CycleRecord &r : study.records())
        {
          largest_energy = std::max(largest_energy, std::abs(r.energy));
          largest_eta    = std::max(largest_eta, r.eta);
          for (const EnergyReleaseRate &g : r.release)
            largest_G = std::max(largest_G, std::abs(g.G));
        }
      std::ofstream("measured.txt", std::ios::app)
        << name << ": max stress / (E |eps*|) = " << stress / (E_max * eps_norm)
        << ", |Pi| / (E |eps*|^2 area) = "
        << largest_energy / (E_max * eps_norm * eps_norm * area)
        << ", |G| / (E |eps*|^2) = "
        << largest_G / (E_max * eps_norm * eps_norm)
        << ", eta / (E |eps*|^2 area)^1/2 = "
        << largest_eta / std::sqrt(E_max * eps_norm * eps_norm * area)
        << std::endl;
    }
    std::cout << name << ": every cycle accepted: "
              << yes(accepted && study.records().size() == (adaptive ? 3 : 1))
              << std::endl;
    std::cout << name << ": largest output stress below 1e-12 E |eps*|: "
              << yes(stress < 1e-12 * E_max * eps_norm) << std::endl;
    std::cout << name << ": energy below 1e-12 E |eps*|^2 area: " << yes(energy)
              << std::endl;
    std::cout << name << ": G below 1e-12 E |eps*|^2 L at both tips: "
              << yes(released && study.records().back().release.size() == 2)
              << std::endl;
    std::cout << name
              << ": eta below 1e-10 (E |eps*|^2 area)^1/2: " << yes(estimate)
              << std::endl;

    // Without the eigenstrain the prescribed displacement stresses the body.
    std::ostringstream plain_sink;
    Study plain(scene_from_string(scene_text(layers, degree, false, false),
                                  "eigenstrain_patch"),
                plain_sink);
    plain.run();
    std::cout
      << name
      << ": without the eigenstrain the largest stress exceeds 0.1 E "
         "|eps*|: "
      << yes(
           largest_stress(
             plain.subproblem(Layer::first, Subdomain::minus),
             plain.solutions()[Layout::index(Layer::first, Subdomain::minus)]) >
           0.1 * E_max * eps_norm)
      << std::endl;
  }
} // namespace


int
main()
{
  std::ofstream("measured.txt", std::ios::trunc) << "";
  patch("one layer, Q1", 1, 1, false);
  patch("two layers, Q2", 2, 2, false);
  patch("two layers, Q2, adaptive", 2, 2, true);
}
