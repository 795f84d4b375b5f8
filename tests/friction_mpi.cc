// Friction on the crack faces under MPI: the processes share the
// subproblems (Distribution) and every process keeps the multipliers, so
// the friction bounds, the box projections of the tangential multipliers
// and the Coulomb fixed point run alike on every process. Run by 1, 2, 4
// and 6 processes (the .mpirun=N outputs), each scene must give the serial
// run's numbers: the energy, the energy release rate G at each crack tip
// and its friction term, the multipliers, the slip [u].tau at the crack
// nodes and (up to 4 processes, where the runs are bit-identical) the
// iteration counts and the Coulomb fixed-point steps. The serial run is a
// Study of the first process alone (MPI_COMM_SELF).
//
// Up to 4 processes every quantity must agree to 1e-10 of itself (the
// friction term of G to 1e-10 of G: it is a difference of face works,
// 1e-3 of G and less, that cancels to rounding where the faces stick).
// With 6 processes u- and u+ are shared by two processes each (another
// direct solver, other sums: rounding differs), and everything must agree
// to 1e-8 instead; the counts may differ by a step where rounding flips an
// active-set decision. Measured with 6 processes: energy 8e-16, G 1.2e-12,
// friction term 1.8e-13 (of G), multipliers 4e-15, slip 8e-14; the
// iteration counts and the fixed-point steps were the serial ones.
//
// Scenes (Example 1 with the shear traction (s c, -c x) on the top and
// (-s c, c x) on the bottom of layer 1, docs/problem.md §5):
//  - Tresca, s = 1/2, g = 1e-3 (stick and slip nodes), active set;
//  - Tresca, the same, accelerated method with theta = auto (the
//    projections onto the friction box);
//  - Coulomb, s = 1, F = 0.5, another material on Omega+ of layer 1 (the
//    normal and tangential responses couple: several fixed-point steps),
//    active set.

#include <deal.II/base/mpi.h>

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/subproblem/distribution.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "friction_scenes.h"
#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  /// |a - b| relative to @p size (to the larger of |a|, |b| if not given;
  /// 0 if both are 0).
  double
  relative(const double a, const double b, const double size = 0)
  {
    const double s = size > 0 ? size : std::max(std::abs(a), std::abs(b));
    return s > 0 ? std::abs(a - b) / s : 0.;
  }

  /// Largest difference of two vectors relative to the larger of their
  /// largest entries.
  double
  relative(const std::vector<double> &a, const std::vector<double> &b)
  {
    if (a.size() != b.size())
      return std::numeric_limits<double>::max();
    double d = 0, size = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        d    = std::max(d, std::abs(a[i] - b[i]));
        size = std::max({size, std::abs(a[i]), std::abs(b[i])});
      }
    return size > 0 ? d / size : 0.;
  }

  std::vector<double>
  slip(const Study &study)
  {
    std::vector<double> s;
    for (const InterfaceNode &node : interface_nodes(study.interface(),
                                                     study.solutions(),
                                                     study.multipliers()))
      if (node.on_crack)
        s.push_back(node.jump_tangential);
    return s;
  }

  void
  compare(const std::string &name, const std::string &text)
  {
    const Distribution &all    = Distribution::world();
    const Scene         scene  = scene_from_string(text, name);
    Scene               serial = scene, parallel = scene;
    serial.output.directory   = "serial-" + name;
    parallel.output.directory = "parallel-" + name;
    std::ostringstream quiet;

    std::unique_ptr<Distribution> self;
    std::unique_ptr<Study>        reference;
    if (all.is_root())
      {
        self      = std::make_unique<Distribution>(MPI_COMM_SELF);
        reference = std::make_unique<Study>(serial, quiet, *self);
        reference->run_cycle(0);
      }
    Study study(parallel, quiet, all);
    study.run_cycle(0);
    if (!all.is_root())
      return;

    const CycleRecord &a         = reference->records().back();
    const CycleRecord &b         = study.records().back();
    const bool         converged = a.accepted() && b.accepted();
    const bool same_counts       = a.result.iterations == b.result.iterations &&
                             a.friction_iterations == b.friction_iterations;
    double energy = relative(a.energy, b.energy), G = 0, G_friction = 0;
    bool same_tips = a.release.size() == b.release.size() && !a.release.empty();
    for (unsigned int t = 0; same_tips && t < a.release.size(); ++t)
      {
        G          = std::max(G, relative(a.release[t].G, b.release[t].G));
        G_friction = std::max(G_friction,
                              relative(a.release[t].friction,
                                       b.release[t].friction,
                                       std::abs(a.release[t].G)));
      }
    const BlockVector<double> &mu_a = reference->multipliers();
    const BlockVector<double> &mu_b = study.multipliers();
    const double               multipliers =
      relative(std::vector<double>(mu_a.begin(), mu_a.end()),
               std::vector<double>(mu_b.begin(), mu_b.end()));
    const double slips = relative(slip(*reference), slip(study));

    const bool   shared    = all.n_processes() > 4;
    const double tolerance = shared ? 1e-8 : 1e-10;
    std::cout << name << ": converged: " << yes(converged);
    if (!shared)
      std::cout << "; same iteration counts: " << yes(same_counts);
    std::cout << "; energy, G, friction term of G within "
              << (shared ? "1e-8" : "1e-10") << ": "
              << yes(same_tips && energy <= tolerance && G <= tolerance &&
                     G_friction <= tolerance)
              << "; multipliers and slip within " << (shared ? "1e-8" : "1e-10")
              << ": " << yes(multipliers <= tolerance && slips <= tolerance)
              << std::endl;
    if (std::getenv("BILAYER_TEST_DIAGNOSTICS") != nullptr)
      std::cerr << name << " (" << all.n_processes() << " processes)"
                << std::setprecision(3) << ": energy " << energy << ", G " << G
                << ", G friction " << G_friction << ", multipliers "
                << multipliers << ", slip " << slips << ", iterations "
                << a.result.iterations << "/" << b.result.iterations
                << ", fixed point " << a.friction_iterations << "/"
                << b.friction_iterations << std::endl;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                common =
    "subsection Mesh\n set Cells along Sigma = 16\nend\n"
    "subsection Output\n set Write VTU = false\n"
    " set Write interface CSV = false\n set Terminal output = checks\nend\n";
  const std::string tresca = common +
                             friction_scenes::shear_loads("0.5", "1e-3*mu1") +
                             "subsection Contact\n set Friction = tresca\n"
                             " set Friction bound = 1e-3\nend\n";
  compare("tresca_active_set",
          tresca + "subsection Solver\n set Method = active set\n"
                   " set Tolerance = 1e-10\nend\n");
  compare("tresca_accelerated",
          tresca + "subsection Solver\n set Method = accelerated\n"
                   " set Uzawa step theta = auto\n set Stopping rule = kkt\n"
                   " set Tolerance = 1e-9\nend\n");
  // c = 1e-3 mu1 of Omega- of layer 1 (78.125) as a number: mu1 differs
  // between the sides.
  compare("coulomb_bimaterial",
          common + friction_scenes::shear_loads("1", "0.078125") +
            "subsection Materials\n subsection Layer 1\n"
            "  subsection Omega+\n   set Young's modulus = 80\n"
            "   set Poisson's ratio = 0.2\n  end\n end\nend\n"
            "subsection Contact\n set Friction = coulomb\n"
            " set Friction coefficient = 0.5\nend\n"
            "subsection Solver\n set Method = active set\n"
            " set Tolerance = 1e-10\nend\n");
}
