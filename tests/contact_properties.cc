// Properties of the contact solution that the mathematics guarantees.
//
// Example 1 (partial closure), solved to a tight relative tolerance:
// - the contact force is compressive: recovered from the displacements
//   alone, as the residual of the equilibrium equations of u+ and v+ at the
//   crack nodes (stiffness assembled here, independently of the library;
//   the Sigma dofs carry no traction load, so K w is the interface load):
//   (K_u+ u+)_y(a) + (K_v+ v+)_y(a) = D_a mu_c(a) >= 0 (the gluing
//   multiplier lambda+ cancels in the sum; D_a = lumped weight of node a).
//   Unlike mu_c >= 0, which the projection onto [0, p] enforces, this fails
//   for a multiplier applied with the wrong sign or a crack held shut by a
//   tensile force; the force must also be D_a mu_c;
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
// The lines "energy Pi" and "largest crack opening" that Study prints are
// the numbers of tests/prm_references.cc (scenes partial_closure,
// partial_closure_linear, doubled load, full_opening: the same discrete
// problems), which checks that this .output holds them.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

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
    return normal_opening(study.interface(), study.solutions());
  }

  /// K w for subproblem s of @p study (Q1, plane strain, the moduli of
  /// docs/problem.md §5 written out here), by its own assembly.
  Vector<double>
  stiffness_times(const Study &study, const unsigned int s)
  {
    const double E[2] = {200., 112.}, nu[2] = {0.28, 0.32};
    const double mu               = E[s / 2] / (2. * (1. + nu[s / 2]));
    const double lambda           = 2. * nu[s / 2] * mu / (1. - 2. * nu[s / 2]);
    const ElasticSubproblem &sub  = study.subproblem(s);
    const DoFHandler<2>     &dofs = sub.dof_handler();
    DynamicSparsityPattern   dsp(dofs.n_dofs());
    DoFTools::make_sparsity_pattern(dofs, dsp);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double>                 K(pattern);
    FEValues<2>                          fe_values(sub.mapping(),
                          sub.fe(),
                          QGauss<2>(2),
                          update_gradients | update_JxW_values);
    const unsigned int                   n = sub.fe().n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> local(n);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell_matrix = 0;
        fe_values.reinit(cell);
        add_elasticity_matrix(
          fe_values, FEValuesExtractors::Vector(0), mu, lambda, cell_matrix);
        cell->get_dof_indices(local);
        K.add(local, cell_matrix);
      }
    Vector<double> Kw(dofs.n_dofs());
    K.vmult(Kw, study.solutions()[s]);
    return Kw;
  }

  /// The y-dof of subproblem s at the point (x, 0) of Sigma.
  types::global_dof_index
  sigma_y_dof(const Study &study, const unsigned int s, const double x)
  {
    const ElasticSubproblem &sub = study.subproblem(s);
    std::vector<Point<2>>    points(sub.n_dofs());
    DoFTools::map_dofs_to_support_points(sub.mapping(),
                                         sub.dof_handler(),
                                         points);
    std::vector<bool>                    y_component(sub.n_dofs());
    std::vector<types::global_dof_index> local(sub.fe().n_dofs_per_cell());
    for (const auto &cell : sub.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          y_component[local[i]] =
            sub.fe().system_to_component_index(i).first == 1;
      }
    for (types::global_dof_index i = 0; i < points.size(); ++i)
      if (y_component[i] && points[i].distance(Point<2>(x, 0)) < 1e-10)
        return i;
    AssertThrow(false, ExcMessage("no dof at this point of Sigma"));
    return 0;
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
  const double scale = displacement_scale(sigma, contact.solutions());

  bool   nonpenetration = true;
  double max_open = 0, complementarity = 0;
  // The contact force at each crack node from the residual of u+ and v+.
  const Vector<double> Ku = stiffness_times(contact, 1),
                       Kv = stiffness_times(contact, 3);
  std::vector<double> force(sigma.space().n_nodes(), 0.);
  double              max_force = 0;
  for (unsigned int a = 0; a < sigma.space().n_nodes(); ++a)
    if (sigma.space().on_crack(a))
      {
        const double x = sigma.space().node_position(a);
        force[a] =
          Ku(sigma_y_dof(contact, 1, x)) + Kv(sigma_y_dof(contact, 3, x));
        max_force = std::max(max_force, std::abs(force[a]));
      }
  bool              compressive = max_force > 0, force_is_multiplier = true;
  bool              left_open = true, right_closed_somewhere = false;
  std::vector<bool> closed(sigma.space().n_nodes(), false);
  for (unsigned int a = 0; a < sigma.space().n_nodes(); ++a)
    if (sigma.space().on_crack(a))
      {
        const double mu_c =
          sigma.space().contact_multiplier(contact.multipliers(), a);
        // D_a: half the adjacent segments (lumped, Q1: all nodes are
        // vertices).
        const double D_a = 0.5 * (sigma.space().node_position(a + 1) -
                                  sigma.space().node_position(a - 1));
        compressive      = compressive && force[a] >= -1e-8 * max_force;
        force_is_multiplier =
          force_is_multiplier &&
          std::abs(force[a] - D_a * mu_c) <= 1e-6 * max_force;
        nonpenetration  = nonpenetration && open[a] >= -1e-9 * scale;
        max_open        = std::max(max_open, open[a]);
        complementarity = std::max(complementarity, mu_c * std::abs(open[a]));
        closed[a]       = mu_c > 0;
        if (sigma.space().node_position(a) < 0)
          left_open = left_open && open[a] > 0.1 * scale;
        if (sigma.space().node_position(a) > 0 && closed[a])
          right_closed_somewhere = true;
      }
  double max_mu =
    contact.multipliers().block(Layout::across_sigma).linfty_norm();
  std::cout << "contact force from the residual (K w)_y of u+ and v+ >= "
               "-1e-8 max at every crack node: "
            << yes(compressive) << std::endl
            << "and equal to D_a mu_c to 1e-6 max: " << yes(force_is_multiplier)
            << std::endl
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
  for (unsigned int a = 0; a < sigma.space().n_nodes(); ++a)
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
  for (const unsigned int s : Layout::indices(Topology().n_subproblems()))
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
  const unsigned int        n         = sigma.space().n_nodes();
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
    if (sigma.space().on_crack(a))
      all_open =
        all_open && open_full[a] > 0 &&
        full.interface().space().contact_multiplier(full.multipliers(), a) == 0;
  std::cout << "crack open with mu_c = 0 at every crack node: " << yes(all_open)
            << std::endl;
}
