#include <bilayer/solvers/coulomb_fixed_point.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;


  CoulombFixedPoint::CoulombFixedPoint(const SolverParameters   &parameters,
                                       const ContactParameters  &contact,
                                       const OutputParameters   &output,
                                       const ConditionalOStream &pcout)
    : parameters(parameters)
    , coefficient(contact.friction_coefficient)
    , max_iterations(contact.friction_iterations)
    , pcout(pcout)
    , tresca(create_outer_solver(parameters, output, pcout))
  {}


  SolverResult
  CoulombFixedPoint::solve(const Subproblems   &subproblems,
                           Interface           &interface,
                           BlockVector<double> &mu,
                           Solutions           &w,
                           FixedPointRecord    &record) const
  {
    const double           F     = coefficient;
    const MultiplierSpace &space = interface.space();
    // The bounds of the crack nodes of each interface's block.
    const auto coulomb_bounds = [&]() {
      std::vector<std::vector<double>> bounds(interface.n_interfaces());
      for (const unsigned int i : Layout::indices(bounds.size()))
        {
          bounds[i].assign(space.n_nodes(i), 0.);
          for (unsigned int a = 0; a < bounds[i].size(); ++a)
            if (space.friction_node(a, i))
              bounds[i][a] =
                F * std::max(space.contact_multiplier(mu, a, i), 0.);
        }
      return bounds;
    };
    std::vector<std::vector<double>> bounds = coulomb_bounds();
    SolverResult                     total;
    // The bounds come from Tresca solves accurate to their own round-off:
    // changes below a few thousand machine epsilons are noise, not progress.
    const double target          = std::max(parameters.tolerance, 1e-12);
    double       previous_change = std::numeric_limits<double>::infinity();
    for (unsigned int k = 1; k <= max_iterations; ++k)
      {
        for (const unsigned int i : Layout::indices(bounds.size()))
          interface.set_friction_bounds(bounds[i], i);
        space.project(mu);
        const SolverResult r   = tresca->solve(subproblems, interface, mu, w);
        const SolverResult sum = total;
        total                  = r;
        total.add_work(sum);
        record.iterations                             = k;
        const std::vector<std::vector<double>> next   = coulomb_bounds();
        double                                 change = 0, largest = 0;
        for (const unsigned int i : Layout::indices(next.size()))
          for (unsigned int a = 0; a < next[i].size(); ++a)
            {
              change  = std::max(change, std::abs(next[i][a] - bounds[i][a]));
              largest = std::max(largest, next[i][a]);
            }
        record.bound_change = largest > 0 ? change / largest : change;
        pcout << "  Coulomb fixed point " << k << ": bounds F mu_c changed by "
              << record.bound_change << " of the largest bound ("
              << r.iterations << " " << r.solver << " iterations)" << std::endl;
        if (!r.converged)
          {
            total.message =
              "Coulomb fixed point " + std::to_string(k) + ": " + r.message;
            return total;
          }
        // The bounds F mu_c are only as accurate as the Tresca solves that
        // give them (their KKT residual is Solver/Tolerance): changes that
        // have stopped contracting within 100 times the tolerance are that
        // noise, and the fixed point is met to it.
        const bool stalled = k >= 3 && record.bound_change <= 100 * target &&
                             record.bound_change >= 0.5 * previous_change;
        if (record.bound_change <= target || stalled)
          {
            if (stalled)
              pcout << "  Coulomb fixed point: the changes no longer contract "
                       "(at the accuracy of the Tresca solves): accepted"
                    << std::endl;
            return total;
          }
        previous_change = record.bound_change;
        bounds          = next;
      }
    // In scientific notation: a change near Solver/Tolerance reads 0 in
    // std::to_string's fixed six decimals.
    std::ostringstream change;
    change << std::setprecision(3) << std::scientific << record.bound_change;
    total.converged = false;
    total.message   = "the friction bounds F mu_c of Coulomb friction still "
                      "changed by " +
                    change.str() + " of the largest after " +
                    std::to_string(max_iterations) +
                    " fixed-point iterations (Contact/Friction iterations); " +
                    (record.bound_change < 1e-8 ?
                       "the changes are near the accuracy of the Tresca "
                       "solves: a larger Solver/Tolerance ends it" :
                       "a smaller Contact/Friction coefficient converges "
                       "faster");
    return total;
  }
} // namespace bilayer
