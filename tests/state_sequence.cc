// The states driver (Study::run_states()): two states on one mesh that
// differ in the crack, each solved from a cold start, give exactly the
// results of two separate runs of the scenes with those cracks (the same
// subproblem matrices, factorised once, and an interface rebuilt for each
// crack), bit for bit: the subproblem matrices do not depend on which part
// of Sigma is cracked, so reusing them changes no operation. The tips are
// recomputed for each crack.
//
// A crack end that is no mesh vertex, a piece reaching an end of Sigma on
// Gamma_D (the left side of Example 1 is clamped) and a piece covering all
// of Sigma are refused with the crack left as it was. With the left side
// free (only the right side clamped) a piece reaching the left end is an
// edge crack: the state (-1, 0.5) is accepted, has one tip (x = 0.5, none
// at the mouth) and gives bit for bit the separate run of that scene.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::string
  scene_text(const std::string &crack,
             const std::string &directory,
             const std::string &clamped = "left, right")
  {
    return "subsection Geometry\n set Crack interval on Sigma = " + crack +
           "\n set Clamped sides = " + clamped +
           "\nend\n"
           "subsection Mesh\n set Cells along Sigma = 16\nend\n"
           "subsection Loads\n set Constants = c = 1e-3*mu1\n"
           " subsection Layer 1\n"
           "  set Traction on bottom side = 0; c*x\n"
           "  set Traction on top side = 0; -c*x\n end\nend\n"
           "subsection Solver\n set Method = active set\n"
           " set Tolerance = 1e-10\nend\n"
           "subsection Fracture\n set Energy release rate = true\nend\n"
           "subsection Output\n set Output directory = " +
           directory +
           "\n set Write VTU = false\n"
           " set Terminal output = checks\nend\n";
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }

  /// Whether two vectors hold the same numbers, bit for bit.
  template <typename VectorType>
  bool
  same(const VectorType &a, const VectorType &b)
  {
    if (a.size() != b.size())
      return false;
    for (unsigned int i = 0; i < a.size(); ++i)
      if (!(a(i) == b(i)))
        return false;
    return true;
  }

  bool
  same_records(const CycleRecord &a, const CycleRecord &b)
  {
    bool ok =
      a.energy == b.energy && a.eta == b.eta && a.dofs == b.dofs &&
      a.multipliers == b.multipliers &&
      a.report.constraint_violation == b.report.constraint_violation &&
      a.report.max_penetration == b.report.max_penetration &&
      a.report.min_contact_multiplier == b.report.min_contact_multiplier &&
      a.report.complementarity == b.report.complementarity &&
      a.report.kkt.value() == b.report.kkt.value() &&
      a.result.iterations == b.result.iterations &&
      a.release.size() == b.release.size();
    for (unsigned int t = 0; ok && t < a.release.size(); ++t)
      ok = a.release[t].G == b.release[t].G &&
           a.release[t].tip.point == b.release[t].tip.point;
    return ok;
  }
} // namespace

