#ifndef bilayer_cohesive_newton_h
#define bilayer_cohesive_newton_h

#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <bilayer/interface/cohesive_zone.h>
#include <bilayer/solvers/subdomain_solves.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The semismooth Newton method of a cohesive step on the interface alone
   * (docs/cohesive.md, "The Newton method"). The jumps are affine in the
   * multipliers and the load factor, g = lambda d - A mu (proportional
   * loads; g = g0 - A mu at a prescribed load factor), with A the jumps of
   * the homogeneous solves with unit multipliers: a dense matrix over the
   * components that carry a multiplier or lie in the zone, built once
   * from the subproblems' factorisations (on Sigma, 64 columns at a time:
   * two blocked dense triangular solves per subproblem and batch). The
   * step's equations are then a small dense
   * system in (mu, lambda):
   *  - a glued component: g = 0;
   *  - a contact component: min(mu, -k0 g) = 0 (mu >= 0, g <= 0, mu g = 0);
   *  - a node of the zone: mu_t = k g_t, and min(mu_n - k g_n, -k0 g_n) =
   *    0 (a spring in tension, exact contact under pressure), with the
   *    secant stiffness k = k0 (1 - d) of the damage d that the separations
   *    give (CohesiveZone::node_state(): irreversible, from the committed
   *    state); the derivatives of k by central differences of the law;
   *  - the step's control: the zone's dissipation equals the target
   *    (dissipation control), the control node's equivalent separation its
   *    committed history plus the increment (separation control), or the
   *    load factor is given.
   * Each Newton step solves the dense Jacobian (a softening tangent makes
   * it indefinite, which the dual problem's active-set method cannot take);
   * the first 30 are taken whole (line_search()), later ones backtrack on
   * the residual's norm. Most rows never change (glued
   * components, intact nodes, open contact): the LU factorisation (partial
   * pivoting) of one Jacobian is kept, across steps, and a Newton step
   * solves with it and the Sherman-Morrison-Woodbury formula for the rows
   * that differ from it (the process zone's, the control's, contact that
   * changed); a new factorisation is made where more than max(40, n / 8)
   * rows differ. The first iterate of a step under path following is the
   * better (by the residual) of the last step's solution and its linear
   * extrapolation from the step before.
   * The result is the first iterate of the step's secant iteration, which
   * checks it with the outer solver: a state the Newton method got right
   * settles in one solve.
   *
   * Scenes it does not take report why in unsupported(): Coulomb or
   * Tresca friction, and prescribed load factors (a softening zone has
   * several equilibria at one load factor, and full Newton steps from the
   * last state can land on another branch than the one the path follows:
   * on random scenes they broke whole zones below the peak); the secant
   * iteration with the outer solver takes them.
   */
  class CohesiveNewton
  {
  public:
    /// The step's control (CohesiveControl, resolved for the step).
    enum class Control
    {
      load_factor,
      separation,
      dissipation
    };

    /// Why a scene's steps cannot be solved by this method (@p frictional:
    /// its crack faces have friction, the only source of friction
    /// components; @p prescribed: the steps are prescribed load factors),
    /// or an empty string.
    static std::string
    unsupported(const bool frictional, const bool prescribed);

    /**
     * The matrix A of the components of @p interface that carry a
     * multiplier or lie in @p zone: one homogeneous solve of
     * @p subproblems per component.
     */
    CohesiveNewton(const Subproblems  &subproblems,
                   const Interface    &interface,
                   const CohesiveZone &zone);

    /// The number of unknown multiplier components (the size of A).
    unsigned int
    size() const
    {
      return unknowns.size();
    }

    /// The homogeneous solves spent on A.
    unsigned int
    subdomain_solves() const
    {
      return n_solves;
    }

    /// The LU factorisations of the Jacobian made so far.
    unsigned int
    factorisations() const
    {
      return kept.factorisations;
    }

    /// A step's data.
    struct Step
    {
      Control control = Control::load_factor;
      /// Dissipation control: the zone's dissipation wanted; separation
      /// control: the growth of the control node's history.
      double target = 0;
      /// Separation control: the control node (as CohesiveZone's).
      int control_node = -1;
    };

    /// What a Newton solve gives.
    struct Result
    {
      bool         converged  = false;
      unsigned int iterations = 0;
      /// The largest residual of the last iterate (traction units; the
      /// control's row relative to its target).
      double residual = 0;
      /// The multipliers (every component), the load factor and the
      /// separations of the zone's nodes at the solution.
      dealii::BlockVector<double>           mu;
      double                                lambda = 0;
      std::vector<CohesiveZone::Separation> delta;
    };

    /**
     * Newton's method for the step @p step from the multipliers @p mu0 and
     * load factor @p lambda0, with @p g0 the jumps (every component) of the
     * solutions without multipliers at @p lambda0, and the zone's committed
     * state. At most @p max_iterations Newton steps; converged where the
     * largest residual falls below @p tolerance times the scale of the
     * multipliers.
     */
    Result
    solve(const CohesiveZone                &zone,
          const dealii::BlockVector<double> &g0,
          const dealii::BlockVector<double> &mu0,
          const double                       lambda0,
          const Step                        &step,
          const unsigned int                 max_iterations,
          const double                       tolerance) const;

  private:
    /// The role of an unknown component.
    enum class Role
    {
      glued,
      contact,
      zone_tangential,
      zone_normal
    };

    /// A row of the Jacobian: unit e_r plus factor_k times the derivative
    /// of the jump g_{q_k} (the row of -A and the load factor's column).
    struct Row
    {
      double                      unit    = 0;
      unsigned int                n_terms = 0;
      std::array<unsigned int, 3> q{};
      std::array<double, 3>       factor{};

      bool
      operator==(const Row &other) const
      {
        if (unit != other.unit || n_terms != other.n_terms)
          return false;
        for (unsigned int k = 0; k < n_terms; ++k)
          if (q[k] != other.q[k] || factor[k] != other.factor[k])
            return false;
        return true;
      }
    };

    /// What the Newton steps keep from one solve to the next: the scale of
    /// the rows, the factorised Jacobian with its rows and control row, the
    /// columns of its inverse asked so far, and the last two starts.
    struct Kept
    {
      double                                            row_scale = 0;
      std::vector<Row>                                  rows;
      dealii::Vector<double>                            control_row;
      std::unique_ptr<dealii::LAPACKFullMatrix<double>> lu;
      std::map<unsigned int, dealii::Vector<double>>    columns;
      dealii::Vector<double>                            start, start_before;
      double       increment = 0, increment_before = 0;
      unsigned int factorisations = 0;
    };

    /// The Newton direction J^{-1} r for the Jacobian of @p rows and
    /// @p control_row (the kept factorisation and the rows that differ
    /// from it, or a new one).
    dealii::Vector<double>
    direction(const std::vector<Row>       &rows,
              const dealii::Vector<double> &control_row,
              const dealii::Vector<double> &r) const;

    class Evaluation;

    /// The first iterate @p x of a step under path following: the start,
    /// or its extrapolation from the start before (by the ratio of the
    /// steps' increments), whichever has the smaller residual.
    void
    predict(const CohesiveZone     &zone,
            const Step             &step,
            Evaluation             &equations,
            dealii::Vector<double> &x) const;

    /// A new kept factorisation: the Jacobian of @p rows and
    /// @p control_row (@p load: the jumps per unit load factor under path
    /// following, else empty).
    void
    factorise(const std::vector<Row>       &rows,
              const dealii::Vector<double> &control_row,
              const dealii::Vector<double> &load) const;

    /// The columns J_kept^{-1} e_k of the rows @p differ not kept yet.
    void
    add_columns(const std::vector<unsigned int> &differ) const;

    /**
     * The step length from @p x along -@p dx (A x is @p Ax; A dx, computed
     * here, goes into @p Adx; @p r is the residual at x). Without
     * @p damped, 1 unless the full step's residual is not finite or its
     * |R|^2 grows more than 1e8 times; else backtracking on |R|^2: the
     * first of the lengths 1, 1/2, ... (down to 1e-3) that decreases it
     * enough, else the best of them, or 0 where none decreases it.
     */
    double
    line_search(Evaluation                   &equations,
                const dealii::Vector<double> &x,
                const dealii::Vector<double> &dx,
                const dealii::Vector<double> &Ax,
                const dealii::Vector<double> &r,
                const bool                    damped,
                dealii::Vector<double>       &Adx) const;

    /// The multipliers of the iterate @p x (@p g its jumps) in
    /// @p result, each component of @p mu0's layout, exactly zero where
    /// open, and the zone's separations.
    void
    solution_state(const CohesiveZone                &zone,
                   const dealii::Vector<double>      &g,
                   const dealii::Vector<double>      &x,
                   const dealii::BlockVector<double> &mu0,
                   Result                            &result) const;

    /// y = A x (BLAS).
    void
    multiply(const dealii::Vector<double> &x, dealii::Vector<double> &y) const;

    /// Row @p r of the Jacobian of @p row (size() + 1 entries under path
    /// following: @p g_fixed the jumps per unit load factor; size() with
    /// an empty @p g_fixed).
    void
    materialise(const unsigned int            r,
                const Row                    &row,
                const dealii::Vector<double> &g_fixed,
                dealii::Vector<double>       &values) const;

    /// The unknowns' global indices in the multiplier vector, their roles
    /// and, for the zone's, their node.
    std::vector<unsigned int> unknowns;
    std::vector<Role>         roles;
    std::vector<unsigned int> nodes;
    /// Per node of the zone's block: the positions of its tangential and
    /// normal components among the unknowns (-1 off the zone).
    std::vector<std::array<int, 2>> node_unknowns;
    /// The jumps of the unknown components for unit multipliers:
    /// g = g0 - A mu.
    dealii::FullMatrix<double> A;
    unsigned int               n_solves = 0;
    /// The jumps per unit load factor of the last solve (path following).
    mutable dealii::Vector<double> g_unit;
    mutable Kept                   kept;
  };
} // namespace bilayer

#endif
