// The load factor lambda (Study::set_load_factor(),
// ElasticSubproblem::set_load_factor()): the proportional loads (tractions,
// body forces, prescribed displacements) scaled by lambda and the preload
// (eigenstrains, thermal strains) kept, on the subproblems as set up and
// factorised once.
//
// (a) Example 1 (parameter_files/partial_closure.prm, the active set, tight
//     tolerance), states at lambda = 1, 2.5, 0.3 on one factorisation: the
//     contact problem without gap is positively homogeneous, so the energy
//     and G at both tips are lambda^2 times those at 1, and the solutions
//     and multipliers lambda times those of a separate run at 1, to 1e-10
//     relative; every subproblem factorised once; lambda set before the
//     subproblems exist (2.5) is applied to them after their set-up; at
//     0.3 Clapeyron's Pi = -1/2 lambda (F_1, w) with (F_1, w) summed from
//     load_work() (the work of the unit load; the multipliers do none).
// (b) One layer, a crack (-0.5, 0.5), a body force, a prescribed
//     displacement on the clamped sides and tractions (no preload): states
//     at 1, 0.4, 2.5, the energies and G lambda^2 times those at 1, and
//     the last state against a separate study whose loads are multiplied
//     by 2.5 in the parameter text (its own assembly): displacements,
//     multipliers, energy, G and the estimate eta to 1e-10 relative.
// (c) The same with a preload (Loads/Temperature change on a layer that
//     expands, and an eigenstrain): the state at 2.5 (after 1 and 0.4)
//     against a study whose proportional loads are multiplied by 2.5 in
//     the text and whose preload is kept, and the state at 0 (after 0.3)
//     against the preload alone, to 1e-10; proportional_loading() false
//     here, true in (a) and (b).

