// Quasi-static crack growth under proportional loading (Study::run_growth,
// docs/fracture.md section 9), on Examples 1 and 2 of the paper with a
// toughness that rises along Sigma (G_c = g0 (1 + 8 (|x| - 0.5))), so that
// the growth is stable: each crack length has its own critical load.
//
// The problem is positively homogeneous of degree one in the load factor
// (frictionless contact, zero gap, no preload), so G(l; lambda) = lambda^2
// G(l; 1) and the critical load of a crack of length l is exactly
// lambda_c(l) = sqrt(G_c / G(l; 1)). Three runs on one mesh:
//  - a sweep at lambda = 1 (the growing tips advance vertex by vertex
//    whatever their criterion): G(l; 1) of every crack length, and from it
//    sqrt(G_c / G(l; 1)) computed here;
//  - quasi-static growth with exact onsets (load factors 0.5:0.5:6): every
//    crack length must start to grow at an "onset" step whose load factor
//    is sqrt(G_c / G(l; 1)) of the sweep (to 1e-6), with the criterion 1
//    there (to 1e-8); the crack lengths follow the sweep's;
//  - the same with the load factors 2.5, 6, the first above the first
//    onset: loading starts at 0, so step 0 is that onset (found below the
//    first load factor) and the onsets are those of 0.5:0.5:6;
//  - quasi-static growth on load factors alone (0.5:0.05:6, Exact onsets =
//    false): each crack length first grows at the first load factor at or
//    above its critical load (the onsets are bracketed by the step).
// Each run factorises each subproblem once.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::string
  scene_text(const std::string &loads,
             const std::string &growth,
             const std::string &factors,
             const std::string &tips,
             const bool         exact,
             const double       g0,
             const std::string &directory)
  {
    std::ostringstream s;
    s << std::setprecision(17)
      << "subsection Geometry\n set Crack interval on Sigma = -0.5, 0.5\n"
         " set Clamped sides = left, right\nend\n"
         "subsection Mesh\n set Cells along Sigma = 32\nend\n"
         "subsection Loads\n set Constants = c = 1e-3*mu1\n"
         " set Load factor = "
      << factors << "\n subsection Layer 1\n"
      << loads
      << " end\nend\n"
         "subsection Solver\n set Method = active set\n"
         " set Tolerance = 1e-12\nend\n"
         "subsection Fracture\n set Crack growth = "
      << growth << "\n set Toughness = " << g0
      << "*(1 + 8*(abs(x) - 0.5))\n set Growing tips = " << tips
      << "\n set Exact onsets = " << (exact ? "true" : "false")
      << "\nend\n"
         "subsection Output\n set Output directory = "
      << directory
      << "\n set Write VTU = false\n set Write interface CSV = false\n"
         " set Terminal output = checks\nend\n";
    return s.str();
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << yes(ok) << std::endl;
  }

  bool
  factorised_once(const Study &study)
  {
    bool once = true;
    for (const Layer l : {Layer::first, Layer::second})
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        once = once && study.subproblem(l, sd).n_factorisations() == 1;
    return once;
  }

  /// The crack length rounded to the mesh (a key).
  long
  key(const double length)
  {
    return std::lround(length * 1e6);
  }

  void
  example(const std::string &name,
          const std::string &loads,
          const std::string &tips)
  {
    std::cout << name << std::endl;
    std::ostringstream quiet;
    // G(l; 1) of the sweep; g0 from the initial crack so that the first
    // onset is at lambda = 1.7.
    Study sweep(scene_from_string(
                  scene_text(loads, "sweep", "1", tips, true, 1, "r_sweep"),
                  "crack_growth_onsets"),
                quiet);
    check("sweep accepted", sweep.run_growth());
    const auto &swept = sweep.growth();
    double      G0    = 0;
    for (const GrowthTip &tip : swept.front().tips)
      if (tip.present && tip.status != "held")
        G0 = std::max(G0, tip.G);
    const double g0 = 1.7 * 1.7 * G0;
    // The critical load of each swept crack length: the smallest over its
    // growing tips of sqrt(G_c / G(l; 1)).
    std::map<long, double> critical;
    for (const GrowthStep &step : swept)
      {
        double lambda_c = std::numeric_limits<double>::infinity();
        for (const GrowthTip &tip : step.tips)
          if (tip.present && tip.status != "held" && tip.G > 0 &&
              tip.status.rfind("stopped", 0) != 0)
            lambda_c =
              std::min(lambda_c,
                       std::sqrt(g0 * (1 + 8 * (std::abs(tip.point[0]) - 0.5)) /
                                 tip.G));
        critical[key(step.crack_length)] = lambda_c;
      }
    std::cout << "  sweep: " << swept.size() << " crack lengths from "
              << swept.front().crack_length << " to "
              << swept.back().crack_length << std::endl;
    check("sweep: subproblems factorised once", factorised_once(sweep));

    // Exact onsets.
    Study exact(
      scene_from_string(
        scene_text(
          loads, "quasi-static", "0.5:0.5:6", tips, true, g0, "r_exact"),
        "crack_growth_onsets"),
      quiet);
    check("exact onsets accepted", exact.run_growth());
    double       worst_onset = 0, worst_criterion = 0;
    unsigned int onsets = 0, unknown = 0;
    for (const GrowthStep &step : exact.growth())
      if (step.kind == "onset")
        {
          ++onsets;
          const auto found = critical.find(key(step.crack_length));
          if (found == critical.end())
            {
              ++unknown;
              continue;
            }
          worst_onset =
            std::max(worst_onset,
                     std::abs(step.load_factor / found->second - 1));
          double f = 0;
          for (const GrowthTip &tip : step.tips)
            if (tip.present && tip.status != "held" &&
                std::isfinite(tip.criterion))
              f = std::max(f, tip.criterion);
          worst_criterion = std::max(worst_criterion, std::abs(f - 1));
        }
    std::cout << "  exact: " << exact.growth().size() << " steps, " << onsets
              << " onsets, final crack length "
              << exact.growth().back().crack_length << std::endl;
    check("at least 3 onsets", onsets >= 3);
    check("every onset at a swept crack length", unknown == 0);
    check("onsets = sqrt(G_c / G(l; 1)) of the sweep to 1e-6",
          worst_onset < 1e-6);
    check("criterion 1 at every onset to 1e-8", worst_criterion < 1e-8);
    check("exact: subproblems factorised once", factorised_once(exact));

    // Loading starts at 0: with load factors whose first lies above the
    // first onset (2.5 > 1.7), the onset is found below it (the state at
    // 2.5 is never the first step) and every onset is that of 0.5:0.5:6.
    Study above(
      scene_from_string(
        scene_text(loads, "quasi-static", "2.5, 6", tips, true, g0, "r_above"),
        "crack_growth_onsets"),
      quiet);
    check("first load factor above the onset accepted", above.run_growth());
    std::vector<double> onsets_exact, onsets_above;
    for (const GrowthStep &s : exact.growth())
      if (s.kind == "onset")
        onsets_exact.push_back(s.load_factor);
    for (const GrowthStep &s : above.growth())
      if (s.kind == "onset")
        onsets_above.push_back(s.load_factor);
    bool same = onsets_exact.size() == onsets_above.size();
    for (unsigned int k = 0; same && k < onsets_exact.size(); ++k)
      same = std::abs(onsets_above[k] / onsets_exact[k] - 1) < 1e-9;
    const GrowthStep &start = above.growth().front();
    check("first load factor above the onset: step 0 is the onset at "
          "sqrt(G_c / G(l_0; 1)) (1e-6)",
          start.kind == "onset" &&
            std::abs(start.load_factor / critical[key(start.crack_length)] -
                     1) < 1e-6);
    check("first load factor above the onset: the onsets of 0.5:0.5:6 "
          "(1e-9) and the same final crack length",
          same && key(above.growth().back().crack_length) ==
                    key(exact.growth().back().crack_length));

    // Load factors alone: each crack length first grows at the first load
    // factor at or above its critical load.
    const double step = 0.05;
    Study        stepped(
      scene_from_string(
        scene_text(
          loads, "quasi-static", "0.5:0.05:6", tips, false, g0, "r_stepped"),
        "crack_growth_onsets"),
      quiet);
    check("stepped accepted", stepped.run_growth());
    const auto  &steps     = stepped.growth();
    bool         bracketed = true;
    unsigned int grown     = 0;
    for (unsigned int k = 1; k < steps.size(); ++k)
      if (steps[k].kind == "growth" && steps[k - 1].kind == "load")
        {
          // The crack of step k - 1 started to grow at its load factor.
          const auto   found  = critical.find(key(steps[k - 1].crack_length));
          const double lambda = steps[k - 1].load_factor;
          ++grown;
          bracketed = bracketed && found != critical.end() &&
                      lambda >= found->second * (1 - 1e-9) &&
                      lambda < found->second + step + 1e-9;
        }
    check("stepped: growth starts within one load step above each onset",
          bracketed && grown >= 3);
    check("stepped: the same final crack length as exact onsets",
          key(steps.back().crack_length) ==
            key(exact.growth().back().crack_length));
  }
} // namespace

int
main()
{
  example("Example 2 (full opening), both tips",
          "  set Traction on bottom side = 0; -c\n"
          "  set Traction on top side = 0; c\n",
          "all");
  example("Example 1 (partial closure), tip 1",
          "  set Traction on bottom side = 0; c*x\n"
          "  set Traction on top side = 0; -c*x\n",
          "1");
}
