// The anchors of a floating subproblem (no clamped side): three dofs held
// at zero make its stiffness non-singular; their displacements and the
// reactions they carry are what FloatingParts balances.

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>
#include <limits>
#include <map>

namespace bilayer
{
  using namespace dealii;

  void
  ElasticSubproblem::choose_anchors(const std::vector<bool> &clamped)
  {
    anchors_.clear();
    anchor_values = {{0, 0, 0}};
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const types::boundary_id id = cell->face(f)->boundary_id();
            if (id < clamped.size() && clamped[id])
              return;
          }

    // The support points of the x and y components; the candidates are
    // the dofs no hanging node constrains, off Sigma where there are such.
    std::vector<Point<2>> points(dofs.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping(), dofs, points);
    const IndexSet x_dofs =
      DoFTools::extract_dofs(dofs,
                             ComponentMask(std::vector<bool>{true, false}));
    const IndexSet on_sigma =
      DoFTools::extract_boundary_dofs(dofs,
                                      ComponentMask(),
                                      BoundaryIds::interfaces());
    std::map<std::pair<double, double>, types::global_dof_index> y_dof_at;
    for (types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
      if (!x_dofs.is_element(i))
        y_dof_at[{points[i][0], points[i][1]}] = i;
    // (Not a master of a hanging node either: the reaction at an anchor is
    // then its row of K w - b alone.)
    std::vector<bool> master(dofs.n_dofs(), false);
    for (const auto &line : homogeneous_constraints.get_lines())
      for (const auto &entry : line.entries)
        master[entry.first] = true;
    const auto unusable = [&](const types::global_dof_index i) {
      return homogeneous_constraints.is_constrained(i) || master[i];
    };
    std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
      pairs, off_sigma;
    for (const types::global_dof_index i : x_dofs)
      {
        const auto y = y_dof_at.find({points[i][0], points[i][1]});
        if (y == y_dof_at.end() || unusable(i) || unusable(y->second))
          continue;
        pairs.emplace_back(i, y->second);
        if (!on_sigma.is_element(i) && !on_sigma.is_element(y->second))
          off_sigma.emplace_back(i, y->second);
      }
    const auto &candidates = off_sigma.size() >= 2 ? off_sigma : pairs;
    AssertThrow(candidates.size() >= 2,
                ExcMessage("subproblem " + name() +
                           " floats (no clamped side) but has fewer than two "
                           "unconstrained support points to anchor it"));

    // Anchor A nearest to the centroid of the candidates, B farthest from A.
    Point<2> centre;
    for (const auto &c : candidates)
      centre += points[c.first];
    centre /= static_cast<double>(candidates.size());
    const auto nearest = [&](const Point<2> &p, const bool farthest) {
      std::size_t best  = 0;
      double      value = farthest ? -1. : std::numeric_limits<double>::max();
      for (std::size_t c = 0; c < candidates.size(); ++c)
        {
          const double d = points[candidates[c].first].distance(p);
          if (farthest ? d > value : d < value)
            {
              best  = c;
              value = d;
            }
        }
      return candidates[best];
    };
    const auto         a = nearest(centre, false);
    const auto         b = nearest(points[a.first], true);
    const Tensor<1, 2> d = points[b.first] - points[a.first];
    // The component of B that a rotation about A moves most.
    const bool hold_y = std::abs(d[0]) >= std::abs(d[1]);
    anchors_          = {a.first, a.second, hold_y ? b.second : b.first};
    anchor_places     = {{{points[a.first], 0u},
                          {points[a.first], 1u},
                          {points[b.first], hold_y ? 1u : 0u}}};
    for (const auto i : anchors_)
      {
        constraints.add_line(i);
        homogeneous_constraints.add_line(i);
      }
  }


  void
  ElasticSubproblem::make_anchor_modes()
  {
    if (!floating() || !owned() || shared)
      return;
    for (unsigned int k = 0; k < 3; ++k)
      {
        // E_k = e_k - K~^{-1} K e_k: the unit displacement of anchor k
        // extended without load.
        Vector<double> unit(n_dofs()), column(n_dofs());
        unit(anchors_[k]) = 1;
        stiffness.vmult(column, unit);
        column *= -1.;
        solve_load(column, anchor_modes[k]);
        anchor_modes[k](anchors_[k]) += 1;
      }
    for (unsigned int k = 0; k < 3; ++k)
      {
        Vector<double> reaction(n_dofs());
        stiffness.vmult(reaction, anchor_modes[k]);
        for (unsigned int j = 0; j < 3; ++j)
          anchor_stiffness[j][k] = reaction(anchors_[j]);
      }
  }


  void
  ElasticSubproblem::add_anchor_displacements(Vector<double> &solution) const
  {
    if (!floating() || anchor_modes[0].size() != solution.size())
      return;
    for (unsigned int k = 0; k < 3; ++k)
      if (anchor_values[k] != 0)
        solution.add(anchor_values[k], anchor_modes[k]);
  }


  void
  ElasticSubproblem::set_anchor_displacements(
    const std::array<double, 3> &alpha)
  {
    Assert(floating(), ExcInternalError());
    for (const double a : alpha)
      AssertThrow(std::isfinite(a),
                  ExcMessage("the anchor displacements of subproblem " +
                             name() + " must be finite"));
    if (condensed())
      for (unsigned int k = 0; k < 3; ++k)
        particular.add(alpha[k] - anchor_values[k], anchor_modes[k]);
    anchor_values = alpha;
  }


  std::array<double, 3>
  ElasticSubproblem::anchor_reactions(const std::array<double, 3> &alpha,
                                      const Vector<double>        &b,
                                      const bool sigma_only) const
  {
    Assert(floating() && owned() && !shared, ExcInternalError());
    std::array<double, 3> r = {{0, 0, 0}};
    for (unsigned int k = 0; k < 3; ++k)
      {
        for (unsigned int j = 0; j < 3; ++j)
          r[k] += anchor_stiffness[j][k] * alpha[j];
        if (b.size() == 0)
          continue;
        if (sigma_only)
          for (const auto i : trace_dofs_)
            r[k] -= anchor_modes[k](i) * b(i);
        else
          r[k] -= anchor_modes[k] * b;
      }
    return r;
  }
} // namespace bilayer