int
main()
{
  const std::array<std::string, 2> cracks = {{"-0.5, 0.5", "-0.25, 0.75"}};
  std::ostringstream               quiet;

  // The two separate runs.
  std::array<std::unique_ptr<Study>, 2> alone;
  std::array<Scene, 2>                  scenes;
  for (unsigned int k = 0; k < 2; ++k)
    {
      scenes[k] = scene_from_string(scene_text(cracks[k], "results_alone"),
                                    "state_sequence");
      alone[k]  = std::make_unique<Study>(scenes[k], quiet);
      alone[k]->run_cycle(0);
    }

  // The states: one study, the cracks of both scenes in turn.
  Study      states(scene_from_string(scene_text(cracks[0], "results_states"),
                                 "state_sequence"),
               quiet);
  const bool accepted =
    states.run_states({scenes[0].geometry.crack(), scenes[1].geometry.crack()});
  check("both states accepted", accepted);
  check("two records", states.records().size() == 2);
  for (unsigned int k = 0; k < 2 && states.records().size() == 2; ++k)
    {
      const CycleRecord &a = alone[k]->records().front();
      const CycleRecord &b = states.records()[k];
      std::cout << "state " << k << " (crack " << cracks[k]
                << "): " << b.release.size() << " tips at x =";
      for (const auto &g : b.release)
        std::cout << " " << g.tip.point[0];
      std::cout << std::endl;
      check("state " + std::to_string(k) +
              ": energy, residuals, iterations, G and tips as the separate run",
            same_records(a, b));
    }
  // The last state's fields against the second separate run.
  bool fields = true;
  for (const unsigned int s : Layout::indices(Topology().n_subproblems()))
    fields = fields && same(states.solutions()[s], alone[1]->solutions()[s]);
  check("state 1: displacements as the separate run, bit for bit", fields);
  check("state 1: multipliers as the separate run, bit for bit",
        same(states.multipliers(), alone[1]->multipliers()));
  unsigned int once = 0;
  for (const Layer l : {Layer::first, Layer::second})
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      once += states.subproblem(l, sd).n_factorisations() == 1;
  check("each of the four subproblems factorised once", once == 4);
  check("the states differ (the cracks do)",
        states.records()[0].energy != states.records()[1].energy);

  // Refusals: a crack end between mesh vertices (h = 1/8), a piece that
  // reaches the end of Sigma on Gamma_D (clamped left side), a piece that
  // covers all of Sigma (the left side free).
  for (const auto &[bad, clamped] :
       {std::make_pair(CrackSet::Piece{-0.55, 0.5}, "left, right"),
        std::make_pair(CrackSet::Piece{-1., 0.5}, "left, right"),
        std::make_pair(CrackSet::Piece{-1., 1.}, "right")})
    {
      Study refused(
        scene_from_string(scene_text(cracks[0], "results_states", clamped),
                          "state_sequence"),
        quiet);
      std::ostringstream name;
      name << "crack (" << bad.start << ", " << bad.end << ")";
      try
        {
          refused.run_states({CrackSet({bad}, 2e-10)});
          check(name.str() + " refused", false);
        }
      catch (const ExceptionBase &e)
        {
          const std::string what = one_line_message(e);
          std::cout << "  " << what << std::endl;
          check(name.str() + " refused naming the crack",
                what.find("the crack") != std::string::npos);
        }
    }
  // An edge crack: the left side free, the piece (-1, 0.5) reaches it.
  {
    const std::string edge = "-1, 0.5";
    Study             free_left(
      scene_from_string(scene_text(cracks[0], "results_edge_states", "right"),
                        "state_sequence"),
      quiet);
    const Scene scene =
      scene_from_string(scene_text(edge, "results_edge_alone", "right"),
                        "state_sequence");
    Study alone_edge(scene, quiet);
    alone_edge.run_cycle(0);
    const bool ok = free_left.run_states(
      {scenes[0].geometry.crack(), scene.geometry.crack()});
    check("edge crack (-1, 0.5), left side free: states accepted", ok);
    const bool  two = free_left.records().size() == 2;
    const auto &tips =
      two ? free_left.records()[1].release : std::vector<EnergyReleaseRate>();
    check("edge crack: one tip, at x = 0.5 (none at the mouth x = -1)",
          tips.size() == 1 && tips[0].tip.point[0] == 0.5);
    check("edge crack: energy, residuals, iterations, G and tips as the "
          "separate run",
          two &&
            same_records(alone_edge.records().front(), free_left.records()[1]));
    check("edge crack: multipliers as the separate run, bit for bit",
          same(free_left.multipliers(), alone_edge.multipliers()));
    // table.csv of the states: two tips in state 0, one in state 1 (null in
    // the columns of tip 2).
    std::ifstream            csv("results_edge_states/table.csv");
    std::vector<std::string> rows;
    for (std::string line; std::getline(csv, line);)
      if (!line.empty() && line[0] != '#')
        rows.push_back(line);
    const auto ends_with = [](const std::string &a, const std::string &b) {
      return a.size() >= b.size() &&
             a.compare(a.size() - b.size(), b.size(), b) == 0;
    };
    check("edge crack: table.csv has the columns of two tips, null for the "
          "second in the edge state",
          rows.size() == 3 && ends_with(rows[0], ",G_tip2,dG_tip2") &&
            !ends_with(rows[1], ",null,null") &&
            ends_with(rows[2], ",null,null"));
  }
}
