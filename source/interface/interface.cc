#include <bilayer/interface/interface.h>

namespace bilayer
{
  using namespace dealii;

  Interface::Interface(const ContactParameters &contact)
    : contact(contact)
  {}


  void
  Interface::setup(const Topology                                 &topology,
                   const PerSubproblem<const ElasticSubproblem *> &subs,
                   const std::vector<InterfaceCurve>              &curves)
  {
    curves_               = curves;
    const double   tol    = curves_[0].tolerance();
    const auto    &traces = coupling_.locate_traces(topology, subs, curves_);
    PerBlock<bool> active(topology.n_blocks());
    for (const unsigned int b : Layout::indices(active.size()))
      active[b] = coupling_.active(b);
    // The degree of each layer's elements (an absent layer's only matters
    // where it exists: that of layer 1).
    std::vector<unsigned int> degrees;
    for (const unsigned int l : Layout::indices(topology.n_slots()))
      {
        const unsigned int s = topology.index(static_cast<Layer>(l), 0);
        degrees.push_back(subs[s] ? subs[s]->fe().degree :
                                    subs[Layout::u_minus]->fe().degree);
      }
    space_.reinit(topology, curves_, contact, traces, degrees, active);
    coupling_.reinit(space_, contact.coupling, tol);
  }


  void
  Interface::jumps(const Solutions     &w,
                   BlockVector<double> &g,
                   const bool           every_component) const
  {
    const bool weighted = contact.sampling == JumpSampling::weighted;
    space_.initialize(g);
    coupling_.differences(w, weighted, g);
    for (const unsigned int b : Layout::indices(space_.n_blocks()))
      if (active(b))
        for (unsigned int i = 0; i < g.block(b).size(); ++i)
          g.block(b)(i) =
            every_component || space_.set().free(b, i) ?
              g.block(b)(i) /
                (weighted ? space_.node_weight(i / Layout::n_components, b) :
                            1.) :
              0.;
  }


  Tensor<1, 2>
  Interface::multiplier_traction(const BlockVector<double> &mu,
                                 const unsigned int         s,
                                 const double               x,
                                 const unsigned int         i) const
  {
    Tensor<1, 2>        t;
    std::vector<double> values;
    for (const unsigned int b : Layout::indices(space_.n_blocks()))
      for (unsigned int j = 0; j < 2; ++j)
        if ((j == 0 ? topology().coupling(b).first :
                      topology().coupling(b).second) == s &&
            topology().coupling(b).interface == i && active(b))
          {
            const unsigned int e = space_.shape_values(b, x, values);
            for (unsigned int i = 0; i <= space_.degree(b); ++i)
              {
                // The multiplier's components in its node's frame.
                const unsigned int r = space_.row(space_.node(e, i, b), b);
                const std::array<Tensor<1, 2>, 2> &frame =
                  space_.node_frame(r, b);
                for (unsigned int k = 0; k < Layout::n_components; ++k)
                  {
                    const double m = (j == 0 ? -1. : 1.) * values[i] *
                                     mu.block(b)(Layout::entry(r, k));
                    for (unsigned int c = 0; c < Layout::n_components; ++c)
                      if (frame[k][c] != 0.)
                        t[c] += m * frame[k][c];
                  }
              }
          }
    return t;
  }
} // namespace bilayer
