#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/contact_parameters.h>
#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/parameter_entries.h>

#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Non-penetration on the crack",
                      "true",
                      Patterns::Bool(),
                      "true: the crack faces of layer 1 must not penetrate "
                      "each other ([u].nu >= 0, multiplier lambda_c). false: "
                      "the linear problem with traction-free crack faces that "
                      "may interpenetrate (the gluing multipliers stay).");
    prm.declare_entry("Multiplier bound p",
                      "1e7",
                      Patterns::Double(0),
                      "Bound p of the multiplier sets: 0 <= lambda_c <= p, "
                      "-p <= lambda_g, lambda-, lambda+ <= p [stress].");
    prm.declare_entry("Multiplier coupling",
                      "lumped",
                      Patterns::Selection("lumped|consistent"),
                      "How the multipliers act on the traces: lumped (nodal "
                      "quadrature of the multiplier mesh, node-to-node "
                      "constraints) or consistent (Gauss quadrature on the "
                      "common refinement of the trace meshes, mortar "
                      "constraints).");
    prm.declare_entry("Jump sampling",
                      "weighted",
                      Patterns::Selection("weighted|nodal"),
                      "Jump used in the multiplier update: weighted (the weak "
                      "jump D^-1 C w, D the lumped multiplier mass) or nodal "
                      "(the traces evaluated at the multiplier nodes). Both "
                      "agree for lumped coupling on matching meshes.");
    prm.declare_entry(
      "Multiplier mesh",
      "finer trace",
      Patterns::Selection("finer trace|coarser trace"),
      "Which trace of layer 1 on Sigma carries the mesh of the multipliers "
      "across Sigma (mu_c, mu_g) where the Omega- and Omega+ meshes do not "
      "match: finer trace (the side with more segments; contact tested at "
      "more points) or coarser trace (fewer constraints, a better "
      "conditioned dual problem). The layer-gluing multipliers always live "
      "on their own side's trace (docs/multipliers.md).");
    prm.declare_entry(
      "Friction",
      "none",
      Patterns::Selection("none|tresca|coulomb"),
      "The tangential force s_tau on the crack faces (docs/problem.md §1): "
      "none (frictionless faces), tresca (given friction: |s_tau| <= g, "
      "the faces stick where |s_tau| < g and slip against the force where "
      "|s_tau| = g) or coulomb (|s_tau| <= F s_nu, F the friction "
      "coefficient, s_nu the contact pressure; solved as a fixed point over "
      "Tresca problems). Needs non-penetration on the crack.");
    prm.declare_entry("Friction bound",
                      "0",
                      Patterns::Anything(),
                      "Tresca's bound g >= 0 [stress], an expression of x, "
                      "y and s (the coordinate along Sigma, arc length) "
                      "[length]; read with Friction = tresca.");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Double(0),
                      "Coulomb's friction coefficient F >= 0 "
                      "[dimensionless]; read with Friction = coulomb.");
    prm.declare_entry(
      "Friction iterations",
      "50",
      Patterns::Integer(1, 100000),
      "The most fixed-point iterations of Coulomb friction (each a Tresca "
      "solve with the bound F s_nu of the previous one), 1 to 100000; the "
      "run fails if the bounds have not settled to Solver/Tolerance by then.");
    prm.declare_entry(
      "Coulomb method",
      "fixed point",
      Patterns::Selection("fixed point|direct"),
      "How Coulomb friction is solved: fixed point (a sequence of Tresca "
      "problems with the bound F s_nu of the previous one, each by "
      "Solver/Method; every solver) or direct (the Coulomb cone in the "
      "projection of Solver/Method = uzawa or accelerated, the bound "
      "following s_nu in every iteration); read with Friction = coulomb.");
    prm.leave_subsection();
  }


  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    non_penetration  = prm.get_bool("Non-penetration on the crack");
    multiplier_bound = get_double(prm, "Contact", "Multiplier bound p");
    AssertThrow(multiplier_bound > 0,
                ExcMessage("Contact/Multiplier bound p must be > 0, got " +
                           prm.get("Multiplier bound p")));
    coupling = prm.get("Multiplier coupling") == "consistent" ?
                 MultiplierCoupling::consistent :
                 MultiplierCoupling::lumped;
    sampling = prm.get("Jump sampling") == "nodal" ? JumpSampling::nodal :
                                                     JumpSampling::weighted;
    mesh     = prm.get("Multiplier mesh") == "coarser trace" ?
                 MultiplierMesh::coarser_trace :
                 MultiplierMesh::finer_trace;
    const std::string law = prm.get("Friction");
    friction              = law == "tresca"  ? Friction::tresca :
                            law == "coulomb" ? Friction::coulomb :
                                               Friction::none;
    friction_bound        = prm.get("Friction bound");
    friction_coefficient  = get_double(prm, "Contact", "Friction coefficient");
    friction_iterations   = prm.get_integer("Friction iterations");
    coulomb_method        = prm.get("Coulomb method") == "direct" ?
                              CoulombMethod::direct :
                              CoulombMethod::fixed_point;
    AssertThrow(!frictional() || non_penetration,
                ExcMessage("Contact/Friction = " + law +
                           " needs Contact/Non-penetration on the crack = "
                           "true (friction acts between touching faces)"));
    AssertThrow(std::isfinite(friction_coefficient),
                ExcMessage("Contact/Friction coefficient must be a finite "
                           "number >= 0, got " +
                           prm.get("Friction coefficient")));
    bound_function.reset();
    if (friction == Friction::tresca)
      bound_function = expressions::curve_function(friction_bound,
                                                   {},
                                                   "Contact/Friction bound");
    prm.leave_subsection();
  }


  double
  ContactParameters::tresca_bound(const Point<2> &p, const double s) const
  {
    if (friction != Friction::tresca || !bound_function)
      return 0.;
    return bound_function->value(Point<3>(p[0], p[1], s));
  }


  std::string
  friction_bound_refusal(const double g, const Point<2> &p)
  {
    if (std::isfinite(g) && g >= 0)
      return "";
    std::ostringstream msg;
    msg << "Contact/Friction bound must be finite and >= 0 on the crack, got "
        << g << " at (x, y) = (" << p[0] << ", " << p[1] << ")";
    return msg.str();
  }
} // namespace bilayer
