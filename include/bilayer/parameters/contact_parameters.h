#ifndef bilayer_contact_parameters_h
#define bilayer_contact_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

/**
 * The subsection Contact: non-penetration on the crack, the multiplier
 * bound and how the multipliers are discretised and coupled.
 */
namespace bilayer
{
  /**
   * How the multipliers act on the traces (the matrix C of interface.h).
   * `lumped`: nodal quadrature of the multiplier mesh (node-to-node
   * coupling); `consistent`: Gauss quadrature on the common refinement of
   * the trace meshes (mortar coupling).
   */
  enum class MultiplierCoupling
  {
    lumped,
    consistent
  };

  /**
   * Which trace of layer 1 carries the mesh of mu_1 (the "slave" of the
   * mortar coupling across Sigma, MultiplierSpace): the one with more
   * segments on Sigma (the contact constraint tested at the finer set of
   * points) or the one with fewer (fewer, better conditioned constraints).
   * The two coincide on matching meshes.
   */
  enum class MultiplierMesh
  {
    finer_trace,
    coarser_trace
  };

  /**
   * How the jumps in the Uzawa update are sampled. `weighted`: the weak
   * jump D^{-1} C w (the gradient of the Lagrangian in the metric of the
   * lumped multiplier mass D); `nodal`: the traces evaluated at the
   * multiplier nodes. For lumped coupling and matching meshes both agree.
   */
  enum class JumpSampling
  {
    weighted,
    nodal
  };

  /**
   * The law of the tangential force on the crack faces (docs/problem.md §1,
   * "Friction on the crack faces"). `none`: frictionless (the paper's
   * condition (8)); `tresca`: given friction, |s_tau| <= g with the bound
   * g(x, y, s) of Contact/Friction bound; `coulomb`: |s_tau| <= F s_nu with
   * the coefficient F of Contact/Friction coefficient, solved as a fixed
   * point over Tresca problems.
   */
  enum class Friction
  {
    none,
    tresca,
    coulomb
  };

  /**
   * How Coulomb friction is solved. `fixed point`: a sequence of Tresca
   * problems with the bound F mu_c of the previous one, each by the outer
   * solver (every solver); `direct`: the Coulomb cone in the projection of
   * a first-order solver (uzawa, accelerated), the bound following mu_c in
   * every iteration.
   */
  enum class CoulombMethod
  {
    fixed_point,
    direct
  };

  struct ContactParameters
  {
    bool               non_penetration  = true;
    double             multiplier_bound = 1e7;
    MultiplierCoupling coupling         = MultiplierCoupling::lumped;
    JumpSampling       sampling         = JumpSampling::weighted;
    MultiplierMesh     mesh             = MultiplierMesh::finer_trace;
    Friction           friction         = Friction::none;
    /// Tresca's bound g as written (an expression of x, y and s).
    std::string friction_bound = "0";
    /// Coulomb's coefficient F.
    double friction_coefficient = 0;
    /// The most fixed-point iterations (Tresca solves) of Coulomb friction.
    unsigned int  friction_iterations = 50;
    CoulombMethod coulomb_method      = CoulombMethod::fixed_point;

    /**
     * Tresca's bound g at the point @p p of Sigma whose coordinate along
     * Sigma is @p s [stress]; 0 without Tresca friction. Not finite or
     * negative values are the caller's to refuse (friction_bound_refusal()).
     */
    double
    tresca_bound(const dealii::Point<2> &p, const double s) const;

    /// Whether the crack faces carry a tangential force.
    bool
    frictional() const
    {
      return friction != Friction::none;
    }


    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

  private:
    /// The parser of friction_bound (Tresca only).
    std::shared_ptr<const dealii::FunctionParser<3>> bound_function;
  };

  /**
   * The one-line refusal of a Tresca bound value @p g at the point @p p of
   * Sigma (empty if g is finite and >= 0).
   */
  std::string
  friction_bound_refusal(const double g, const dealii::Point<2> &p);
} // namespace bilayer

#endif
