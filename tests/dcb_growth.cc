// Crack growth in the double cantilever beam (parameter_files/dcb.prm on a
// uniform Q2 mesh, 160 cells along Sigma; docs/fracture.md sections 8, 9)
// against beam theory with the root rotation of the arms (chi = 6^(-1/4),
// b = 1, E' = E / (1 - nu^2)):
//
//   G(a; P)      = 12 P^2 (a + chi h)^2 / (E' h^3),
//   delta(a; P)  = 8 P (a + chi h)^3 / (E' h^3)        (load-point opening),
//   P_c(a)       = sqrt(G_c E' h^3 / 12) / (a + chi h)  (critical force),
//   delta_c(a)   = 8 P_c(a) (a + chi h)^3 / (E' h^3)    (its opening).
//
// A sweep at P (lambda = 1) gives, for a = 8 ... 20 (a/h >= 8), G(a; 1),
// the opening delta(a; 1) = (F_1, w) / P (the work-conjugate displacement
// of the pair of forces) and the critical load factor lambda_c(a) =
// sqrt(G_c / G(a; 1)) of the driver; the displacement-controlled branch of
// the growth curve is (lambda_c P, lambda_c delta(a; 1)) by homogeneity.
// Checked: G within 2 %, delta within 3 %, P_c within 1 %, delta_c within
// 3 %, and the driver's critical load equal to sqrt(G_c / G) to 1e-9.
//
// Under load control (load factors rising past lambda_c(8)) G rises with a
// at a fixed force, so the growth is unstable: the crack starts at the
// exact onset lambda_c(8) (to 1e-6) and runs at that load until the tip
// can advance no further; one unstable run is reported, at that load.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  constexpr double P = 1e-3, h = 1, E = 1, nu = 0.3, G_c = 0.01;

  std::string
  dcb_text()
  {
    std::ifstream file(std::string(SOURCE_DIR) + "/../parameter_files/dcb.prm");
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
  }

  Scene
  growth_scene(const std::string &growth, const std::string &factors)
  {
    std::ostringstream s;
    s << dcb_text() << "subsection Geometry\n"
      << " set Crack interval on Sigma = 0, 8\nend\n"
      << "subsection Mesh\n set Refinement = global\n"
      << " set Number of cycles = 1\n set Cells along Sigma = 160\nend\n"
      << "subsection Loads\n set Load factor = " << factors << "\nend\n"
      << "subsection Fracture\n set Crack growth = " << growth
      << "\n set Toughness = " << G_c << "\n set Growth increment = 4\nend\n"
      << "subsection Output\n set Output directory = r_" << growth
      << "\n set Write interface CSV = false\n"
      << " set Terminal output = checks\nend\n";
    return scene_from_string(s.str(), "dcb_growth");
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }
} // namespace

int
main()
{
  const double       chi = std::pow(6., -0.25), Ep = E / (1 - nu * nu);
  std::ostringstream quiet;

  Study sweep(growth_scene("sweep", "1"), quiet);
  check("sweep accepted", sweep.run_growth());
  double worst_G = 0, worst_delta = 0, worst_P = 0, worst_dc = 0,
         worst_shortcut = 0;
  unsigned int lengths  = 0;
  for (const GrowthStep &step : sweep.growth())
    {
      const double a = step.crack_length;
      if (a < 8 * h - 1e-9 || a > 20 * h + 1e-9 || step.tips.empty())
        continue;
      ++lengths;
      const GrowthTip &tip     = step.tips[0];
      const double     arm     = a + chi * h;
      const double     G       = 12 * P * P * arm * arm / (Ep * h * h * h);
      const double     delta   = 8 * P * arm * arm * arm / (Ep * h * h * h);
      const double     P_c     = std::sqrt(G_c * Ep * h * h * h / 12) / arm;
      const double     delta_c = 8 * P_c * arm * arm * arm / (Ep * h * h * h);
      const double     delta_1 = step.conjugate_displacement / P;
      worst_G                  = std::max(worst_G, std::abs(tip.G / G - 1));
      worst_delta = std::max(worst_delta, std::abs(delta_1 / delta - 1));
      worst_P = std::max(worst_P, std::abs(tip.critical_load * P / P_c - 1));
      worst_dc =
        std::max(worst_dc, std::abs(tip.critical_load * delta_1 / delta_c - 1));
      worst_shortcut =
        std::max(worst_shortcut,
                 std::abs(tip.critical_load / std::sqrt(G_c / tip.G) - 1));
    }
  std::cout << "sweep: " << lengths << " crack lengths a/h = 8 ... 20"
            << std::endl;
  check("G(a) within 2 % of beam theory", worst_G < 0.02);
  check("opening delta(a) within 3 % of beam theory", worst_delta < 0.03);
  check("critical force P_c(a) within 1 % of beam theory", worst_P < 0.01);
  check("displacement-controlled branch delta_c(a) within 3 %",
        worst_dc < 0.03);
  check("critical load of the driver = sqrt(G_c / G(a; 1)) to 1e-9",
        worst_shortcut < 1e-9);
  check("every subproblem factorised once",
        sweep.subproblem(Layer::first, Subdomain::minus).n_factorisations() ==
            1 &&
          sweep.subproblem(Layer::first, Subdomain::plus).n_factorisations() ==
            1);

  // Load control: the onset at lambda_c(8), then unstable growth.
  const double lambda_c = sweep.growth().front().tips[0].critical_load;
  Study        load(growth_scene("quasi-static", "0.5:0.5:5"), quiet);
  check("load control accepted", load.run_growth());
  const auto  &steps  = load.growth();
  unsigned int onsets = 0, loads_during_growth = 0;
  double       onset = 0;
  for (const GrowthStep &step : steps)
    if (step.kind == "onset")
      {
        ++onsets;
        onset = step.load_factor;
      }
  const auto runs = unstable_runs(steps);
  for (const GrowthStep &step : steps)
    if (step.kind == "growth" && step.load_factor != onset)
      ++loads_during_growth;
  check("one onset", onsets == 1);
  check("onset at lambda_c(8) of the sweep to 1e-6",
        std::abs(onset / lambda_c - 1) < 1e-6);
  check("every growth step at the onset load", loads_during_growth == 0);
  check("one unstable run, at the onset load, from a = 8",
        runs.size() == 1 && runs[0].load_factor == onset &&
          std::abs(runs[0].from_length - 8) < 1e-9);
  check("the run goes as far as the sweep",
        !runs.empty() && std::abs(runs[0].to_length -
                                  sweep.growth().back().crack_length) < 1e-9);
}
