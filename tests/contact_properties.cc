// Properties of the contact solution that the mathematics guarantees.
//
// Example 1 (partial closure), solved to a tight relative tolerance:
// - mu_c >= 0 at every crack node (the projection onto [0, p]);
// - [u].nu >= 0 up to the iteration error (non-penetration);
// - mu_c [u].nu = 0 (complementarity): where mu_c > 0 the faces touch;
// - the load c x opens the left part of the crack (x < 0) and presses the
//   right part shut;
// - the linear problem (no non-penetration) interpenetrates where the
//   contact problem is closed, and has the lower energy (it minimises the
//   same energy over a larger set).
// Positive homogeneity: the constraint set is a cone and the solution map
// of the contact problem is positively homogeneous, so doubling the loads
// doubles every displacement. Example 2 is mirror symmetric in x: the
// normal opening is even, the tangential displacement odd.

#include <bilayer/parameters.h>
#include <bilayer/study.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::string
  scene_text(const std::string &load, const bool contact)
  {
    std::ostringstream s;
    s << "subsection Mesh\n set Cells along Sigma = 8\nend\n"
      << "subsection Loads\n set Constants = " << load << "\n"
      << " subsection Layer 1\n"
      << "  set Traction on bottom side = 0; c*x\n"
      << "  set Traction on top side = 0; -c*x\n end\nend\n"
      << "subsection Contact\n set Non-penetration on the crack = "
      << (contact ? "true" : "false") << "\nend\n"
      << "subsection Solver\n set Stopping rule = relative\n"
      << " set Tolerance = 1e-11\nend\n"
      << "subsection Output\n set Output directory = results\n"
      << " set Write VTU = false\n set Write interface CSV = false\n"
      << " set Terminal output = checks\nend\n";
    return s.str();
  }

  /// Normal opening (u+ - u-).nu at the multiplier nodes.
  std::vector<double>
  opening(const Study &study)
  {
    return study.interface().normal_opening(study.solutions());
  }

} // namespace

int
main()
{
  std::cout << "Example 1:" << std::endl;
  Study contact(scene_from_string(scene_text("c = 1e-3*mu1", true), "e1"),
                std::cout);
  contact.run_cycle(0);
  const Interface          &sigma = contact.interface();
  const std::vector<double> open  = opening(contact);
  const double scale = sigma.displacement_scale(contact.solutions());

  bool              sign_ok = true, nonpenetration = true;
  double            max_open = 0, complementarity = 0;
  bool              left_open = true, right_closed_somewhere = false;
  std::vector<bool> closed(sigma.n_nodes(), false);
  for (unsigned int a = 0; a < sigma.n_nodes(); ++a)
    if (sigma.node_on_crack(a))
      {
        const double mu_c = contact.multipliers().block(0)(2 * a + 1);
        sign_ok           = sign_ok && mu_c >= 0;
        nonpenetration    = nonpenetration && open[a] >= -1e-9 * scale;
        max_open          = std::max(max_open, open[a]);
        complementarity   = std::max(complementarity, mu_c * std::abs(open[a]));
        closed[a]         = mu_c > 0;
        if (sigma.node_position(a) < 0)
          left_open = left_open && open[a] > 0.1 * scale;
        if (sigma.node_position(a) > 0 && closed[a])
          right_closed_somewhere = true;
      }
  double max_mu = contact.multipliers().block(0).linfty_norm();
  std::cout << "mu_c >= 0 at every crack node: " << yes(sign_ok) << std::endl
            << "opening >= -1e-9 * displacement scale: " << yes(nonpenetration)
            << std::endl
            << "max mu_c |opening| <= 1e-9 * max mu * scale: "
            << yes(complementarity <= 1e-9 * max_mu * scale) << std::endl
            << "crack open on x < 0: " << yes(left_open) << std::endl
            << "crack closed (mu_c > 0) on part of x > 0: "
            << yes(right_closed_somewhere) << std::endl;

  std::cout << "Linear problem:" << std::endl;
  Study linear(scene_from_string(scene_text("c = 1e-3*mu1", false), "lin"),
               std::cout);
  linear.run_cycle(0);
  const std::vector<double> open_linear = opening(linear);
  bool                      penetrates  = true;
  for (unsigned int a = 0; a < sigma.n_nodes(); ++a)
    if (closed[a])
      penetrates = penetrates && open_linear[a] < -1e-3 * scale;
  std::cout << "linear problem interpenetrates where the contact problem "
               "is closed: "
            << yes(penetrates) << std::endl;
  // The contact problem minimises the same energy over a smaller set.
  std::cout << "energy with contact >= energy without: "
            << yes(contact.records().back().energy >=
                   linear.records().back().energy)
            << std::endl;

  std::cout << "Homogeneity:" << std::endl;
  Study doubled(scene_from_string(scene_text("c = 2e-3*mu1", true), "e1x2"),
                std::cout);
  doubled.run_cycle(0);
  double difference = 0, size = 0;
  for (unsigned int s = 0; s < 4; ++s)
    {
      Vector<double> d = doubled.solutions()[s];
      d.add(-2., contact.solutions()[s]);
      difference = std::max(difference, d.linfty_norm());
      size       = std::max(size, doubled.solutions()[s].linfty_norm());
    }
  std::cout << "|w(2 f) - 2 w(f)| <= 1e-8 |w(2 f)|: "
            << yes(difference <= 1e-8 * size) << std::endl;

  std::cout << "Example 2 symmetry:" << std::endl;
  std::string text = scene_text("c = 1e-3*mu1", true);
  text.replace(text.find("0; c*x"), 6, "0; -c");
  text.replace(text.find("0; -c*x"), 7, "0; c");
  Study full(scene_from_string(text, "e2"), std::cout);
  full.run_cycle(0);
  const std::vector<double> open_full = opening(full);
  const unsigned int        n         = sigma.n_nodes();
  double                    asymmetry = 0, max_full = 0;
  for (unsigned int a = 0; a < n; ++a)
    {
      asymmetry =
        std::max(asymmetry, std::abs(open_full[a] - open_full[n - 1 - a]));
      max_full = std::max(max_full, std::abs(open_full[a]));
    }
  std::cout << "opening(x) = opening(-x) to 1e-8: "
            << yes(asymmetry <= 1e-8 * max_full) << std::endl;
  bool all_open = true;
  for (unsigned int a = 0; a < n; ++a)
    if (sigma.node_on_crack(a))
      all_open = all_open && open_full[a] > 0 &&
                 full.multipliers().block(0)(2 * a + 1) == 0;
  std::cout << "crack open with mu_c = 0 at every crack node: " << yes(all_open)
            << std::endl;
}
