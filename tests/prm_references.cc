// The reference numbers of the seven parameter-file tests (tests/*.prm)
// and of the other tests whose Study prints them (contact_properties,
// contact_reference, refinement): for each scene, the energy Pi and the
// largest normal opening of the crack (with its position) of the exact
// solution of the scene's discrete problem, computed here by an independent
// monolithic solver, printed in the format of the lines that bilayer prints
// after its acceptance checks (Study::print_report):
//
//   cycle N: energy Pi [10^k]: m                  (Pi = m 10^k, 1 <= |m| < 10)
//   cycle N: largest crack opening [10^k]: m at x = x_max
//
// m has 8 significant digits, so numdiff's absolute tolerance 1e-6 (it
// compares a test's output with its .output file; run_test.sh: -a 1e-6
// -r 1e-8, a number passes if either holds) is a relative tolerance of
// 1e-7 to 1e-6. The .output files of those tests hold these numbers; this
// test checks that they do (a changed .output file, or a changed reference,
// fails here), and those tests check the program against them.
//
// The reference solver, generalising tests/contact_reference.cc: its own
// meshes (deal.II's GridGenerator, n x n/2 cells per subdomain, n = 8 2^cycle
// cells along Sigma), its own FESystem of Q1, Q2 or P1 elements and its own
// plane-strain stiffness (reference.h) for the four subproblems u-, u+, v-,
// v+ in one global system, clamped at x = -1 and x = 1 (the dofs whose
// support point lies there), the tractions of layer 1 on the bottom and
// top, E and nu of docs/problem.md §5 written out here. The interface
// constraints are rows of a matrix B, imposed with Lagrange multipliers in the
// saddle point system [K B_A^T; B_A 0] (SparseDirectUMFPACK):
//  - lumped coupling (nodal constraints, interface.h): at every node a of
//    Sigma that is not clamped, u-(a) = v-(a) and u+(a) = v+(a); off the
//    crack (crack tips included) u-(a) = u+(a); at the nodes strictly inside
//    the crack (u- - u+)_y(a) <= 0 with free tangential jump;
//  - consistent (mortar) coupling: the same rows integrated against the
//    Lagrange basis phi_a of the trace: int phi_a (u- - u+) ds = 0 (or
//    int phi_a (u- - u+)_y ds <= 0 on the crack), Gauss quadrature on the
//    Sigma faces;
//  - without non-penetration the crack nodes carry no row.
// The contact rows are found by a primal-dual active set iteration (start:
// all closed; release a row whose multiplier is tensile (< 0), close a row
// that penetrates), until the set stops changing.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "reference.h"

using namespace dealii;

namespace
{
  /// One scene: a parameter-file test (see its .prm) or a scene of
  /// another test whose Study prints these lines.
  struct SceneSpec
  {
    std::string  name;
    bool         triangles;
    unsigned int degree;
    bool         consistent;
    bool         contact;
    bool         full_opening; // the load of Example 2, else Example 1
    double       load_factor;  // c = load_factor 1e-3 mu1
    unsigned int cycles;
    /// The tests whose .output must hold the lines.
    std::vector<std::string> tests;
  };

  const std::vector<SceneSpec> scenes = {
    {"partial_closure",
     false,
     1,
     false,
     true,
     false,
     1.,
     1,
     {"partial_closure", "contact_properties", "contact_reference"}},
    {"partial_closure_active_set",
     false,
     2,
     true,
     true,
     false,
     1.,
     2,
     {"partial_closure_active_set"}},
    {"partial_closure_consistent",
     false,
     1,
     true,
     true,
     false,
     1.,
     1,
     {"partial_closure_consistent"}},
    {"partial_closure_linear",
     false,
     1,
     false,
     false,
     false,
     1.,
     1,
     {"partial_closure_linear", "contact_properties"}},
    {"partial_closure_q2",
     false,
     2,
     false,
     true,
     false,
     1.,
     1,
     {"partial_closure_q2"}},
    {"partial_closure_triangles",
     true,
     1,
     false,
     true,
     false,
     1.,
     1,
     {"partial_closure_triangles"}},
    {"full_opening",
     false,
     1,
     false,
     true,
     true,
     1.,
     1,
     {"full_opening", "contact_properties"}},
    // contact_properties.cc: Example 1 with the load doubled.
    {"doubled load",
     false,
     1,
     false,
     true,
     false,
     2.,
     1,
     {"contact_properties"}},
    // refinement.cc: Example 1, three cycles, Q1 and P1.
    {"refinement, quadrilaterals",
     false,
     1,
     false,
     true,
     false,
     1.,
     3,
     {"refinement"}},
    {"refinement, triangles",
     true,
     1,
     false,
     true,
     false,
     1.,
     3,
     {"refinement"}}};

