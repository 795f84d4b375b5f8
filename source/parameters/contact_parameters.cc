#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/contact_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

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
    prm.leave_subsection();
  }
} // namespace bilayer
