#ifndef bilayer_estimator_h
#define bilayer_estimator_h

#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/subproblem/subproblem.h>

#include <array>

namespace bilayer
{
  /**
   * Error indicators per active cell of the region meshes (indexed
   * by active_cell_index()), for adaptive refinement:
   *   eta_K^2 = eta_K(u)^2 + eta_K(v)^2 + sum over the Sigma faces F of K
   *             of h_F / 24 int_F |(sigma(w) n - t) / (2 mu)|^2 ds
   *             [+ h_K^2 / 12 int_K |(f + div sigma(w)) / (2 mu)|^2 dx],
   * where eta_K(w) is Kelly's indicator (jumps of the normal derivative
   * across interior faces, deal.II's KellyErrorEstimator) of each layer and,
   * with @p interface_terms, t is the traction of the multipliers on the
   * subproblem w (Interface::multiplier_traction()) for each layer: the
   * residual of the multiplier load on Sigma, which is large where the
   * discrete multipliers do not resolve the traction (the crack tips and
   * the end of the contact zone). Division by 2 mu gives the stress
   * residual the units of a displacement gradient, as in Kelly's terms;
   * the weight h/24 is Kelly's. On the crack faces of layer 1 the
   * indicator also carries @p contact_weight times
   * |int_F mu_c [u].nu ds| / (2 mu) (the
   * complementarity of contact_residual() (interface_diagnostics.h), split
   * among the faces by overlap; an energy over 2 mu, so again a squared
   * length): the discrete constraints hold at the nodes only, and the product
   * is non-zero on the segment where the contact zone ends.
   * A layer with a VolumeLoad (body force f, eigenstrain eps*) has
   * sigma(w) = C (eps(w) - eps*) in the Sigma residual and the cell
   * residual in brackets (h_K the cell's diameter; the weight 1/12 of the
   * residual estimator's h_K^2, as Kelly's h_F / 24 is 1/12 of its
   * h_F / 2; div sigma from the Hessians of w and the gradient of eps*); a
   * layer without one has neither.
   *
   * With @p global_estimate, also the global estimate in the units of the
   * energy norm,
   *   eta = (sum over the four subproblems s of 2 mu_s sum_K eta_K(s)^2)^1/2,
   * each layer's squared indicators (squared lengths) times twice its shear
   * modulus: an energy (per unit thickness), to be compared with
   * a(e, e) = 2 (Pi_h - Pi) of the error e = u - u_h (the efficiency index
   * eta / (2 |Pi_h - Pi|)^1/2 of scripts/mesh_convergence).
   *
   * Scale invariance: the problem is linear in the loads (positively
   * homogeneous with the contact constraints), so the indicators of the
   * solution times c are c times those of the solution. They are computed
   * from the solution and multipliers divided by the power of two S =
   * normalisation_scale() (exactly: the division by a power of two rounds
   * nothing), where Kelly's single precision indicators and the squares of
   * the residuals can neither overflow nor underflow, and multiplied by S
   * at the end in double precision: loads scaled by a power of two give
   * indicators and eta scaled by exactly that power, whatever the loads'
   * magnitude (within double precision).
   */
  std::vector<dealii::Vector<double>>
  estimate_error(const PerSubproblem<const ElasticSubproblem *> &subproblems,
                 const Interface                                &interface,
                 const Solutions                                &solutions,
                 const dealii::BlockVector<double>              &multipliers,
                 const bool   interface_terms,
                 const double contact_weight  = 1,
                 double      *global_estimate = nullptr);

  /**
   * The power of two 2^e with 2^(e-1) <= max |w| < 2^e over the solutions
   * of all subproblems (over all processes: collective); 1 for a zero or
   * non-finite solution.
   */
  double
  normalisation_scale(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Solutions                                &solutions);
} // namespace bilayer

#endif