  using example1_materials::E;
  using example1_materials::lame_lambda;
  using example1_materials::lame_mu;
  using example1_materials::poisson;
  constexpr double crack[2] = {-0.5, 0.5};
  constexpr double tol      = 1e-10;

  long long
  key_of(const double x)
  {
    return std::llround(x * 1e6);
  }

  /// A constraint row: sum_j coefficient_j w_j (= 0, or <= 0 for contact).
  struct Row
  {
    std::map<types::global_dof_index, double> entries;
    bool                                      contact = false;
    long long                                 node    = 0;
  };

  struct Result
  {
    double    energy = 0, max_opening = 0;
    long long max_position = 0;
    bool      settled      = false;
    bool      kkt          = false;
  };


  class Reference
  {
  public:
    Reference(const SceneSpec &spec, const unsigned int cycle);
    Result
    solve();

  private:
    Tensor<1, 2>
    traction(const unsigned int layer, const Point<2> &p) const;
    void
    assemble();
    void
    build_rows();
    void
    add_pair_rows(const unsigned int first,
                  const unsigned int second,
                  const bool         layer1_across);

    const SceneSpec                               spec;
    std::array<Triangulation<2>, 2>               tria;
    std::unique_ptr<FESystem<2>>                  fe;
    std::unique_ptr<Mapping<2>>                   mapping;
    std::unique_ptr<Quadrature<2>>                quadrature;
    std::unique_ptr<Quadrature<1>>                face_quadrature;
    std::array<std::unique_ptr<DoFHandler<2>>, 4> dofs;
    std::array<types::global_dof_index, 5>        offset;
    /// Support point and component of every global dof.
    std::vector<Point<2>>     support;
    std::vector<unsigned int> component;
    /// Per subproblem: Sigma node -> its (x, y) dofs (global numbers).
    std::array<std::map<long long, std::array<types::global_dof_index, 2>>, 4>
                              sigma;
    AffineConstraints<double> clamped;
    SparsityPattern           pattern;
    SparseMatrix<double>      stiffness;
    Vector<double>            load;
    std::vector<Row>          rows;
  };


  Reference::Reference(const SceneSpec &spec, const unsigned int cycle)
    : spec(spec)
  {
    const unsigned int n = 8u << cycle;
    for (unsigned int d = 0; d < 2; ++d)
      {
        const Point<2> p1(-1, d == 0 ? -1 : 0), p2(1, d == 0 ? 0 : 1);
        if (spec.triangles)
          GridGenerator::subdivided_hyper_rectangle_with_simplices(tria[d],
                                                                   {n, n / 2},
                                                                   p1,
                                                                   p2);
        else
          GridGenerator::subdivided_hyper_rectangle(tria[d],
                                                    {n, n / 2},
                                                    p1,
                                                    p2);
      }
    if (spec.triangles)
      {
        fe      = std::make_unique<FESystem<2>>(FE_SimplexP<2>(spec.degree), 2);
        mapping = std::make_unique<MappingFE<2>>(FE_SimplexP<2>(1));
        quadrature = std::make_unique<QGaussSimplex<2>>(spec.degree + 1);
      }
    else
      {
        fe         = std::make_unique<FESystem<2>>(FE_Q<2>(spec.degree), 2);
        mapping    = std::make_unique<MappingQ1<2>>();
        quadrature = std::make_unique<QGauss<2>>(spec.degree + 1);
      }
    face_quadrature = std::make_unique<QGauss<1>>(spec.degree + 1);

    // s = 2 layer + subdomain: u-, u+, v-, v+.
    offset[0] = 0;
    for (unsigned int s = 0; s < 4; ++s)
      {
        dofs[s] = std::make_unique<DoFHandler<2>>(tria[s % 2]);
        dofs[s]->distribute_dofs(*fe);
        offset[s + 1] = offset[s] + dofs[s]->n_dofs();
      }
    support.resize(offset[4]);
    component.resize(offset[4]);
    std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
    for (unsigned int s = 0; s < 4; ++s)
      {
        std::vector<Point<2>> points(dofs[s]->n_dofs());
        DoFTools::map_dofs_to_support_points(*mapping, *dofs[s], points);
        for (const auto &cell : dofs[s]->active_cell_iterators())
          {
            cell->get_dof_indices(local);
            for (unsigned int i = 0; i < local.size(); ++i)
              {
                const auto g = offset[s] + local[i];
                support[g]   = points[local[i]];
                component[g] = fe->system_to_component_index(i).first;
              }
          }
      }
    for (unsigned int s = 0; s < 4; ++s)
      for (auto g = offset[s]; g < offset[s + 1]; ++g)
        {
          if (std::abs(std::abs(support[g][0]) - 1.) < tol)
            clamped.add_line(g);
          else if (std::abs(support[g][1]) < tol)
            sigma[s][key_of(support[g][0])][component[g]] = g;
        }
    clamped.close();
    assemble();
    build_rows();
  }


