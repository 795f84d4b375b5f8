// Example 1 of the paper (partial closure of the crack faces, docs/problem.md
// §5) on 8 + 8 x 4 quadrilaterals: the Uzawa solution of bilayer::Study against
// an independent reference solution of the SAME discrete contact problem by
// a primal-dual active set method.
//
// The reference assembles its own four Q1 plane-strain stiffness matrices on
// its own two subdomain meshes and puts them into one global system. The
// discrete constraints of the lumped coupling are nodal (interface.h): at
// every vertex of Sigma that is not clamped, u- = v- and u+ = v+; at the
// glued vertices (crack tips included) u- = u+; at the crack vertices
// (u+ - u-).y >= 0, with free tangential jump. The equalities and the normal
// contact at the active crack vertices are imposed with AffineConstraints
// (v in favour of u, u+ in favour of u-), the condensed system is solved by
// SparseDirectUMFPACK. The contact force at an active vertex a is read from
// the residual r = K w - F of the constrained solution: with the Lagrangian
// of docs/problem.md §3, the layer-1 multiplier mu_c acts on the upper face as
// the load +D_a mu_c (D_a the lumped weight of the vertex), so that
//   mu_c(a) = (r(u+_y(a)) + r(v+_y(a))) / D_a,
// the gluing multiplier lambda+ cancelling in the sum; mu_c >= 0 is
// compressive. Active set update: an active vertex with mu_c < 0 (tensile)
// is released, an inactive vertex with (u+ - u-).y < 0 is closed, until the
// set stops changing.
//
// The discrete problems are identical, so the comparison only sees the error
// of the Uzawa iteration, stopped at relative multiplier change 1e-10.
//
// The same comparison for the one-layer scene (Materials/Number of layers =
// 1): the reference is then the classical single-body crack problem, one
// elastic body (u- and u+ glued off the crack) with non-penetration on the
// crack, mu_c(a) = r(u+_y(a)) / D_a; bilayer builds only the layer-1
// subproblems and the crack and gluing multipliers.
//
// The lines "energy Pi" and "largest crack opening" that Study prints: for
// two layers the numbers of tests/prm_references.cc (scene partial_closure,
// the same discrete problem; it checks this .output), for one layer those of
// the reference here (printed below; relative differences asserted).

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "reference.h"

using namespace dealii;

