// The time-left estimate of a study (progress.h), against what the cycles
// still to come took.
//
// - On sequences that follow its model (unknowns growing geometrically,
//   cost a power of the unknowns) the estimate is silent before two cycles
//   are done (global refinement) or five (adaptive: the first cycles grow
//   less), within a factor 2 of the remaining time at two cycles (its cost
//   exponent still a guess) and exact once the exponent is fitted.
// - On two measured runs (the 2-core development VM, 2026-12-02; wall
//   seconds of each cycle from summary.json: parameter_files/template.prm
//   with 20 adaptive cycles, and parameter_files/partial_closure.prm with
//   the active set and 6 uniform cycles) every estimate that is printed
//   lies within a factor 2 of the time the later cycles took.

#include <bilayer/core/progress.h>

#include <cmath>
#include <iostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "verdict.h"

using namespace bilayer;

namespace
{
  using Run = std::vector<std::pair<double, double>>; // (dofs, seconds)

  /// The largest factor between estimate and truth over the cycles with an
  /// estimate from @p from cycles done on, and whether the estimate is
  /// silent exactly before @p first cycles are done.
  std::pair<double, bool>
  worst_ratio(const Run         &run,
              const bool         adaptive,
              const unsigned int first,
              const unsigned int from = 0)
  {
    double worst  = 1;
    bool   silent = true;
    for (unsigned int done = 1; done < run.size(); ++done)
      {
        std::vector<double> dofs, seconds;
        for (unsigned int i = 0; i < done; ++i)
          dofs.push_back(run[i].first), seconds.push_back(run[i].second);
        double truth = 0;
        for (unsigned int i = done; i < run.size(); ++i)
          truth += run[i].second;
        const TimeLeft left =
          time_left(seconds, dofs, run.size() - done, adaptive);
        if ((left.seconds >= 0) != (done >= first))
          silent = false;
        if (left.seconds >= 0 && done >= from)
          worst =
            std::max(worst,
                     std::max(left.seconds / truth, truth / left.seconds));
      }
    return {worst, silent};
  }

  /// Unknowns growing by @p growth from @p n0, cost 1e-5 N^alpha.
  Run
  model(const double n0, const double growth, const double alpha, const int n)
  {
    Run    run;
    double dofs = n0;
    for (int i = 0; i < n; ++i, dofs *= growth)
      run.emplace_back(dofs, 1e-5 * std::pow(dofs, alpha));
    // Cycle 0 carries one-off costs the estimate must not use.
    run[0].second *= 7;
    return run;
  }
} // namespace


int
main()
{
  {
    const Run run                 = model(1224, 4, 1.3, 7);
    const auto [at_two, silent]   = worst_ratio(run, false, 2);
    const auto [from_three, same] = worst_ratio(run, false, 2, 3);
    std::cout << "global, cost N^1.3: silent before 2 cycles, within a factor "
                 "2, exact from 3 cycles on: "
              << yes(silent && at_two <= 2 && from_three < 1 + 1e-9)
              << std::endl;
  }
  {
    const Run run              = model(4488, 1.2, 1.1, 12);
    const auto [worst, silent] = worst_ratio(run, true, 5);
    std::cout << "adaptive, growth 1.2, cost N^1.1: silent before 5 cycles, "
                 "exact from 5 cycles on: "
              << yes(silent && worst < 1 + 1e-9) << std::endl;
  }

  const Run adaptive_run = {{4488, 0.113},   {4904, 0.068},  {5320, 0.075},
                            {5880, 0.122},   {7160, 0.145},  {8320, 0.179},
                            {10152, 0.208},  {11960, 0.246}, {14960, 0.246},
                            {20000, 0.43},   {24952, 0.368}, {31368, 0.445},
                            {39280, 0.594},  {47408, 0.696}, {58888, 1.108},
                            {74104, 1.262},  {92152, 1.554}, {113888, 2.103},
                            {138176, 2.525}, {163344, 3.874}};
  const Run uniform_run  = {{1224, 0.105},
                            {4488, 0.108},
                            {17160, 0.323},
                            {67080, 1.577},
                            {265224, 9.456},
                            {1054728, 33.163}};
  for (const auto &[name, run, adaptive, first] :
       {std::tuple<const char *, Run, bool, unsigned int>{
          "template.prm, 20 adaptive cycles", adaptive_run, true, 5u},
        std::tuple<const char *, Run, bool, unsigned int>{
          "partial_closure.prm, 6 uniform cycles", uniform_run, false, 2u}})
    {
      const auto [worst, silent] = worst_ratio(run, adaptive, first);
      std::cout << name << ": every estimate within a factor 2: "
                << yes(silent && worst <= 2) << std::endl;
    }
  return 0;
}