  Tensor<1, 2>
  Reference::traction(const unsigned int layer, const Point<2> &p) const
  {
    // Example 1: (0, c x) on the bottom, (0, -c x) on the top of layer 1;
    // Example 2: (0, -c) on the bottom, (0, c) on the top. c = 1e-3 mu1.
    const double c = spec.load_factor * 1e-3 * lame_mu(0);
    Tensor<1, 2> f;
    if (layer == 0)
      {
        const double side = p[1] < 0 ? 1. : -1.; // bottom: +, top: -
        f[1]              = spec.full_opening ? -side * c : side * c * p[0];
      }
    return f;
  }


  void
  Reference::assemble()
  {
    DynamicSparsityPattern               dsp(offset[4]);
    std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
    for (unsigned int s = 0; s < 4; ++s)
      for (const auto &cell : dofs[s]->active_cell_iterators())
        {
          cell->get_dof_indices(local);
          for (auto &i : local)
            i += offset[s];
          clamped.add_entries_local_to_global(local, dsp, false);
        }
    pattern.copy_from(dsp);
    stiffness.reinit(pattern);
    load.reinit(offset[4]);

    FEValues<2>                      fe_values(*mapping,
                          *fe,
                          *quadrature,
                          update_gradients | update_JxW_values);
    FEFaceValues<2>                  fe_face_values(*mapping,
                                   *fe,
                                   *face_quadrature,
                                   update_values | update_quadrature_points |
                                     update_JxW_values);
    const unsigned int               n = fe->n_dofs_per_cell();
    FullMatrix<double>               cell_matrix(n, n);
    Vector<double>                   cell_rhs(n);
    const FEValuesExtractors::Vector displacement(0);
    for (unsigned int s = 0; s < 4; ++s)
      for (const auto &cell : dofs[s]->active_cell_iterators())
        {
          cell_matrix = 0;
          cell_rhs    = 0;
          fe_values.reinit(cell);
          add_elasticity_matrix(fe_values,
                                displacement,
                                lame_mu(s / 2),
                                lame_lambda(s / 2),
                                cell_matrix);
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                std::abs(std::abs(cell->face(f)->center()[1]) - 1.) < tol)
              {
                fe_face_values.reinit(cell, f);
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  {
                    const Tensor<1, 2> t =
                      traction(s / 2, fe_face_values.quadrature_point(q));
                    for (unsigned int i = 0; i < n; ++i)
                      cell_rhs(i) += fe_face_values[displacement].value(i, q) *
                                     t * fe_face_values.JxW(q);
                  }
              }
          cell->get_dof_indices(local);
          for (auto &i : local)
            i += offset[s];
          clamped.distribute_local_to_global(
            cell_matrix, cell_rhs, local, stiffness, load);
        }
  }


  void
  Reference::add_pair_rows(const unsigned int first,
                           const unsigned int second,
                           const bool         layer1_across)
  {
    // Which rows: component c at node x; contact rows only across Sigma.
    const auto on_crack = [](const long long x) {
      return x > key_of(crack[0]) && x < key_of(crack[1]);
    };
    std::map<std::pair<long long, unsigned int>, Row> pair_rows;
    for (const auto &entry : sigma[first])
      {
        const long long x = entry.first;
        for (unsigned int c = 0; c < 2; ++c)
          {
            const bool crack_node = layer1_across && on_crack(x);
            if (crack_node && (!spec.contact || c == 0))
              continue; // no row: free jump
            Row row;
            row.contact       = crack_node;
            row.node          = x;
            pair_rows[{x, c}] = row;
          }
      }

    if (!spec.consistent)
      for (auto &[where, row] : pair_rows)
        {
          row.entries[sigma[first].at(where.first)[where.second]]  = 1.;
          row.entries[sigma[second].at(where.first)[where.second]] = -1.;
        }
    else
      // int phi_a (w_first - w_second)_c ds: phi_a is the trace of the
      // shape function of node a (the traces of all four subproblems lie in
      // the same space of piecewise polynomials on the Sigma faces).
      for (const unsigned int s : {first, second})
        {
          const double                         sign = s == first ? 1. : -1.;
          FEFaceValues<2>                      fe_face_values(*mapping,
                                         *fe,
                                         *face_quadrature,
                                         update_values | update_JxW_values);
          std::vector<types::global_dof_index> local(fe->n_dofs_per_cell());
          for (const auto &cell : dofs[s]->active_cell_iterators())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  std::abs(cell->face(f)->center()[1]) < tol)
                {
                  fe_face_values.reinit(cell, f);
                  cell->get_dof_indices(local);
                  for (unsigned int i = 0; i < local.size(); ++i)
                    {
                      const auto gi = offset[s] + local[i];
                      const auto it =
                        pair_rows.find({key_of(support[gi][0]), component[gi]});
                      if (std::abs(support[gi][1]) > tol ||
                          it == pair_rows.end())
                        continue;
                      for (unsigned int j = 0; j < local.size(); ++j)
                        {
                          const auto gj = offset[s] + local[j];
                          if (component[gj] != component[gi] ||
                              clamped.is_constrained(gj))
                            continue;
                          double m = 0;
                          for (const unsigned int q :
                               fe_face_values.quadrature_point_indices())
                            m += fe_face_values.shape_value(i, q) *
                                 fe_face_values.shape_value(j, q) *
                                 fe_face_values.JxW(q);
                          if (m != 0)
                            it->second.entries[gj] += sign * m;
                        }
                    }
                }
        }
    for (auto &entry : pair_rows)
      rows.push_back(entry.second);
  }


  void
  Reference::build_rows()
  {
    add_pair_rows(0, 1, true);  // layer 1 across Sigma
    add_pair_rows(0, 2, false); // u- = v-
    add_pair_rows(1, 3, false); // u+ = v+
  }


  Result
  Reference::solve()
  {
    std::set<unsigned int> active;
    for (unsigned int r = 0; r < rows.size(); ++r)
      if (rows[r].contact)
        active.insert(r);
    Result                    result;
    Vector<double>            w, multipliers;
    std::vector<unsigned int> imposed;
    for (unsigned int iteration = 0; iteration < 50 && !result.settled;
         ++iteration)
      {
        imposed.clear();
        for (unsigned int r = 0; r < rows.size(); ++r)
          if (!rows[r].contact || active.count(r) > 0)
            imposed.push_back(r);
        const types::global_dof_index N = offset[4], m = imposed.size();
        DynamicSparsityPattern        dsp(N + m);
        for (auto e = stiffness.begin(); e != stiffness.end(); ++e)
          dsp.add(e->row(), e->column());
        for (unsigned int k = 0; k < m; ++k)
          for (const auto &entry : rows[imposed[k]].entries)
            {
              dsp.add(N + k, entry.first);
              dsp.add(entry.first, N + k);
            }
        SparsityPattern sp;
        sp.copy_from(dsp);
        SparseMatrix<double> system(sp);
        for (auto e = stiffness.begin(); e != stiffness.end(); ++e)
          system.set(e->row(), e->column(), e->value());
        for (unsigned int k = 0; k < m; ++k)
          for (const auto &entry : rows[imposed[k]].entries)
            {
              system.set(N + k, entry.first, entry.second);
              system.set(entry.first, N + k, entry.second);
            }
        Vector<double> x(N + m);
        for (types::global_dof_index i = 0; i < N; ++i)
          x(i) = load(i);
        SparseDirectUMFPACK direct;
        direct.initialize(system);
        direct.solve(x);
        w.reinit(N);
        for (types::global_dof_index i = 0; i < N; ++i)
          w(i) = x(i);
        multipliers.reinit(rows.size());
        for (unsigned int k = 0; k < m; ++k)
          multipliers(imposed[k]) = x(N + k);

        // Contact rows: release tensile multipliers, close penetrations.
        double force_scale = 0;
        for (const unsigned int r : active)
          force_scale = std::max(force_scale, std::abs(multipliers(r)));
        const double           scale = w.linfty_norm();
        std::set<unsigned int> next;
        for (unsigned int r = 0; r < rows.size(); ++r)
          if (rows[r].contact)
            {
              double gap = 0;
              for (const auto &entry : rows[r].entries)
                gap += entry.second * w(entry.first);
              if (active.count(r) > 0 ? multipliers(r) >= -1e-12 * force_scale :
                                        gap > 1e-12 * scale)
                next.insert(r);
            }
        result.settled = next == active;
        active         = next;
      }

    // KKT conditions of the final solution: stationarity K w - F + B^T mu
    // = 0 holds by construction; check the signs.
    result.kkt         = true;
    double force_scale = multipliers.linfty_norm();
    for (unsigned int r = 0; r < rows.size(); ++r)
      if (rows[r].contact)
        {
          double gap = 0;
          for (const auto &entry : rows[r].entries)
            gap += entry.second * w(entry.first);
          result.kkt = result.kkt && gap <= 1e-10 * w.linfty_norm() &&
                       multipliers(r) >= -1e-10 * force_scale;
        }

    Vector<double> Kw(offset[4]);
    stiffness.vmult(Kw, w);
    result.energy = 0.5 * (w * Kw) - load * w;
    // The normal opening (u+ - u-)_y at the nodes strictly inside the crack.
    bool first = true;
    for (const auto &[x, u_minus] : sigma[0])
      if (x > key_of(crack[0]) && x < key_of(crack[1]))
        {
          const double opening = w(sigma[1].at(x)[1]) - w(u_minus[1]);
          if (first || opening > result.max_opening)
            {
              result.max_opening  = opening;
              result.max_position = x;
              first               = false;
            }
        }
    return result;
  }


  /// v = m 10^k with 1 <= |m| < 10, printed as "[10^k]: m" (8 digits).
  std::string
  scaled(const double v)
  {
    int k = v == 0 ? 0 : static_cast<int>(std::floor(std::log10(std::abs(v))));
    double m = v / std::pow(10., k);
    if (std::abs(m) >= 9.99999995)
      {
        ++k;
        m /= 10;
      }
    std::ostringstream s;
    s << "[10^" << k << "]: " << std::fixed << std::setprecision(7) << m;
    return s.str();
  }


  /// The fields of a line split at numdiff's separators (run_test.sh).
  std::vector<std::string>
  fields(const std::string &line)
  {
    std::vector<std::string> result;
    std::string              field;
    for (const char c : line + " ")
      if (std::string(" \t\r\n=,:;<>[](){}^").find(c) != std::string::npos)
        {
          if (!field.empty())
            result.push_back(field);
          field.clear();
        }
      else
        field += c;
    return result;
  }

  /// Whether two lines are equal for numdiff -a 1e-6 -r 1e-8.
  bool
  numdiff_equal(const std::string &a, const std::string &b)
  {
    const auto fa = fields(a), fb = fields(b);
    if (fa.size() != fb.size())
      return false;
    for (unsigned int i = 0; i < fa.size(); ++i)
      {
        char  *end_a, *end_b;
        double x = std::strtod(fa[i].c_str(), &end_a);
        double y = std::strtod(fb[i].c_str(), &end_b);
        if (*end_a != '\0' || *end_b != '\0' || end_a == fa[i].c_str())
          {
            if (fa[i] != fb[i])
              return false;
          }
        else if (!(std::abs(x - y) <= 1e-6 ||
                   std::abs(x - y) <=
                     1e-8 * std::max(std::abs(x), std::abs(y))))
          return false;
      }
    return true;
  }
} // namespace


