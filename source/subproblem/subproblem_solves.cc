#include <bilayer/subproblem/subproblem.h>

/**
 * @file
 * The solves of a subproblem for multiplier loads: on its Sigma dofs alone
 * through the Schur complement its factorisation keeps, or whole.
 */

namespace bilayer
{
  using namespace dealii;

  void
  ElasticSubproblem::solve_on_sigma(const Vector<double> &coupling,
                                    Vector<double>       &solution,
                                    const bool            homogeneous) const
  {
    Assert(condensed(), ExcInternalError());
    // The condensed load on the unconstrained Sigma dofs, the Sigma part of
    // K^{-1} of it ...
    std::vector<double> y = condensed_load(coupling);
    factorisation.schur_complement()->solve(y);
    // ... added to the solution without coupling, and distributed to the
    // constrained Sigma dofs.
    if (homogeneous)
      solution.reinit(n_dofs());
    else
      solution = particular;
    for (const auto &[i, a] : sigma_positions)
      solution(i) += y[a];
    for (const auto &dof : constrained_sigma_dofs)
      for (const auto &[a, weight] : dof.entries)
        solution(dof.dof) += weight * y[a];
  }


  void
  ElasticSubproblem::solve_homogeneous_on_sigma(
    const std::vector<const Vector<double> *> &couplings,
    std::vector<Vector<double>>               &solutions) const
  {
    Assert(condensed(), ExcInternalError());
    const std::size_t   n = n_schur_dofs(), m = couplings.size();
    std::vector<double> Y(n * m);
    for (std::size_t c = 0; c < m; ++c)
      {
        const std::vector<double> y = condensed_load(*couplings[c]);
        std::copy(y.begin(), y.end(), Y.begin() + c * n);
      }
    factorisation.schur_complement()->solve_many(Y, m);
    solutions.resize(m);
    for (std::size_t c = 0; c < m; ++c)
      {
        const double *y = Y.data() + c * n;
        solutions[c].reinit(n_dofs());
        for (const auto &[i, a] : sigma_positions)
          solutions[c](i) += y[a];
        for (const auto &dof : constrained_sigma_dofs)
          for (const auto &[a, weight] : dof.entries)
            solutions[c](dof.dof) += weight * y[a];
      }
  }


  std::vector<double>
  ElasticSubproblem::condensed_load(const Vector<double> &coupling) const
  {
    std::vector<double> y(n_schur_dofs(), 0.);
    if (coupling.size() > 0)
      {
        for (const auto &[i, a] : sigma_positions)
          y[a] += coupling(i);
        for (const auto &dof : constrained_sigma_dofs)
          for (const auto &[a, weight] : dof.entries)
            y[a] += weight * coupling(dof.dof);
      }
    return y;
  }


  void
  ElasticSubproblem::solve_coupling(const Vector<double> &coupling,
                                    Vector<double>       &solution) const
  {
    // K^{-1} of the condensed load (zero off the Sigma dofs: only the
    // backward substitution runs through the sparse factor), with the
    // homogeneous constraints.
    std::vector<double> y = condensed_load(coupling);
    factorisation.solve_from_trailing(y, solution);
    homogeneous_constraints.distribute(solution);
  }


  void
  ElasticSubproblem::apply_schur_complement(const Vector<double> &x,
                                            Vector<double>       &y) const
  {
    Assert(condensed(), ExcInternalError());
    const SchurComplementFactor &schur = *factorisation.schur_complement();
    std::vector<double>          values(schur.size());
    for (const auto &[i, a] : sigma_positions)
      values[a] = x(i);
    schur.multiply(values);
    y.reinit(n_dofs());
    for (const auto &[i, a] : sigma_positions)
      y(i) = values[a];
  }


  void
  ElasticSubproblem::solve(const Vector<double> &coupling,
                           Vector<double>       &solution) const
  {
    if (condensed() && coupling.size() > 0)
      {
        // The solution without coupling (distributed) plus K^{-1} of the
        // coupling load.
        solve_coupling(coupling, solution);
        solution += particular;
        return;
      }
    if (shared)
      {
        if (coupling.size() > 0)
          solution = coupling;
        else
          solution.reinit(n_dofs());
        homogeneous_constraints.condense(solution);
        shared->solve(solution, true);
      }
    else
      {
        if (coupling.size() > 0)
          {
            solution = coupling;
            homogeneous_constraints.condense(solution);
            solution += system_rhs;
          }
        else
          solution = system_rhs;
        factorisation.solve(solution);
      }
    constraints.distribute(solution);
    add_anchor_displacements(solution);
  }


  void
  ElasticSubproblem::solve_homogeneous(const Vector<double> &coupling,
                                       Vector<double>       &solution) const
  {
    if (condensed())
      {
        solve_coupling(coupling, solution);
        return;
      }
    solve_load(coupling, solution);
  }


  void
  ElasticSubproblem::share_trace(Vector<double> &w) const
  {
    if (!distribution.parallel())
      return;
    if (w.size() != n_dofs())
      w.reinit(n_dofs());
    distribution.share(index(), w, &trace_dofs_);
  }
} // namespace bilayer
