// The anchors of a floating subproblem (no clamped side): three dofs held
// at zero make its stiffness non-singular; their displacements and the
// reactions they carry are what FloatingParts balances.

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/full_matrix.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>
#include <limits>

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

    // The candidates: the vertices whose two dofs no hanging node
    // constrains or masters (the reaction at an anchor is then its row of
    // K w - b alone), off Sigma where there are such.
    const IndexSet on_sigma =
      DoFTools::extract_boundary_dofs(dofs,
                                      ComponentMask(),
                                      BoundaryIds::interfaces());
    std::vector<bool> master(dofs.n_dofs(), false);
    for (const auto &line : homogeneous_constraints.get_lines())
      for (const auto &entry : line.entries)
        master[entry.first] = true;
    const auto unusable = [&](const types::global_dof_index i) {
      return homogeneous_constraints.is_constrained(i) || master[i];
    };
    struct Candidate
    {
      types::global_dof_index x, y;
      Point<2>                point;
    };
    std::vector<Candidate> all, off_sigma;
    std::vector<bool>      seen(dofs.get_triangulation().n_vertices(), false);
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          if (seen[cell->vertex_index(v)])
            continue;
          seen[cell->vertex_index(v)] = true;
          const Candidate c{cell->vertex_dof_index(v, 0),
                            cell->vertex_dof_index(v, 1),
                            cell->vertex(v)};
          if (unusable(c.x) || unusable(c.y))
            continue;
          all.push_back(c);
          if (!on_sigma.is_element(c.x) && !on_sigma.is_element(c.y))
            off_sigma.push_back(c);
        }
    const auto &candidates = off_sigma.size() >= 2 ? off_sigma : all;
    AssertThrow(candidates.size() >= 2,
                ExcMessage("subproblem " + name() +
                           " floats (no clamped side) but has fewer than two "
                           "unconstrained vertices to anchor it"));

    // Anchor A nearest to the centroid of the candidates, B farthest from A.
    Point<2> centre;
    for (const auto &c : candidates)
      centre += c.point;
    centre /= static_cast<double>(candidates.size());
    const auto nearest = [&](const Point<2> &p, const bool farthest) {
      std::size_t best  = 0;
      double      value = farthest ? -1. : std::numeric_limits<double>::max();
      for (std::size_t c = 0; c < candidates.size(); ++c)
        {
          const double d = candidates[c].point.distance(p);
          if (farthest ? d > value : d < value)
            {
              best  = c;
              value = d;
            }
        }
      return candidates[best];
    };
    const Candidate    a = nearest(centre, false);
    const Candidate    b = nearest(a.point, true);
    const Tensor<1, 2> d = b.point - a.point;
    // The component of B that a rotation about A moves most.
    const bool hold_y = std::abs(d[0]) >= std::abs(d[1]);
    anchors_          = {a.x, a.y, hold_y ? b.y : b.x};
    anchor_places     = {
          {{a.point, 0u}, {a.point, 1u}, {b.point, hold_y ? 1u : 0u}}};
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
    // The rigid motions with unit anchor values: interpolated at the
    // support points, E = R R_A^{-1} (R the two translations and the
    // rotation about anchor A, R_A its anchor rows), exact wherever the
    // element space holds the rigid motions (K E = 0 to round-off).
    std::vector<Point<2>> points(n_dofs());
    DoFTools::map_dofs_to_support_points(mapping(), dofs, points);
    const IndexSet x_dofs =
      DoFTools::extract_dofs(dofs,
                             ComponentMask(std::vector<bool>{true, false}));
    const Point<2> a = anchor_places[0].first;
    const auto     rigid =
      [&](const unsigned int t, const Point<2> &p, const unsigned int c) {
        if (t < 2)
          return c == t ? 1. : 0.;
        return c == 0 ? -(p[1] - a[1]) : p[0] - a[0];
      };
    FullMatrix<double> R_A(3, 3);
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int t = 0; t < 3; ++t)
        R_A(k, t) = rigid(t, anchor_places[k].first, anchor_places[k].second);
    FullMatrix<double> inverse(3, 3);
    inverse.invert(R_A);
    for (unsigned int k = 0; k < 3; ++k)
      anchor_modes[k].reinit(n_dofs());
    for (types::global_dof_index i = 0; i < n_dofs(); ++i)
      {
        const unsigned int c = x_dofs.is_element(i) ? 0 : 1;
        for (unsigned int t = 0; t < 3; ++t)
          {
            const double value = rigid(t, points[i], c);
            if (value != 0)
              for (unsigned int k = 0; k < 3; ++k)
                anchor_modes[k](i) += value * inverse(t, k);
          }
      }
    bool exact = true;
    for (unsigned int k = 0; k < 3 && exact; ++k)
      {
        Vector<double> reaction(n_dofs());
        stiffness.vmult(reaction, anchor_modes[k]);
        exact = reaction.linfty_norm() <=
                1e-10 * stiffness.linfty_norm() * anchor_modes[k].linfty_norm();
      }
    // Otherwise (a mapping that does not reproduce the rotation) the
    // discrete-harmonic extensions E_k = e_k - K~^{-1} K e_k.
    if (!exact)
      for (unsigned int k = 0; k < 3; ++k)
        {
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