int
main()
{
  // The .output files of the .prm tests, beside this file (SOURCE_DIR: a
  // compile definition of deal.II's test macros).
  const std::string directory = std::string(SOURCE_DIR) + "/";

  for (const SceneSpec &spec : scenes)
    {
      std::cout << spec.name << ":" << std::endl;
      std::vector<std::string> lines;
      bool                     settled = true, kkt = true;
      for (unsigned int cycle = 0; cycle < spec.cycles; ++cycle)
        {
          Reference    reference(spec, cycle);
          const Result r = reference.solve();
          settled        = settled && r.settled;
          kkt            = kkt && r.kkt;
          std::ostringstream x;
          x << r.max_position * 1e-6;
          lines.push_back("cycle " + std::to_string(cycle) + ": energy Pi " +
                          scaled(r.energy));
          lines.push_back("cycle " + std::to_string(cycle) +
                          ": largest crack opening " + scaled(r.max_opening) +
                          " at x = " + x.str());
        }
      for (const auto &line : lines)
        std::cout << line << std::endl;
      std::cout << "active set settled, signs of the KKT conditions hold: "
                << yes(settled && kkt) << std::endl;

      // Every reference line must appear, to numdiff's tolerance, in the
      // .output file of each test that prints it.
      for (const std::string &test : spec.tests)
        {
          std::ifstream            in(directory + test + ".output");
          std::vector<std::string> expected;
          for (std::string line; std::getline(in, line);)
            expected.push_back(line);
          bool found = !expected.empty();
          for (const auto &line : lines)
            found = found && std::any_of(expected.begin(),
                                         expected.end(),
                                         [&](const std::string &e) {
                                           return numdiff_equal(line, e);
                                         });
          std::cout << test << ".output holds these numbers: " << yes(found)
                    << std::endl;
        }
    }
}