namespace
{
  const char *scene_text = R"(
subsection Geometry
  set Crack interval on Sigma = -0.5, 0.5
  set Clamped sides           = left, right
end
subsection Mesh
  set Element shape     = quadrilaterals
  set Cells along Sigma = 8
end
subsection Loads
  set Constants = c = 1e-3*mu1
  subsection Layer 1
    set Traction on bottom side = 0; c*x
    set Traction on top side    = 0; -c*x
  end
end
subsection Solver
  set Stopping rule = relative
  set Tolerance     = 1e-10
end
subsection Output
  set Output directory    = results
  set Write VTU           = false
  set Write interface CSV = false
  set Terminal output     = checks
end
)";

  // The data of Example 1 (tests/reference.h).
  using example1_materials::E;
  using example1_materials::lame_lambda;
  using example1_materials::lame_mu;
  using example1_materials::poisson;
  constexpr double crack_start = -0.5, crack_end = 0.5;
  constexpr double tol = 1e-10;

  /// Vertical traction of layer 1: (0, c x) on the bottom, (0, -c x) on top.
  Tensor<1, 2>
  traction(const unsigned int layer, const unsigned int side, const Point<2> &p)
  {
    const double c = 1e-3 * lame_mu(0);
    Tensor<1, 2> f;
    if (layer == 0 && side == 2)
      f[1] = c * p[0];
    else if (layer == 0 && side == 3)
      f[1] = -c * p[0];
    return f;
  }

  long long
  key_of(const double x)
  {
    return std::llround(x * 1e6);
  }

  /// The (x-dof, y-dof) of every vertex of Sigma (y = 0), by position x.
  std::map<long long, std::array<types::global_dof_index, 2>>
  sigma_dofs(const DoFHandler<2> &dof_handler, const unsigned int offset)
  {
    std::map<long long, std::array<types::global_dof_index, 2>> result;
    const auto                          &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const auto      ci = fe.system_to_component_index(i);
            const Point<2> &p  = cell->vertex(ci.second);
            if (std::abs(p[1]) < tol)
              result[key_of(p[0])][ci.first] = offset + local[i];
          }
      }
    return result;
  }

  /// The reference solver: the subproblems (four, or u- and u+ for one
  /// layer) in one global system.
  class Reference
  {
  public:
    explicit Reference(const unsigned int n_layers);

    /// Solve with the crack vertices in @p active closed; fills w.
    void
    solve(const std::set<long long> &active);

    /// (u+ - u-).y at crack vertex x.
    double
    opening(const long long x) const;

    /// mu_c at crack vertex x from the residual (meaningful where active).
    double
    contact_force(const long long x) const;

    double
    energy() const;

    /// The displacement of subproblem s at the vertex at p.
    std::array<double, 2>
    value(const unsigned int s, const Point<2> &p) const;

    /// The crack vertices (strictly inside the crack), by position.
    std::vector<long long> crack_nodes;
    /// The solution of the last solve() (the four subproblems one after the
    /// other) and its residual K w - F in the unconstrained system.
    Vector<double> w, residual;

  private:
    void
    assemble(const AffineConstraints<double> &constraints,
             SparseMatrix<double>            &system_matrix,
             Vector<double>                  &rhs);

    std::array<Triangulation<2>, 2>               tria;
    FESystem<2>                                   fe;
    MappingQ1<2>                                  mapping;
    const unsigned int                            n_sub;
    std::array<std::unique_ptr<DoFHandler<2>>, 4> dofs;
    std::array<unsigned int, 5>                   offset;
    std::array<std::map<long long, std::array<types::global_dof_index, 2>>, 4>
                                sigma;
    std::map<long long, double> node_weight;
    /// The dofs on the clamped sides (zero displacement).
    std::set<types::global_dof_index> clamped;
    SparsityPattern                   plain_sparsity;
    SparseMatrix<double>              stiffness;
    Vector<double>                    load;
  };


  Reference::Reference(const unsigned int n_layers)
    : fe(FE_Q<2>(1), 2)
    , n_sub(2 * n_layers)
  {
    GridGenerator::subdivided_hyper_rectangle(
      tria[0], {8, 4}, Point<2>(-1, -1), Point<2>(1, 0), true);
    GridGenerator::subdivided_hyper_rectangle(
      tria[1], {8, 4}, Point<2>(-1, 0), Point<2>(1, 1), true);
    // colorize gives Sigma the id of a top (bottom) side: mark it as 4.
    for (auto &t : tria)
      for (const auto &face : t.active_face_iterators())
        if (face->at_boundary() && std::abs(face->center()[1]) < tol)
          face->set_boundary_id(4);

    // s = 2 layer + subdomain: u-, u+, v-, v+.
    offset[0] = 0;
    for (unsigned int s = 0; s < n_sub; ++s)
      {
        dofs[s] = std::make_unique<DoFHandler<2>>(tria[s % 2]);
        dofs[s]->distribute_dofs(fe);
        offset[s + 1] = offset[s] + dofs[s]->n_dofs();
        sigma[s]      = sigma_dofs(*dofs[s], offset[s]);

        std::map<types::global_dof_index, double> boundary_values;
        for (const types::boundary_id side : {0, 1})
          VectorTools::interpolate_boundary_values(mapping,
                                                   *dofs[s],
                                                   side,
                                                   Functions::ZeroFunction<2>(
                                                     2),
                                                   boundary_values);
        for (const auto &entry : boundary_values)
          clamped.insert(offset[s] + entry.first);
      }

    // Sigma vertices; the lumped weight D_a is half the length of the
    // adjacent Sigma edges.
    std::vector<double> xs;
    for (const auto &entry : sigma[0])
      xs.push_back(entry.first * 1e-6);
    for (unsigned int i = 0; i < xs.size(); ++i)
      {
        const double left          = i > 0 ? xs[i] - xs[i - 1] : 0.;
        const double right         = i + 1 < xs.size() ? xs[i + 1] - xs[i] : 0.;
        node_weight[key_of(xs[i])] = 0.5 * (left + right);
        if (xs[i] > crack_start + tol && xs[i] < crack_end - tol)
          crack_nodes.push_back(key_of(xs[i]));
      }

    DynamicSparsityPattern               dsp(offset[n_sub]);
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (unsigned int s = 0; s < n_sub; ++s)
      for (const auto &cell : dofs[s]->active_cell_iterators())
        {
          cell->get_dof_indices(local);
          for (auto &i : local)
            i += offset[s];
          for (const auto i : local)
            for (const auto j : local)
              dsp.add(i, j);
        }
    plain_sparsity.copy_from(dsp);
    stiffness.reinit(plain_sparsity);
    load.reinit(offset[n_sub]);
    AffineConstraints<double> none;
    none.close();
    assemble(none, stiffness, load);
  }


  void
  Reference::assemble(const AffineConstraints<double> &constraints,
                      SparseMatrix<double>            &system_matrix,
                      Vector<double>                  &rhs)
  {
    const QGauss<2>                      quadrature(2);
    const QGauss<1>                      face_quadrature(2);
    FEValues<2>                          fe_values(mapping,
                          fe,
                          quadrature,
                          update_gradients | update_JxW_values);
    FEFaceValues<2>                      fe_face_values(mapping,
                                   fe,
                                   face_quadrature,
                                   update_values | update_quadrature_points |
                                     update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> local(n);
    const FEValuesExtractors::Vector     displacement(0);

    for (unsigned int s = 0; s < n_sub; ++s)
      {
        const unsigned int layer  = s / 2;
        const double       mu     = lame_mu(layer);
        const double       lambda = lame_lambda(layer);
        for (const auto &cell : dofs[s]->active_cell_iterators())
          {
            cell_matrix = 0;
            cell_rhs    = 0;
            fe_values.reinit(cell);
            add_elasticity_matrix(
              fe_values, displacement, mu, lambda, cell_matrix);
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  (cell->face(f)->boundary_id() == 2 ||
                   cell->face(f)->boundary_id() == 3))
                {
                  fe_face_values.reinit(cell, f);
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    {
                      const Tensor<1, 2> f_q =
                        traction(layer,
                                 cell->face(f)->boundary_id(),
                                 fe_face_values.quadrature_point(q));
                      for (unsigned int i = 0; i < n; ++i)
                        cell_rhs(i) +=
                          fe_face_values[displacement].value(i, q) * f_q *
                          fe_face_values.JxW(q);
                    }
                }
            cell->get_dof_indices(local);
            for (auto &i : local)
              i += offset[s];
            if (constraints.n_constraints() == 0)
              {
                system_matrix.add(local, cell_matrix);
                rhs.add(local, cell_rhs);
              }
            else
              constraints.distribute_local_to_global(
                cell_matrix, cell_rhs, local, system_matrix, rhs);
          }
      }
  }


  void
  Reference::solve(const std::set<long long> &active)
  {
    AffineConstraints<double> constraints;
    for (const auto dof : clamped)
      constraints.add_line(dof);
    const auto tie = [&](const types::global_dof_index slave,
                         const types::global_dof_index master) {
      if (!constraints.is_constrained(slave))
        {
          constraints.add_line(slave);
          constraints.add_entry(slave, master, 1.0);
        }
    };
    for (const auto &[x, u_minus] : sigma[0])
      {
        if (clamped.count(u_minus[0]) > 0)
          continue; // a clamped end of Sigma: no multipliers there
        const auto &u_plus = sigma[1].at(x);
        const bool  crack =
          std::find(crack_nodes.begin(), crack_nodes.end(), x) !=
          crack_nodes.end();
        for (unsigned int c = 0; c < 2; ++c)
          {
            if (n_sub == 4)
              {
                tie(sigma[2].at(x)[c], u_minus[c]);
                tie(sigma[3].at(x)[c], u_plus[c]);
              }
            if (!crack || (c == 1 && active.count(x) > 0))
              tie(u_plus[c], u_minus[c]);
          }
      }
    constraints.close();

    DynamicSparsityPattern               dsp(offset[n_sub]);
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (unsigned int s = 0; s < n_sub; ++s)
      for (const auto &cell : dofs[s]->active_cell_iterators())
        {
          cell->get_dof_indices(local);
          for (auto &i : local)
            i += offset[s];
          constraints.add_entries_local_to_global(local, dsp, false);
        }
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> system_matrix(sparsity);
    Vector<double>       rhs(offset[n_sub]);
    assemble(constraints, system_matrix, rhs);

    SparseDirectUMFPACK direct;
    direct.initialize(system_matrix);
    w = rhs;
    direct.solve(w);
    constraints.distribute(w);

    residual.reinit(offset[n_sub]);
    stiffness.vmult(residual, w);
    residual -= load;
  }


  double
  Reference::opening(const long long x) const
  {
    return w(sigma[1].at(x)[1]) - w(sigma[0].at(x)[1]);
  }


  double
  Reference::contact_force(const long long x) const
  {
    return (residual(sigma[1].at(x)[1]) +
            (n_sub == 4 ? residual(sigma[3].at(x)[1]) : 0.)) /
           node_weight.at(x);
  }


  double
  Reference::energy() const
  {
    return 0.5 * stiffness.matrix_norm_square(w) - load * w;
  }


  std::array<double, 2>
  Reference::value(const unsigned int s, const Point<2> &p) const
  {
    std::array<double, 2>                result = {{0., 0.}};
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &cell : dofs[s]->active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).distance(p) < tol)
          {
            cell->get_dof_indices(local);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              if (fe.system_to_component_index(i).second == v)
                result[fe.system_to_component_index(i).first] =
                  w(offset[s] + local[i]);
            return result;
          }
    AssertThrow(false, ExcMessage("vertex not found"));
    return result;
  }
} // namespace


