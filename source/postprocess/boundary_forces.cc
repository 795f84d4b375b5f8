// The forces on the boundary parts: the consistent reactions of the clamps
// from the residual, the resultants of the tractions, the mean
// displacements, and their balance.

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <bilayer/postprocess/boundary_forces.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The sum of @p list; NaN where it is empty (not computed).
    Tensor<1, 2>
    sum(const std::vector<Tensor<1, 2>> &list)
    {
      Tensor<1, 2> total;
      if (list.empty())
        total[0] = total[1] = std::numeric_limits<double>::quiet_NaN();
      for (const Tensor<1, 2> &v : list)
        total += v;
      return total;
    }
  } // namespace


  Tensor<1, 2>
  PartForce::force() const
  {
    return sum(layer_force);
  }


  Tensor<1, 2>
  PartForce::mean_displacement() const
  {
    return sum(layer_mean_displacement) /
           std::max<double>(layer_mean_displacement.size(), 1);
  }


  namespace
  {
    /// Whether layer slot @p l has a subproblem.
    bool
    layer_present(const PerSubproblem<const ElasticSubproblem *> &subproblems,
                  const unsigned int                              l)
    {
      for (const ElasticSubproblem *sub : subproblems)
        if (sub != nullptr && static_cast<unsigned int>(sub->layer()) == l)
          return true;
      return false;
    }

    /// Per part: force (2), int w ds (2), length; then the applied load's
    /// resultant (2) and the reactions' (2), the scale of the round-off of
    /// the sums, sum_i (sum_j |K_ij| |w_j| + |F_i| + |c_i|), and the
    /// resultant of the reactions at a floating subproblem's anchors (2).
    constexpr unsigned int per_part = 5;
    constexpr unsigned int totals   = 7;

    /// The residual r = K w - F - c of @p sub with the residuals of the
    /// hanging nodes moved to their masters.
    Vector<double>
    residual(const ElasticSubproblem &sub,
             const Vector<double>    &w,
             const Vector<double>    &coupling)
    {
      Vector<double> r(sub.n_dofs());
      sub.multiply_stiffness(r, w);
      r -= sub.load();
      if (coupling.size() == r.size())
        r -= coupling;
      // The hanging nodes alone: in the constraints of the solves an entry
      // on a clamped master is folded into the inhomogeneity, and the
      // weights of a line would no longer sum to one.
      AffineConstraints<double> hanging;
      DoFTools::make_hanging_node_constraints(sub.dof_handler(), hanging);
      hanging.close();
      for (const auto &line : hanging.get_lines())
        {
          for (const auto &[master, weight] : line.entries)
            r(master) += weight * r(line.index);
          r(line.index) = 0;
        }
      return r;
    }


    /// The values of one subproblem (owners only; not shared by a group).
    Vector<double>
    subproblem_values(const ElasticSubproblem                &sub,
                      const Vector<double>                   &w,
                      const Vector<double>                   &coupling,
                      const std::vector<bool>                &clamped,
                      const std::vector<const Function<2> *> &traction)
    {
      const unsigned int               n_parts = clamped.size();
      Vector<double>                   values(n_parts * per_part + totals);
      const auto                      &dofs = sub.dof_handler();
      const auto                      &fe   = sub.fe();
      const Vector<double>             r    = residual(sub, w, coupling);
      const AffineConstraints<double> &constraints =
        sub.zero_displacement_constraints();

      // The component of every dof, and the resultants of the load and of
      // the reactions.
      const IndexSet x_dofs = DoFTools::extract_dofs(
        dofs, fe.component_mask(FEValuesExtractors::Scalar(0)));
      const auto component = [&](const types::global_dof_index i) {
        return x_dofs.is_element(i) ? 0u : 1u;
      };
      const Vector<double> &load     = sub.load();
      double                roundoff = load.l1_norm();
      if (coupling.size() == load.size())
        roundoff += coupling.l1_norm();
      for (const auto &entry : sub.stiffness_matrix())
        roundoff += std::abs(entry.value() * w(entry.column()));
      values(n_parts * per_part + 4) = roundoff;
      for (types::global_dof_index i = 0; i < load.size(); ++i)
        values(n_parts * per_part + component(i)) += load(i);

      // The reactions: the clamped dofs of each clamped part (a dof on two
      // counts to the first).
      std::vector<bool> taken(dofs.n_dofs(), false);
      for (unsigned int p = 0; p < n_parts; ++p)
        if (clamped[p])
          {
            const IndexSet on_part = DoFTools::extract_boundary_dofs(
              dofs, ComponentMask(), {static_cast<types::boundary_id>(p)});
            for (const types::global_dof_index i : on_part)
              if (!taken[i] && constraints.is_constrained(i))
                {
                  taken[i] = true;
                  values(p * per_part + component(i)) += r(i);
                  values(n_parts * per_part + 2 + component(i)) += r(i);
                }
          }

      // A floating subproblem's anchors: what they carry is a reaction
      // too (zero where the floating parts are balanced).
      if (sub.floating())
        for (const types::global_dof_index i : sub.anchors())
          {
            values(n_parts * per_part + 2 + component(i)) += r(i);
            values(n_parts * per_part + 5 + component(i)) += r(i);
          }

      // The tractions' resultants, int w ds and the lengths.
      const Quadrature<1> quadrature =
        ReferenceCells::Line.get_gauss_type_quadrature<1>(fe.degree + 1);
      FEFaceValues<2>                  face_values(sub.mapping(),
                                  fe,
                                  quadrature,
                                  update_values | update_quadrature_points |
                                    update_JxW_values);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<1, 2>>        w_q(quadrature.size());
      Vector<double>                   t(2);
      for (const auto &cell : dofs.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() < n_parts)
            {
              const unsigned int p = face->boundary_id();
              face_values.reinit(cell, face);
              face_values[displacement].get_function_values(w, w_q);
              for (const unsigned int q :
                   face_values.quadrature_point_indices())
                {
                  const double dx = face_values.JxW(q);
                  values(p * per_part + 2) += w_q[q][0] * dx;
                  values(p * per_part + 3) += w_q[q][1] * dx;
                  values(p * per_part + 4) += dx;
                  if (!clamped[p] && p < traction.size() &&
                      traction[p] != nullptr)
                    {
                      traction[p]->vector_value(face_values.quadrature_point(q),
                                                t);
                      values(p * per_part + 0) += sub.load_factor() * t(0) * dx;
                      values(p * per_part + 1) += sub.load_factor() * t(1) * dx;
                    }
                }
            }
      return values;
    }
  } // namespace


  ForceBalance
  boundary_forces(const PerSubproblem<const ElasticSubproblem *> &subproblems,
                  const Interface                                &interface,
                  const Solutions                                &w,
                  const BlockVector<double>                      &mu,
                  const std::vector<std::string>                 &names,
                  const std::vector<bool>                        &clamped,
                  const std::vector<std::vector<const Function<2> *>> &traction,
                  const unsigned int                                   n_slots)
  {
    const unsigned int n_parts  = names.size();
    const unsigned int n_values = n_parts * per_part + totals;
    ForceBalance       balance;
    balance.parts.resize(n_parts);
    std::vector<bool> clamped_parts(n_parts, false);
    for (unsigned int p = 0; p < n_parts; ++p)
      {
        balance.parts[p].name    = names[p];
        balance.parts[p].clamped = clamped_parts[p] =
          p < clamped.size() && clamped[p];
      }

    Solutions loads;
    interface.apply(mu, loads);
    // The values of every subproblem, known to every process.
    PerSubproblem<Vector<double>> values(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      {
        const ElasticSubproblem *sub = subproblems[s];
        if (sub == nullptr)
          continue;
        if (sub->processes().group_size(s) > 1)
          return balance;
        const unsigned int l = static_cast<unsigned int>(sub->layer());
        values[s].reinit(n_values);
        if (sub->owned())
          values[s] =
            subproblem_values(*sub,
                              w[s],
                              s < loads.size() ? loads[s] : Vector<double>(),
                              clamped_parts,
                              l < traction.size() ?
                                traction[l] :
                                std::vector<const Function<2> *>());
        sub->processes().share(s, values[s], nullptr);
      }

    // Per part: by layer (summed over the regions) and by region (summed
    // over the layers; displacements averaged).
    double force_scale = 0, roundoff = 0;
    for (unsigned int p = 0; p < n_parts; ++p)
      {
        PartForce &part = balance.parts[p];
        part.layer_force.assign(n_slots, Tensor<1, 2>());
        part.layer_mean_displacement.assign(n_slots, Tensor<1, 2>());
        std::vector<double> layer_length(n_slots, 0.);
        std::map<unsigned int, PartForce::RegionShare> regions;
        std::map<unsigned int, unsigned int>           layers_in_region;
        for (const unsigned int s : Layout::indices(subproblems.size()))
          if (subproblems[s] != nullptr)
            {
              const Vector<double> &v = values[s];
              const unsigned int    l =
                static_cast<unsigned int>(subproblems[s]->layer());
              const unsigned int r      = subproblems[s]->region();
              const double       length = v(p * per_part + 4);
              if (!(length > 0))
                continue;
              const Tensor<1, 2> force({v(p * per_part), v(p * per_part + 1)});
              const Tensor<1, 2> integral(
                {v(p * per_part + 2), v(p * per_part + 3)});
              part.layer_force[l] += force;
              part.layer_mean_displacement[l] += integral;
              layer_length[l] += length;
              PartForce::RegionShare &share = regions[r];
              share.region                  = r;
              share.length                  = length;
              share.force += force;
              share.mean_displacement += integral / length;
              ++layers_in_region[r];
              force_scale += force.norm();
            }
        for (unsigned int l = 0; l < n_slots; ++l)
          if (layer_length[l] > 0)
            {
              part.layer_mean_displacement[l] /= layer_length[l];
              part.length = layer_length[l];
            }
        for (auto &[r, share] : regions)
          {
            share.mean_displacement /= layers_in_region[r];
            part.regions.push_back(share);
          }
      }
    // (Absent layers: no entries.)
    for (PartForce &part : balance.parts)
      {
        std::vector<Tensor<1, 2>> forces, displacements;
        for (unsigned int l = 0; l < n_slots; ++l)
          if (layer_present(subproblems, l))
            {
              forces.push_back(part.layer_force[l]);
              displacements.push_back(part.layer_mean_displacement[l]);
            }
        part.layer_force             = forces;
        part.layer_mean_displacement = displacements;
      }
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          const Vector<double> &v = values[s];
          balance.applied +=
            Tensor<1, 2>({v(n_parts * per_part), v(n_parts * per_part + 1)});
          balance.reactions += Tensor<1, 2>(
            {v(n_parts * per_part + 2), v(n_parts * per_part + 3)});
          roundoff += v(n_parts * per_part + 4);
          balance.anchors += Tensor<1, 2>(
            {v(n_parts * per_part + 5), v(n_parts * per_part + 6)});
        }
    force_scale += balance.applied.norm();
    balance.residual    = (balance.applied + balance.reactions).norm();
    balance.roundoff    = std::numeric_limits<double>::epsilon() * roundoff;
    balance.force_scale = force_scale;
    return balance;
  }
} // namespace bilayer
