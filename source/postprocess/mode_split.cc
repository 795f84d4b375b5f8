#include <bilayer/postprocess/mode_split.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
  } // namespace


  std::array<double, 3>
  crack_closure_integrals(const Interface           &interface,
                          const Solutions           &w,
                          const BlockVector<double> &mu,
                          const CrackTip            &tip,
                          const double               length)
  {
    const MultiplierSpace &space = interface.space();
    // The block across the tip's interface.
    const unsigned int mu_1 = tip.interface;
    const unsigned int n_t = Layout::tangential, n_n = Layout::normal;
    Vector<double>     tm, tp;
    interface.coupling().crack_face_traces(w, tm, tp, mu_1);
    // The jump of layer 1 at node a in its frame: 0 on the glued part (the
    // tip), the opening of a crack node 0 where the faces touch (mu_c > 0,
    // complementarity) or penetrate.
    const auto jump = [&](const unsigned int a) -> std::array<double, 2> {
      if (!space.on_crack(a, mu_1))
        return {{0., 0.}};
      const double opening =
        tp(Layout::entry(a, n_n)) - tm(Layout::entry(a, n_n));
      return {{tp(Layout::entry(a, n_t)) - tm(Layout::entry(a, n_t)),
               space.contact_multiplier(mu, a, mu_1) > 0 ?
                 0. :
                 std::max(opening, 0.)}};
    };
    std::vector<double>   shape;
    std::array<double, 3> c = {{0., 0., 0.}};
    // The nodes ahead at 0 <= r < Delta (the node at r = Delta meets the
    // jump at the tip, 0); their forces F_a = -D_a mu_a against the jump at
    // the point Delta - r behind.
    for (unsigned int a = 0; a < space.n_nodes(mu_1); ++a)
      {
        const double r = tip.sign * (space.node_position(a, mu_1) - tip.s);
        if (r < -1e-12 * length || r >= length * (1 - 1e-12))
          continue;
        std::array<double, 2> F;
        for (const unsigned int comp : {n_t, n_n})
          F[comp] = -space.node_weight(a, mu_1) *
                    mu.block(mu_1)(Layout::entry(a, comp));
        std::array<double, 2> d = {{0., 0.}};
        const unsigned int    e =
          space.shape_values(mu_1, tip.s - tip.sign * (length - r), shape);
        for (unsigned int i = 0; i < shape.size(); ++i)
          {
            const std::array<double, 2> node_jump =
              jump(space.node(e, i, mu_1));
            for (const unsigned int comp : {n_t, n_n})
              d[comp] += shape[i] * node_jump[comp];
          }
        c[0] += F[n_n] * d[n_n] / (2 * length);
        c[1] += F[n_t] * d[n_t] / (2 * length);
        const double weight = space.node_weight(a, mu_1);
        c[2] =
          std::max(c[2],
                   length * (F[0] * F[0] + F[1] * F[1]) / (weight * weight));
      }
    return c;
  }


  bool
  materials_agree_across(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Topology                                 &topology,
    const unsigned int                              i,
    const Point<2>                                 &tip)
  {
    // Each layer's two sides.
    for (const unsigned int l : Layout::indices(topology.n_slots()))
      {
        const ElasticSubproblem
          *minus = subproblems[topology.index(static_cast<Layer>(l),
                                              topology.regions_of(i)[0])],
          *plus  = subproblems[topology.index(static_cast<Layer>(l),
                                             topology.regions_of(i)[1])];
        if (minus == nullptr || plus == nullptr)
          continue;
        const SymmetricTensor<4, 2> C_minus =
                                      minus->interface_law(i, tip).tangent(),
                                    C_plus =
                                      plus->interface_law(i, tip).tangent();
        double largest = 0, difference = 0;
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            for (unsigned int k = 0; k < 2; ++k)
              for (unsigned int l = 0; l < 2; ++l)
                {
                  largest    = std::max({largest,
                                         std::abs(C_minus[i][j][k][l]),
                                         std::abs(C_plus[i][j][k][l])});
                  difference = std::max(difference,
                                        std::abs(C_minus[i][j][k][l] -
                                                 C_plus[i][j][k][l]));
                }
        if (difference > 1e-12 * largest)
          return false;
      }
    return true;
  }


  void
  mode_split(const PerSubproblem<const ElasticSubproblem *> &subproblems,
             const Interface                                &interface,
             const Solutions                                &w,
             const BlockVector<double>                      &mu,
             const std::vector<double>                      &tip_cell_sizes,
             const double                                    length,
             std::vector<EnergyReleaseRate>                 &release)
  {
    const Topology &topology = interface.topology();
    for (unsigned int t = 0; t < release.size(); ++t)
      {
        EnergyReleaseRate &g = release[t];
        // The materials at the tip's interface.
        const unsigned int i   = g.tip.interface;
        const Point<2>    &tip = g.tip.point;
        const bool         agree =
          materials_agree_across(subproblems, topology, i, tip);
        const Coupling across    = topology.coupling(i);
        const double   stiffness = subproblems[across.first] != nullptr ?
                                     subproblems[across.first]
                                     ->interface_law(i, tip)
                                     .energy_norm_scale() :
                                     subproblems[across.second]
                                     ->interface_law(i, tip)
                                     .energy_norm_scale();
        g.G_I = g.G_II = g.phase_angle = g.mode_split_length = not_a_number;
        g.mode_split_note.clear();
        if (!std::isfinite(g.G))
          {
            g.mode_split_note = "G is not reported at this tip";
            continue;
          }
        if (length == 0 && !agree)
          {
            g.mode_split_note = "mode split not defined at a bimaterial tip: "
                                "set Fracture/Mode split length";
            continue;
          }
        const double cell = t < tip_cell_sizes.size() ? tip_cell_sizes[t] : 0;
        // A closure length below the tip's cell is resolved by one cell
        // only (the nodal forces integrate over it): it is raised to the
        // cell, and the note and mode_split_length carry the length used.
        const bool         raised = length > 0 && length < cell;
        const double       delta  = raised     ? cell :
                                    length > 0 ? length :
                                                 std::min(mode_split_cells * cell,
                                                   0.5 * g.tip.free_distance);
        std::ostringstream note;
        note << std::setprecision(6);
        if (raised)
          note << "Fracture/Mode split length " << length
               << " is below the tip cell " << cell
               << ": the split is computed over " << delta;
        if (!(delta > 0) || delta > g.tip.free_distance)
          {
            note << (note.str().empty() ? "" : "; ") << "the closure length "
                 << delta << " does not fit in the free distance "
                 << g.tip.free_distance
                 << " of the tip (Fracture/Mode split length)";
            g.mode_split_note = note.str();
            continue;
          }
        g.mode_split_length = delta;
        const std::array<double, 3> c =
          crack_closure_integrals(interface, w, mu, g.tip, delta);
        // A negative closure work is round-off (or faces that close behind
        // the tip): no energy of that mode.
        const double c_I = std::max(c[0], 0.), c_II = std::max(c[1], 0.);
        if (c_I + c_II > 0)
          {
            g.G_I  = g.G * (c_I / (c_I + c_II));
            g.G_II = g.G * (c_II / (c_I + c_II));
            // atan(sqrt(G_II / G_I)) from the ratio itself, so that it
            // holds for a G of either sign (round-off near 0).
            g.phase_angle =
              std::atan2(std::sqrt(c_II), std::sqrt(c_I)) * 180 / M_PI;
          }
        else if (std::abs(g.G) <= 1e-6 * c[2] / stiffness)
          {
            // Nothing released behind the tip, and G is round-off.
            g.G_I = g.G_II = 0;
            note << (note.str().empty() ? "" : "; ")
                 << "no crack-closure work and G at round-off: G_I = G_II = "
                    "0, no phase angle";
            g.mode_split_note = note.str();
          }
        else
          {
            note << (note.str().empty() ? "" : "; ")
                 << "the crack-closure work over " << delta
                 << " is 0 while G is not: the split is 0/0";
            g.mode_split_note = note.str();
          }
        if (raised && agree)
          g.mode_split_note = note.str();
        if (!agree)
          {
            note << (note.str().empty() ? "" : "; ")
                 << "bimaterial tip: the split at the reference length "
                 << delta << " (Fracture/Mode split length)";
            g.mode_split_note = note.str();
          }
      }
  }
} // namespace bilayer
