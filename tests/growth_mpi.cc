// Crack growth under MPI: the growth driver's steps (the load factors, the
// exact onsets, the tips' advance) are decided from G, which every process
// receives, so every process takes the same steps. Run by 1, 2 and 4
// processes (the .mpirun=N outputs), quasi-static growth of Example 2 with
// a toughness rising along Sigma and two displacement points must give the
// steps of the serial run (a Study of the first process alone,
// MPI_COMM_SELF): the same kinds and crack lengths, and the load factors,
// energies, G, criteria, conjugate displacements and point displacements
// to 1e-10. With more than four processes a subproblem is shared by a
// group, which keeps the load of its set-up: a load factor other than 1 is
// refused by every process together (the .mpirun=6 output).

#include <deal.II/base/mpi.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/subproblem/distribution.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  double
  relative(const double a, const double b)
  {
    if (a == b)
      return 0;
    return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
  }

  /// The largest relative difference of the numbers of two step lists,
  /// or infinity where they differ in their steps or tips.
  double
  difference(const std::vector<GrowthStep> &a, const std::vector<GrowthStep> &b)
  {
    if (a.size() != b.size())
      return 1. / 0.;
    double worst = 0;
    for (unsigned int k = 0; k < a.size(); ++k)
      {
        if (a[k].kind != b[k].kind || a[k].tips.size() != b[k].tips.size() ||
            a[k].crack_length != b[k].crack_length ||
            a[k].point_displacements.size() != b[k].point_displacements.size())
          return 1. / 0.;
        for (const auto &[x, y] :
             {std::pair{a[k].load_factor, b[k].load_factor},
              std::pair{a[k].energy, b[k].energy},
              std::pair{a[k].conjugate_displacement,
                        b[k].conjugate_displacement}})
          worst = std::max(worst, relative(x, y));
        for (unsigned int p = 0; p < a[k].point_displacements.size(); ++p)
          worst = std::max(
            worst,
            (a[k].point_displacements[p] - b[k].point_displacements[p]).norm() /
              a[k].point_displacements[p].norm());
        for (unsigned int t = 0; t < a[k].tips.size(); ++t)
          {
            const GrowthTip &ta = a[k].tips[t], &tb = b[k].tips[t];
            if (ta.present != tb.present || ta.s != tb.s ||
                ta.status != tb.status)
              return 1. / 0.;
            if (ta.present)
              worst = std::max({worst,
                                relative(ta.G, tb.G),
                                relative(ta.criterion, tb.criterion)});
          }
      }
    return worst;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Distribution              &all = Distribution::world();
  const std::string                text =
    "subsection Geometry\n set Crack interval on Sigma = -0.5, 0.5\n"
    " set Clamped sides = left, right\nend\n"
    "subsection Mesh\n set Cells along Sigma = 32\nend\n"
    "subsection Loads\n set Constants = c = 1e-3*mu1\n"
    " set Load factor = 0.5:0.5:4\n subsection Layer 1\n"
    "  set Traction on bottom side = 0; -c\n"
    "  set Traction on top side = 0; c\n end\nend\n"
    "subsection Solver\n set Method = active set\n"
    " set Tolerance = 1e-12\nend\n"
    "subsection Fracture\n set Crack growth = quasi-static\n"
    " set Toughness = 4e-5*(1 + 8*(abs(x) - 0.5))\nend\n"
    "subsection Output\n set Write VTU = false\n"
    " set Write interface CSV = false\n set Terminal output = checks\n"
    " set Displacement points = 0, 1; -0.5, -0.5\nend\n";
  const Scene scene  = scene_from_string(text, "growth_mpi");
  Scene       serial = scene, parallel = scene;
  serial.output.directory   = "serial";
  parallel.output.directory = "parallel";
  std::ostringstream quiet;

  if (all.n_processes() > 4)
    {
      bool refused = false;
      try
        {
          Study study(parallel, quiet, all);
          study.run_growth();
        }
      catch (const CollectiveError &e)
        {
          refused = std::string(e.what()).find(
                      "Loads/Load factor other than 1 needs at most four MPI "
                      "processes") != std::string::npos;
        }
      if (all.is_root())
        std::cout << "load factors refused with more than four processes: "
                  << yes(refused) << std::endl;
      return 0;
    }

  std::unique_ptr<Distribution> self;
  std::unique_ptr<Study>        reference;
  bool                          reference_ok = false;
  if (all.is_root())
    {
      self         = std::make_unique<Distribution>(MPI_COMM_SELF);
      reference    = std::make_unique<Study>(serial, quiet, *self);
      reference_ok = reference->run_growth();
    }
  Study      study(parallel, quiet, all);
  const bool ok = study.run_growth();
  if (!all.is_root())
    return 0;
  unsigned int onsets = 0;
  for (const GrowthStep &step : study.growth())
    onsets += step.kind == "onset";
  std::cout << "serial and parallel growth accepted: "
            << yes(reference_ok && ok) << std::endl
            << "growth with at least 3 onsets: " << yes(onsets >= 3)
            << std::endl
            << "the serial run's steps, tips and statuses; numbers within "
               "1e-10: "
            << yes(difference(reference->growth(), study.growth()) <= 1e-10)
            << std::endl;
}
