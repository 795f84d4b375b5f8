// The critical temperature change of a film (Loads/Load factor scales =
// thermal; docs/fracture.md section 9): parameter_files/thin_film.prm, an
// aluminium film on a silicon substrate (one layer, per-side materials)
// cooled by dT = -200 with an interface crack from its free end, on one
// uniform mesh (global refinement).
//
// With the factors scaling the temperature change alone and no mechanical
// load, the problem is positively homogeneous of degree one in lambda
// (frictionless contact, zero gap, the eigenstrain lambda alpha dT), so
// G(lambda dT) = lambda^2 G(dT) and the energy is lambda^2 Pi(dT) (the
// eigenstrain energy included). The critical temperature change for a
// toughness G_c is therefore dT_c = dT sqrt(G_c / G(dT)), with G(dT) from a
// static run of the scene. The toughness rises ahead of the tip, G_c (1 +
// (x - 5)), so that the growth after the onset arrests within a few steps.
// Checks:
//  - the growth driver's onset load factor times dT equals dT_c to 1e-8,
//    with load factors that bracket it (0.5:0.5:2) and with load factors
//    whose first lies above it (1.5, 2: loading starts at 0);
//  - the energy of the load steps over lambda^2 is Pi(dT) to 1e-9;
//  - the same scene with the default Load factor scales = mechanical (no
//    mechanical load: the factors would scale nothing) is refused.

#include <deal.II/base/exceptions.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::string
  scene_text(const std::string &extra)
  {
    return "subsection Geometry\n"
           " set Lower left corner = 0, -10\n set Upper right corner = 20, 1\n"
           " set Height of Sigma = 0\n set Crack interval on Sigma = 0, 5\n"
           " set Clamped sides = right\nend\n"
           "subsection Mesh\n set Cells along Sigma = 40\n"
           " set Polynomial degree of layer 1 = 2\n"
           " set Refinement = global\n set Number of cycles = 2\nend\n"
           "subsection Materials\n set Number of layers = 1\n"
           " subsection Layer 1\n  set Young's modulus = 170\n"
           "  set Poisson's ratio = 0.28\n  set Thermal expansion = 2.6e-6\n"
           "  subsection Omega+\n   set Young's modulus = 70\n"
           "   set Poisson's ratio = 0.35\n   set Thermal expansion = 23e-6\n"
           "  end\n end\nend\n"
           "subsection Contact\n set Non-penetration on the crack = true\nend\n"
           "subsection Solver\n set Method = active set\n"
           " set Tolerance = 1e-12\nend\n"
           "subsection Output\n set Output directory = r_thermal_onset\n"
           " set Write VTU = false\n set Write interface CSV = false\n"
           " set Terminal output = checks\nend\n" +
           extra;
  }

  std::string
  growth_text(const double G_c, const std::string &factors, const bool thermal)
  {
    std::ostringstream s;
    s << std::setprecision(17)
      << "subsection Loads\n set Temperature change = -200\n"
      << " set Load factor = " << factors << "\n"
      << (thermal ? " set Load factor scales = thermal\n" : "") << "end\n"
      << "subsection Fracture\n set Crack growth = quasi-static\n"
      << " set Toughness = " << G_c << "*(1 + (x - 5))\nend\n";
    return s.str();
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
  std::ostringstream quiet;
  Study              base(scene_from_string(
               scene_text("subsection Loads\n set Temperature change = -200\n"
                                       "end\nsubsection Fracture\n"
                                       " set Energy release rate = true\nend\n"),
               "thermal_onset"),
             quiet);
  check("static run accepted", base.run());
  const CycleRecord &last = base.records().back();
  check("one crack tip", last.release.size() == 1);
  const double G  = last.release.at(0).G;
  const double Pi = last.energy;
  const double dT = -200;
  // A toughness 1.3 times G(dT): dT_c = dT sqrt(1.3).
  const double G_c  = 1.3 * G;
  const double dT_c = dT * std::sqrt(G_c / G);

  for (const std::string factors : {"0.5:0.5:2", "1.5, 2"})
    {
      Study      growth(scene_from_string(scene_text(
                                       growth_text(G_c, factors, true)),
                                     "thermal_onset"),
                   quiet);
      const bool accepted = growth.run_growth();
      double     onset = std::numeric_limits<double>::quiet_NaN(), worst = 0;
      for (const GrowthStep &step : growth.growth())
        {
          if (step.kind == "onset" && std::isnan(onset))
            onset = step.load_factor;
          if (step.kind == "load" && step.step + 1 < growth.growth().size() &&
              growth.growth()[step.step + 1].kind != "growth" &&
              step.crack_length == 5)
            worst =
              std::max(worst,
                       std::abs(step.energy /
                                  (step.load_factor * step.load_factor) / Pi -
                                1));
        }
      std::cout << "load factors " << factors
                << ": the first step: " << growth.growth().front().kind
                << std::endl;
      check("  accepted", accepted);
      check("  onset load factor times dT = dT sqrt(G_c / G(dT)) (1e-8)",
            std::abs(onset * dT / dT_c - 1) < 1e-8);
      check("  energy of the load steps before the onset = lambda^2 Pi(dT) "
            "(1e-9)",
            worst < 1e-9);
    }

  // The factors of a scene without a mechanical load scale nothing with
  // the default Load factor scales = mechanical: refused.
  std::string refusal;
  try
    {
      Study growth(scene_from_string(scene_text(
                                       growth_text(G_c, "0.9:0.05:1.2", false)),
                                     "thermal_onset"),
                   quiet);
      growth.run_growth();
    }
  catch (const std::exception &e)
    {
      refusal = e.what();
    }
  check("factors that scale nothing refused, naming Loads/Load factor scales",
        refusal.find("Loads/Load factor scales = mechanical") !=
          std::string::npos);
}