void
compare(const unsigned int n_layers)
{
  std::cout << (n_layers == 2 ? "two layers:" : "one layer (layer 2 absent):")
            << std::endl;
  const bilayer::Scene scene = bilayer::scene_from_string(
    std::string(scene_text) + "subsection Materials\n set Number of layers = " +
      std::to_string(n_layers) + "\nend\n",
    "reference");

  bilayer::Study              study(scene, std::cout);
  const bilayer::CycleRecord &record = study.run_cycle(0);

  // The reference: primal-dual active set, starting with the crack closed.
  Reference           reference(n_layers);
  std::set<long long> active(reference.crack_nodes.begin(),
                             reference.crack_nodes.end());
  unsigned int        iterations = 0;
  bool                settled    = false;
  while (!settled && iterations < 20)
    {
      reference.solve(active);
      ++iterations;
      const double scale       = reference.w.linfty_norm();
      double       force_scale = 0;
      for (const long long x : active)
        force_scale =
          std::max(force_scale, std::abs(reference.contact_force(x)));
      std::set<long long> next;
      for (const long long x : reference.crack_nodes)
        if (active.count(x) > 0 ?
              reference.contact_force(x) >= -1e-12 * force_scale :
              reference.opening(x) < -1e-12 * scale)
          next.insert(x);
      settled = (next == active);
      active  = next;
    }

  // The Uzawa result at the crack vertices of the interface.
  const auto &interface = study.interface();
  const auto &w         = study.solutions();
  const auto  uzawa_minus =
    sigma_dofs(study
                 .subproblem(bilayer::Layer::first, bilayer::Subdomain::minus)
                 .dof_handler(),
               0);
  const auto uzawa_plus =
    sigma_dofs(study.subproblem(bilayer::Layer::first, bilayer::Subdomain::plus)
                 .dof_handler(),
               0);
  std::set<long long>    uzawa_active;
  std::vector<long long> uzawa_crack;
  double                 max_opening = 0, opening_difference = 0, max_force = 0,
         force_difference = 0;
  bool      left_open = true, right_end_closed = false;
  long long right_end = reference.crack_nodes.back();
  for (unsigned int a = 0; a < interface.space().n_nodes(); ++a)
    if (interface.space().on_crack(a))
      {
        const long long x = key_of(interface.space().node_position(a));
        uzawa_crack.push_back(x);
        const double opening =
          w[1](uzawa_plus.at(x)[1]) - w[0](uzawa_minus.at(x)[1]);
        const double mu_c =
          interface.space().contact_multiplier(study.multipliers(), a);
        if (mu_c > 0)
          uzawa_active.insert(x);
        const double ref_opening = reference.opening(x);
        const double ref_force =
          active.count(x) > 0 ? reference.contact_force(x) : 0.;
        max_opening = std::max(max_opening, std::abs(ref_opening));
        opening_difference =
          std::max(opening_difference, std::abs(opening - ref_opening));
        max_force = std::max(max_force, std::abs(ref_force));
        force_difference =
          std::max(force_difference, std::abs(mu_c - ref_force));
        if (x < 0 && !(ref_opening > 0 && opening > 0))
          left_open = false;
        if (x == right_end)
          right_end_closed = active.count(x) > 0 && mu_c > 0;
      }

  // All vertex values of the four subproblems.
  double max_difference = 0, max_displacement = 0;
  for (unsigned int s = 0; s < 2 * n_layers; ++s)
    {
      const auto                          &sub = study.subproblem(s);
      const auto                          &fe  = sub.fe();
      std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          cell->get_dof_indices(local);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const auto   ci = fe.system_to_component_index(i);
              const double ref =
                reference.value(s, cell->vertex(ci.second))[ci.first];
              max_difference =
                std::max(max_difference, std::abs(w[s](local[i]) - ref));
              max_displacement = std::max(max_displacement, std::abs(ref));
            }
        }
    }

  const double energy_difference =
    std::abs(record.energy - reference.energy()) / std::abs(reference.energy());

  if (n_layers == 1)
    std::cout
      << "only the layer-1 subproblems and the crack and gluing multipliers "
         "are built: "
      << (record.dofs ==
                study
                    .subproblem(bilayer::Layer::first,
                                bilayer::Subdomain::minus)
                    .n_dofs() +
                  study
                    .subproblem(bilayer::Layer::first, bilayer::Subdomain::plus)
                    .n_dofs() &&
              study.multipliers().block(bilayer::Layout::glue_minus).size() ==
                0 &&
              study.multipliers().block(bilayer::Layout::glue_plus).size() ==
                0 ?
            "yes" :
            "NO")
      << std::endl;
  std::cout << "Uzawa solver converged: "
            << (record.result.converged ? "yes" : "NO") << std::endl;
  std::cout << "reference active set settled after " << iterations
            << " solves: " << (settled ? "yes" : "NO") << std::endl;
  std::cout << "same crack vertices: "
            << (uzawa_crack == reference.crack_nodes ? "yes" : "NO")
            << std::endl;
  std::cout << "closed crack vertices x =";
  for (const long long x : active)
    std::cout << ' ' << x * 1e-6;
  std::cout << std::endl;
  // Scaled so that numdiff's relative tolerance applies to them.
  std::cout << std::setprecision(6)
            << "energy of the reference solution [1e-6]: "
            << reference.energy() * 1e6 << std::endl
            << "largest crack opening [1e-6]: " << max_opening * 1e6
            << std::endl;
  std::cout << "active sets agree: " << (uzawa_active == active ? "yes" : "NO")
            << std::endl;
  std::cout << "crack opening max difference / max opening < 1e-6: "
            << (opening_difference < 1e-6 * max_opening ? "yes" : "NO")
            << std::endl;
  std::cout << "contact force max difference / max force < 1e-6: "
            << (force_difference < 1e-6 * max_force ? "yes" : "NO")
            << std::endl;
  std::cout << "max nodal difference / max displacement < 1e-7: "
            << (max_difference < 1e-7 * max_displacement ? "yes" : "NO")
            << std::endl;
  std::cout << "energy relative difference < 1e-8: "
            << (energy_difference < 1e-8 ? "yes" : "NO") << std::endl;
  std::cout << "left half of the crack open: " << (left_open ? "yes" : "NO")
            << std::endl;
  std::cout << "right end of the crack closed: "
            << (right_end_closed ? "yes" : "NO") << std::endl;

  // The measured numbers, for whoever adjusts this test (not part of the
  // expected output: they depend on the floating-point details).
  if (std::getenv("BILAYER_TEST_DIAGNOSTICS") != nullptr)
    {
      std::cerr << std::setprecision(6) << "iterations "
                << record.result.iterations << ", energy difference "
                << energy_difference << ", opening difference / max "
                << opening_difference / max_opening
                << ", force difference / max " << force_difference / max_force
                << ", nodal difference / max "
                << max_difference / max_displacement << std::endl;
      for (unsigned int a = 0; a < interface.space().n_nodes(); ++a)
        if (interface.space().on_crack(a))
          {
            const long long x = key_of(interface.space().node_position(a));
            std::cerr
              << "  x " << x * 1e-6 << " opening ref " << reference.opening(x)
              << " uzawa "
              << w[1](uzawa_plus.at(x)[1]) - w[0](uzawa_minus.at(x)[1])
              << "  mu_c ref "
              << (active.count(x) ? reference.contact_force(x) : 0.)
              << " uzawa "
              << interface.space().contact_multiplier(study.multipliers(), a)
              << std::endl;
          }
    }
}


int
main()
{
  compare(2);
  compare(1);
}