#include <bilayer/drivers/study.h>
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
  const std::string quiet_output =
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Progress interval = 0\n set Terminal output = checks\nend\n";

  std::ofstream measured("measured.txt");

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }

  /// |a - b| / |b| (max norms).
  template <typename VectorType>
  double
  relative(const VectorType &a, const VectorType &b)
  {
    double diff = 0, size = 0;
    for (unsigned int i = 0; i < b.size(); ++i)
      {
        diff = std::max(diff, std::abs(a(i) - b(i)));
        size = std::max(size, std::abs(b(i)));
      }
    return a.size() == b.size() ? diff / size : 1.;
  }

  double
  relative(const double a, const double b)
  {
    return a == b ? 0. : std::abs(a - b) / std::abs(b);
  }

  /// The largest relative difference of the solutions and multipliers of
  /// @p a from @p scale times those of @p b.
  double
  state_difference(const Study &a, const Study &b, const double scale)
  {
    double largest = 0;
    for (const unsigned int s : Layout::indices(Topology().n_subproblems()))
      if (b.solutions()[s].size() > 0)
        {
          Vector<double> scaled = b.solutions()[s];
          scaled *= scale;
          largest = std::max(largest, relative(a.solutions()[s], scaled));
        }
    BlockVector<double> mu = b.multipliers();
    mu *= scale;
    return std::max(largest, relative(a.multipliers(), mu));
  }

  /// The largest relative difference of energy, G (every tip) and eta of
  /// record @p a from those of @p b, the first two times @p scale^2, eta
  /// times |scale| (eta only with @p with_eta).
  double
  record_difference(const CycleRecord &a,
                    const CycleRecord &b,
                    const double       scale,
                    const bool         with_eta)
  {
    const double s2 = scale * scale;
    double       d  = relative(a.energy, s2 * b.energy);
    if (a.release.size() != b.release.size() || a.release.empty())
      return 1;
    for (unsigned int t = 0; t < a.release.size(); ++t)
      d = std::max(d, relative(a.release[t].G, s2 * b.release[t].G));
    if (with_eta)
      d = std::max(d, relative(a.eta, std::abs(scale) * b.eta));
    return d;
  }

  bool
  factorised_once(const Study &study, const unsigned int layers)
  {
    bool once = true;
    for (unsigned int l = 0; l < layers; ++l)
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        once =
          once &&
          study.subproblem(static_cast<Layer>(l), sd).n_factorisations() == 1;
    return once;
  }

  /// (a) Example 1.
  void
  example_1()
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/partial_closure.prm");
    std::ostringstream text;
    text << in.rdbuf()
         << "subsection Solver\n set Method = active set\n"
            " set Tolerance = 1e-13\nend\n"
            "subsection Fracture\n set Energy release rate = true\nend\n"
         << quiet_output;
    const Scene        scene = scene_from_string(text.str(), "load_factor");
    std::ostringstream sink;
    Study              one(scene, sink);
    one.run_cycle(0);
    Study states(scene, sink);
    check("(a) proportional loading", states.proportional_loading());
    const std::vector<double> lambdas = {1, 2.5, 0.3};
    const bool accepted = states.run_states({scene.geometry.crack(),
                                             scene.geometry.crack(),
                                             scene.geometry.crack()},
                                            lambdas);
    check("(a) three states accepted",
          accepted && states.records().size() == 3);
    check("(a) every subproblem factorised once", factorised_once(states, 2));
    double d = 0;
    for (unsigned int k = 0; k < 3 && k < states.records().size(); ++k)
      d = std::max(d,
                   record_difference(states.records()[k],
                                     one.records().front(),
                                     lambdas[k],
                                     false));
    measured << "(a) energy and G against lambda^2 at 1: " << d << std::endl;
    check("(a) energy and G at both tips lambda^2 times those at 1 (1e-10)",
          d <= 1e-10);
    const double w = state_difference(states, one, 0.3);
    measured << "(a) lambda = 0.3: solutions and multipliers " << w
             << std::endl;
    check("(a) at 0.3 solutions and multipliers 0.3 times those at 1 (1e-10)",
          w <= 1e-10);

    // Clapeyron at 0.3 (forces only, no work of the contact and gluing
    // multipliers): Pi = -1/2 (0.3 F_1, w), (F_1, w) = load_work(w).
    double work = 0;
    for (const Layer layer : {Layer::first, Layer::second})
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        work += states.subproblem(layer, sd).load_work(
          states.solutions()[Layout::index(layer, sd)]);
    const double clapeyron =
      relative(states.records().back().energy, -0.5 * 0.3 * work);
    measured << "(a) lambda = 0.3: Pi against -1/2 lambda load_work: "
             << clapeyron << std::endl;
    check("(a) at 0.3 Pi = -1/2 lambda (F_1, w) (load_work, 1e-10)",
          clapeyron <= 1e-10);

    Study later(scene, sink);
    later.set_load_factor(2.5);
    later.run_states({scene.geometry.crack()});
    const double w_later = state_difference(later, one, 2.5);
    const double r_later = record_difference(later.records().front(),
                                             one.records().front(),
                                             2.5,
                                             false);
    measured << "(a) lambda = 2.5 before the set-up: " << w_later << ", "
             << r_later << std::endl;
    check("(a) lambda = 2.5 set before the set-up: 2.5 times the state at 1 "
          "(1e-10)",
          std::max(w_later, r_later) <= 1e-10 && factorised_once(later, 2));
  }

  /// The one-layer scene of (b) and (c): the proportional loads times
  /// @p p (as text), with the preload @p preload.
  std::string
  one_layer(const std::string &p, const bool preload)
  {
    std::ostringstream s;
    s << "subsection Materials\n set Number of layers = 1\n"
      << (preload ? " subsection Layer 1\n  set Thermal expansion = 1e-5\n"
                    " end\n" :
                    "")
      << "end\n"
      << "subsection Geometry\n set Crack interval on Sigma = -0.5, 0.5\n"
         " set Clamped sides = left, right\nend\n"
         "subsection Mesh\n set Cells along Sigma = 8\n"
         " set Polynomial degree of layer 1 = 2\nend\n"
         "subsection Loads\n"
      << (preload ? " set Temperature change = 20 + 10*x\n" : "")
      << " subsection Layer 1\n"
      << "  set Traction on bottom side = " << p << "*0.05*x; " << p << "*0.2\n"
      << "  set Traction on top side = " << p << "*(-0.1); " << p
      << "*0.3*x*x\n"
      << "  set Prescribed displacement = " << p << "*1e-3*y; " << p
      << "*(-2e-3)*(1 + y)\n"
      << "  set Body force = " << p << "*0.5*y; " << p << "*0.4\n"
      << (preload ? "  set Eigenstrain = 1e-4*y; -2e-4; 5e-5*x\n" : "")
      << " end\nend\n"
      << "subsection Solver\n set Method = active set\n"
         " set Tolerance = 1e-13\nend\n"
         "subsection Fracture\n set Energy release rate = true\nend\n"
      << quiet_output;
    return s.str();
  }

  /// (b) and (c): the states @p lambdas on one study against fresh studies
  /// at the last one.
  void
  one_layer_scenes(const bool preload)
  {
    const std::string  part = preload ? "(c) " : "(b) ";
    std::ostringstream sink;
    const Scene        scene =
      scene_from_string(one_layer("1", preload), "load_factor");
    const CrackSet crack = scene.geometry.crack();
    Study          states(scene, sink);
    check(part + "proportional loading " + (preload ? "false" : "true"),
          states.proportional_loading() == !preload);
    const std::vector<double> lambdas = {1, 0.4, 2.5};
    const bool accepted = states.run_states({crack, crack, crack}, lambdas);
    check(part + "three states accepted",
          accepted && states.records().size() == 3);
    check(part + "the subproblems factorised once", factorised_once(states, 1));
    if (!preload)
      {
        double d = 0;
        for (unsigned int k = 1; k < 3 && k < states.records().size(); ++k)
          d = std::max(d,
                       record_difference(states.records()[k],
                                         states.records()[0],
                                         lambdas[k],
                                         false));
        measured << part << "energy and G against lambda^2 at 1: " << d
                 << std::endl;
        check(part + "energy and G lambda^2 times those at 1 (1e-10)",
              d <= 1e-10);
      }
    // The last state against its own assembly.
    Study fresh(scene_from_string(one_layer("2.5", preload), "load_factor"),
                sink);
    fresh.run_cycle(0);
    const double w = state_difference(states, fresh, 1);
    const double r = record_difference(states.records().back(),
                                       fresh.records().front(),
                                       1,
                                       true);
    measured << part << "lambda = 2.5 against the loads times 2.5: " << w
             << ", " << r << std::endl;
    check(part + "lambda = 2.5: solutions, multipliers, energy, G, eta of "
                 "the loads times 2.5 (1e-10)",
          std::max(w, r) <= 1e-10);
    if (preload)
      {
        // lambda = 0: the preload alone.
        Study zero(scene, sink);
        zero.run_states({crack, crack}, {0.3, 0});
        Study alone(scene_from_string(one_layer("0", true), "load_factor"),
                    sink);
        alone.run_cycle(0);
        const double w0 = state_difference(zero, alone, 1);
        const double r0 = record_difference(zero.records().back(),
                                            alone.records().front(),
                                            1,
                                            true);
        measured << part << "lambda = 0 against the preload alone: " << w0
                 << ", " << r0 << std::endl;
        check(part + "lambda = 0: the solution of the preload alone (1e-10)",
              std::max(w0, r0) <= 1e-10);
      }
  }
} // namespace

int
main()
{
  example_1();
  one_layer_scenes(false);
  one_layer_scenes(true);
}
