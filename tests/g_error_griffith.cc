// The error bar dG of the energy release rate on a run (Study): Griffith's
// crack in mode I (one layer, E = 1, nu = 0.3, the crack (-0.05, 0.05) in
// the square (-1, 1)^2, the displacement of the uniform tension 1e-3
// prescribed on the whole boundary; adaptive Q2 from 20 cells along Sigma,
// as parameter_files/griffith.prm), 16 cycles. G converges under adaptive
// refinement (docs/fracture.md: within 1 % of the infinite plate at 12
// cycles, the rest the finite-size correction); the reference G_ref is G
// of the last cycle, four or more cycles finer than the cycles judged.
//
// Asserted, at both tips:
// - on every cycle where G is reported and the previous cycles too, dG is
//   finite, and its estimator is named in summary.json;
// - on cycles 3 to 11 (G is first reported on cycle 2, where it has no
//   error bar yet), the true error |G - G_ref| <= dG (effectivity >= 1),
//   and the median effectivity dG / |G - G_ref| is at most 10 (not
//   absurdly pessimistic: single cycles where G crosses G_ref have a tiny
//   error and a larger effectivity);
// - the single-mesh indicator |G(R) - G(R/2)| is available where R/2 holds
//   a cell at the tip, and on cycle 0, where R = 0.05 holds no cell of 0.1,
//   neither G nor dG is reported;
// - summary.json carries "G_error" and "G_error_estimate", table.csv the
//   column dG_tip<k> right after G_tip<k> with the values of summary.json.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "verdict.h"

using namespace bilayer;

int
main()
{
  const unsigned int n_cycles = 16, first_judged = 3, last_judged = 11;
  std::ostringstream s;
  s << "subsection Geometry\n set Crack interval on Sigma = -0.05, 0.05\n"
    << " set Clamped sides = left, right, bottom, top\nend\n"
    << "subsection Mesh\n set Cells along Sigma = 20\n"
    << " set Fit crack tips = true\n"
    << " set Polynomial degree of layer 1 = 2\n"
    << " set Refinement = adaptive\n set Refinement fraction = 0.8\n"
    << " set Number of cycles = " << n_cycles << "\nend\n"
    << "subsection Materials\n set Number of layers = 1\n"
    << " subsection Layer 1\n  set Young's modulus = 1\n"
    << "  set Poisson's ratio = 0.3\n end\nend\n"
    << "subsection Loads\n set Constants = s = 1e-3; exx = -nu1*(1+nu1)*s/E1;"
    << " eyy = (1-nu1^2)*s/E1\n subsection Layer 1\n"
    << "  set Prescribed displacement = exx*x; eyy*y\n end\nend\n"
    << "subsection Solver\n set Method = active set\nend\n"
    << "subsection Output\n set Output directory = results\n"
    << " set Write VTU = false\n set Write interface CSV = false\n"
    << " set Terminal output = checks\nend\n";
  std::ostringstream sink;
  Study      study(scene_from_string(s.str(), "g_error_griffith"), sink);
  const bool accepted = study.run();
  std::cout << "every cycle accepted: " << yes(accepted) << std::endl;
  const auto &records = study.records();
  if (records.size() != n_cycles || records.back().release.size() != 2)
    {
      std::cout << "not 16 cycles with two tips" << std::endl;
      return 0;
    }

  bool bounded = true, finite = true, named = true, support = false;
  std::vector<double> effectivities;
  for (unsigned int t = 0; t < 2; ++t)
    {
      const double G_ref = records.back().release[t].G;
      for (unsigned int c = 0; c < records.size(); ++c)
        {
          const EnergyReleaseRate &g = records[c].release[t];
          const bool               previous_reported =
            c > 0 && std::isfinite(records[c - 1].release[t].G);
          if (std::isfinite(g.G) && previous_reported)
            finite = finite && std::isfinite(g.error);
          if (std::isfinite(g.error))
            named = named && (g.error_estimate == "cycles" ||
                              g.error_estimate == "support radius" ||
                              g.error_estimate == "cycles and support radius");
          support = support || std::isfinite(g.G_half_support);
          if (c >= first_judged && c <= last_judged)
            {
              const double error = std::abs(g.G - G_ref);
              bounded            = bounded && g.error >= error;
              effectivities.push_back(g.error / error);
            }
        }
    }
  std::cout << "dG finite on every cycle after one that reports G: "
            << yes(finite) << std::endl;
  std::cout << "the estimator named: " << yes(named) << std::endl;
  std::sort(effectivities.begin(), effectivities.end());
  std::cout << "cycles 3-11: |G - G_ref| <= dG at both tips: " << yes(bounded)
            << std::endl;
  std::cout << "cycles 3-11: median effectivity dG / |G - G_ref| <= 10: "
            << yes(effectivities.size() == 18 &&
                   effectivities[effectivities.size() / 2] <= 10)
            << std::endl;
  std::cout << "G(R/2) evaluated on the finer cycles: " << yes(support)
            << std::endl;
  std::cout << "cycle 0 (R = 0.05 on cells of 0.1): neither G nor dG: "
            << yes(std::isnan(records[0].release[0].G) &&
                   std::isnan(records[0].release[0].error) &&
                   records[0].release[0].error_estimate.rfind("none: ", 0) == 0)
            << std::endl;

  // summary.json and table.csv.
  std::ifstream     json_file("results/summary.json");
  std::stringstream json;
  json << json_file.rdbuf();
  std::cout << "summary.json: G_error and G_error_estimate at the tips: "
            << yes(json.str().find("\"G_error\": null") != std::string::npos &&
                   json.str().find("\"G_error_estimate\": \"cycles") !=
                     std::string::npos)
            << std::endl;
  std::ifstream csv("results/table.csv");
  std::string   line;
  unsigned int  notes = 0;
  while (std::getline(csv, line) && line.rfind("# ", 0) == 0)
    ++notes;
  std::cout << "table.csv: one note per tip: " << yes(notes == 2) << std::endl;
  std::cout << "table.csv: dG_tip<k> right after G_tip<k>: "
            << yes(line.find(",G_tip1,dG_tip1,G_tip2,dG_tip2") !=
                   std::string::npos)
            << std::endl;
  // The last row: dG_tip1 is the fourth value from the end.
  std::string last;
  while (std::getline(csv, line))
    last = line;
  std::vector<std::string> values;
  std::stringstream        row(last);
  for (std::string v; std::getline(row, v, ',');)
    values.push_back(v);
  std::cout << "table.csv: the last row's dG_tip1 is summary.json's: "
            << yes(values.size() >= 4 &&
                   std::abs(std::stod(values[values.size() - 3]) -
                            records.back().release[0].error) <=
                     1e-12 * records.back().release[0].error)
            << std::endl;
}
