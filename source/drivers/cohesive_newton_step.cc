// The cohesive driver's Newton method on the interface: the first iterate
// of a step's secant iteration (docs/cohesive.md, "The Newton method").

#include <deal.II/base/timer.h>

#include <bilayer/drivers/study.h>
#include <bilayer/interface/cohesive_zone.h>
#include <bilayer/solvers/cohesive_newton.h>

#include <iomanip>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// @p x with 3 significant digits (the stream's own precision kept).
    std::string
    three_digits(const double x)
    {
      std::ostringstream out;
      out << std::setprecision(3) << x;
      return out.str();
    }
  } // namespace

  int
  Study::newton_first_iterate(CohesiveZone &zone,
                              double       &lambda,
                              const double  fraction,
                              const double  target,
                              int          &control,
                              SolverResult &work)
  {
    const CohesiveParameters &parameters = scene.cohesive;
    const Interface          &interface  = model.interface();
    const auto                views      = model.subproblem_views();
    // The most multiplier components whose dense matrix is built (6000:
    // 288 MB).
    constexpr unsigned int most = 6000;
    if (!cohesive_newton && cohesive_newton_skipped.empty())
      {
        cohesive_newton_skipped =
          CohesiveNewton::unsupported(scene.contact.frictional(),
                                      parameters.control ==
                                        CohesiveControl::load_factor);
        unsigned int n = 0;
        for (unsigned int c = 0; c < interface.space().set().size(); ++c)
          n += interface.space().set().free(c);
        if (cohesive_newton_skipped.empty() && n > most)
          cohesive_newton_skipped = std::to_string(n) +
                                    " multiplier components (more than " +
                                    std::to_string(most) + ")";
        if (!cohesive_newton_skipped.empty())
          {
            rout << "cohesive: the secant iteration alone (Cohesive/Method "
                    "= newton does not take "
                 << cohesive_newton_skipped << ")" << std::endl;
            return -1;
          }
        Timer timer;
        cohesive_newton =
          std::make_unique<CohesiveNewton>(views, interface, zone);
        work.subdomain_solves += cohesive_newton->subdomain_solves();
        rout << "cohesive: the Newton method on the interface: "
             << cohesive_newton->size() << " multiplier components, "
             << cohesive_newton->subdomain_solves() << " subdomain solves, "
             << three_digits(timer.wall_time()) << " s" << std::endl;
      }
    if (!cohesive_newton)
      return -1;
    // The jumps of the solutions without multipliers at lambda.
    BlockVector<double> zero, g0;
    interface.space().initialize(zero);
    Solutions free_solutions;
    solve_subproblems(
      views, interface, zero, free_solutions, SolveExtent::sigma);
    interface.jumps(free_solutions, g0, true);
    for (const auto *s : views)
      work.subdomain_solves += s != nullptr;

    CohesiveNewton::Step step;
    switch (parameters.control)
      {
        case CohesiveControl::dissipation:
          step.control = CohesiveNewton::Control::dissipation;
          step.target  = target;
          break;
        case CohesiveControl::separation:
          step.control = CohesiveNewton::Control::separation;
          step.target  = fraction * parameters.separation_increment;
          if (control < 0)
            zone.scale_for_increment(zone.separations(interface,
                                                      model.solutions()),
                                     step.target,
                                     control);
          step.control_node = control;
          break;
        default:
          break;
      }
    Timer                        timer;
    const CohesiveNewton::Result result = cohesive_newton->solve(
      zone, g0, model.multipliers(), lambda, step, 100, 1e-8);
    if (scene.output.progress_interval > 0)
      pcout << "  Newton on the interface: " << result.iterations
            << " iterations, residual " << three_digits(result.residual) << ", "
            << three_digits(timer.wall_time()) << " s, "
            << cohesive_newton->factorisations()
            << " factorisations of the Jacobian so far"
            << (result.converged ? "" :
                                   " (not converged: the secant "
                                   "iteration goes on alone)")
            << std::endl;
    if (!result.converged)
      return -1;
    lambda = result.lambda;
    set_load_factor(lambda);
    model.set_multipliers(result.mu);
    zone.try_separations(result.delta, 1.);
    model.set_cohesive_compliance(zone.compliance(), parameters.interface);
    return result.iterations;
  }
} // namespace bilayer
