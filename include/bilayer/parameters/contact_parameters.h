#ifndef bilayer_contact_parameters_h
#define bilayer_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

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

  struct ContactParameters
  {
    bool               non_penetration  = true;
    double             multiplier_bound = 1e7;
    MultiplierCoupling coupling         = MultiplierCoupling::lumped;
    JumpSampling       sampling         = JumpSampling::weighted;
    MultiplierMesh     mesh             = MultiplierMesh::finer_trace;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace bilayer

#endif
