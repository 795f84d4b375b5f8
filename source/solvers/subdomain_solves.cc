#include <bilayer/core/tasks.h>
#include <bilayer/solvers/subdomain_solves.h>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The solves with the multiplier loads of @p multipliers, as parallel
    /// tasks; @p homogeneous drops the tractions and the prescribed
    /// displacement (the linear part of the solution map); without
    /// @p whole, a condensed subproblem solves on Sigma alone.
    void
    solve_all(const Subproblems         &subproblems,
              const Interface           &interface,
              const BlockVector<double> &multipliers,
              Solutions                 &solutions,
              const bool                 homogeneous,
              const bool                 whole)
    {
      Solutions loads;
      interface.apply(multipliers, loads);
      solutions.resize(subproblems.size());
      Tasks tasks;
      for (const unsigned int s : Layout::indices(subproblems.size()))
        if (subproblems[s] != nullptr && subproblems[s]->owned())
          tasks.add([&, s]() {
            if (!whole && subproblems[s]->condensed())
              subproblems[s]->solve_on_sigma(loads[s],
                                             solutions[s],
                                             homogeneous);
            else if (homogeneous)
              subproblems[s]->solve_homogeneous(loads[s], solutions[s]);
            else
              subproblems[s]->solve(loads[s], solutions[s]);
          });
      tasks.join_all();
      share_traces(subproblems, solutions);
    }
  } // namespace


  void
  share_traces(const Subproblems &subproblems, Solutions &solutions)
  {
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        subproblems[s]->share_trace(solutions[s]);
  }


  PerSubproblem<double>
  share_values(const Subproblems                         &subproblems,
               const std::function<double(unsigned int)> &value)
  {
    PerSubproblem<double> values(subproblems.size(), 0.);
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        values[s] = value(s);
    // Layer 1 is always present.
    subproblems[Layout::u_minus]->processes().share(values);
    return values;
  }


  void
  solve_subproblems(const Subproblems         &subproblems,
                    const Interface           &interface,
                    const BlockVector<double> &multipliers,
                    Solutions                 &solutions,
                    const SolveExtent          extent)
  {
    solve_all(subproblems,
              interface,
              multipliers,
              solutions,
              false,
              extent == SolveExtent::whole);
  }


  void
  solve_homogeneous_subproblems(const Subproblems         &subproblems,
                                const Interface           &interface,
                                const BlockVector<double> &multipliers,
                                Solutions                 &solutions)
  {
    solve_all(subproblems, interface, multipliers, solutions, true, false);
  }


  void
  solve_homogeneous_subproblems(
    const Subproblems                      &subproblems,
    const Interface                        &interface,
    const std::vector<BlockVector<double>> &multipliers,
    std::vector<Solutions>                 &solutions)
  {
    const unsigned int     m = multipliers.size();
    std::vector<Solutions> loads(m);
    for (unsigned int c = 0; c < m; ++c)
      interface.apply(multipliers[c], loads[c]);
    solutions.assign(m, Solutions(subproblems.size()));
    Tasks tasks;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        tasks.add([&, s]() {
          if (subproblems[s]->condensed())
            {
              std::vector<const Vector<double> *> couplings(m);
              for (unsigned int c = 0; c < m; ++c)
                couplings[c] = &loads[c][s];
              std::vector<Vector<double>> results;
              subproblems[s]->solve_homogeneous_on_sigma(couplings, results);
              for (unsigned int c = 0; c < m; ++c)
                solutions[c][s].swap(results[c]);
            }
          else
            for (unsigned int c = 0; c < m; ++c)
              subproblems[s]->solve_homogeneous(loads[c][s], solutions[c][s]);
        });
    tasks.join_all();
    for (Solutions &w : solutions)
      share_traces(subproblems, w);
  }
} // namespace bilayer
