// The cohesive springs of MultiplierSpace (docs/cohesive.md): the kinds of
// a cohesive zone's components and the springs' part of the dual problem.

#include <deal.II/base/exceptions.h>

#include <bilayer/interface/multiplier_space.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;

  void
  MultiplierSpace::set_cohesive_compliance(const std::vector<double> &c,
                                           const unsigned int         b)
  {
    AssertThrow(c.size() == n_nodes(b),
                ExcMessage("MultiplierSpace::set_cohesive_compliance: one "
                           "compliance per node of the block is needed"));
    for (unsigned int a = 0; a < n_nodes(b); ++a)
      {
        if (std::isnan(c[a]) || !cohesive_node(a, b))
          continue;
        for (const unsigned int k : {Layout::tangential, Layout::normal})
          {
            const unsigned int i = Layout::entry(a, k);
            if (std::isinf(c[a]))
              set_.copy_component(crack_set, b, i);
            else
              set_.set_cohesive(
                b, i, c[a], k == Layout::normal, multiplier_bound);
          }
      }
  }


  bool
  MultiplierSpace::cohesive_node(const unsigned int a,
                                 const unsigned int b) const
  {
    return topology_.across(b) && crack_nodes[b][a] && !corner_nodes[b][a] &&
           crack_set.free(b, Layout::entry(a, Layout::normal));
  }


  void
  MultiplierSpace::add_cohesive_jumps(const BlockVector<double> &mu,
                                      BlockVector<double>       &g) const
  {
    for (unsigned int i = 0; i < g.size(); ++i)
      if (set_.cohesive(i))
        g(i) -= set_.cohesive_term(i, mu(i));
  }


  void
  MultiplierSpace::add_cohesive_operator(const BlockVector<double> &mu,
                                         const BlockVector<double> &x,
                                         BlockVector<double>       &Fx) const
  {
    unsigned int i = 0;
    for (unsigned int b = 0; b < x.n_blocks(); ++b)
      for (unsigned int j = 0; j < x.block(b).size(); ++j, ++i)
        if (set_.cohesive(i))
          Fx.block(b)(j) += meshes[b].node_weight[j / Layout::n_components] *
                            set_.cohesive_slope(i, mu(i)) * x.block(b)(j);
  }
} // namespace bilayer
