// Solves on Sigma alone (ElasticSubproblem::condensed()) against the whole
// sparse solves they replace.
//
// A subproblem on the unit square, clamped at the bottom, loaded by a
// traction on the left and right sides, whose top side is Sigma (half glued,
// half crack). With its Sigma dofs S eliminated last, the trailing block
// L_S of the sparse Cholesky factor is the Cholesky factor of the Schur
// complement S = K_SS - K_SI K_II^{-1} K_IS, and (K^{-1})_SS = S^{-1}. So,
// for loads c on the Sigma dofs:
//  1. solve_on_sigma(c) equals solve(c) on every Sigma dof, for the whole
//     problem and the homogeneous one (relative difference < 1e-10), and
//     so does solve_homogeneous_on_sigma() of several loads at once;
//  2. S S^{-1} c = c: apply_schur_complement() of the homogeneous solution
//     on Sigma gives back the condensed load (relative < 1e-10);
//  3. S is symmetric: x.S y = y.S x (relative < 1e-12);
//  4. on meshes without hanging nodes, S x equals the reaction on Sigma of
//     the discrete-harmonic extension that the Dirichlet preconditioner
//     computes with its own factorisation (InterfaceStiffness);
//  5. without condensation asked for, none is made.
//  6. a Sigma dof on the clamped side (prescribed displacement, no entries)
//     takes its prescribed value in the whole problem and zero in the
//     homogeneous one.
//  7. solve() and solve_homogeneous() of the condensed subproblem (their
//     forward substitution on Sigma alone) equal the plain sparse solves on
//     every dof (relative difference < 1e-10);
// Meshes (8 x 8 cells, simplicial factors, and 48 x 48, supernodal): Q1
// and Q2 quadrilaterals, P2 triangles, Q1 refined towards a
// point of Sigma (hanging nodes next to Sigma whose constraints name Sigma
// dofs; a boundary face has no hanging node), and Q2 with the left side
// clamped as well, so that Sigma ends on Gamma_D.

#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <bilayer/geometry/geometry.h>
#include <bilayer/subproblem/interface_stiffness.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace dealii;
using namespace bilayer;

namespace
{
  void
  set_boundary_ids(Triangulation<2> &tria)
  {
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        {
          const Point<2> c = face->center();
          face->set_boundary_id(c[0] < 1e-12     ? BoundaryIds::left :
                                c[0] > 1 - 1e-12 ? BoundaryIds::right :
                                c[1] < 1e-12     ? BoundaryIds::bottom :
                                                   BoundaryIds::sigma);
        }
  }


  double
  largest_difference_on(const std::vector<types::global_dof_index> &dofs,
                        const Vector<double>                       &a,
                        const Vector<double>                       &b)
  {
    double difference = 0, size = 0;
    for (const auto i : dofs)
      {
        difference = std::max(difference, std::abs(a(i) - b(i)));
        size       = std::max(size, std::abs(b(i)));
      }
    return size > 0 ? difference / size : difference;
  }


  const char *
  verdict(const bool ok)
  {
    return ok ? "yes" : "NO";
  }
} // namespace


int
main()
{
  const LayerMaterial material{200.0, 0.28};
  FunctionParser<2>   prescribed(2), side_traction(2);
  prescribed.initialize("x,y", "1e-3*(x+1); 1e-3*(y+2)", {});
  side_traction.initialize("x,y", "1 - y; 0.5", {});
  const Functions::ZeroFunction<2> zero(2);
  // Side ids: left, right, bottom, top (BoundaryIds); Sigma carries its own.
  const std::vector<const Function<2> *> traction = {&side_traction,
                                                     &side_traction,
                                                     &zero,
                                                     &zero};
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  struct Case
  {
    std::string  name;
    bool         simplex;
    unsigned int degree;
    bool         hanging;
    bool         clamped_left;
    unsigned int cells = 8;
  };
  for (const Case &c :
       {Case{"Q1", false, 1, false, false},
        Case{"Q2", false, 2, false, false},
        Case{"P2", true, 2, false, false},
        Case{"Q1 with hanging nodes next to Sigma", false, 1, true, false},
        Case{"Q2 with Sigma ending on the clamped side", false, 2, false, true},
        // Large enough for CHOLMOD's supernodal factor (the others are
        // simplicial): both layouts of the factor are read.
        Case{"Q2, 48 x 48 cells, Sigma ending on the clamped side",
             false,
             2,
             false,
             true,
             48}})
    {
      const std::vector<bool> clamped = {c.clamped_left, false, true, false};
      Triangulation<2>        tria;
      if (c.simplex)
        GridGenerator::subdivided_hyper_rectangle_with_simplices(
          tria, {c.cells, c.cells}, Point<2>(0, 0), Point<2>(1, 1));
      else
        GridGenerator::subdivided_hyper_rectangle(tria,
                                                  {c.cells, c.cells},
                                                  Point<2>(0, 0),
                                                  Point<2>(1, 1));
      if (c.hanging)
        for (unsigned int step = 0; step < 2; ++step)
          {
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->center().distance(Point<2>(0.3, 1.)) < 0.3)
                cell->set_refine_flag();
            tria.execute_coarsening_and_refinement();
          }
      set_boundary_ids(tria);

      ElasticSubproblem condensed(
        Layer::first, Subdomain::minus, tria, c.degree, material);
      condensed.setup(clamped, prescribed, traction, "Amesos_Mumps", true);
      ElasticSubproblem plain(
        Layer::first, Subdomain::minus, tria, c.degree, material);
      plain.setup(clamped, prescribed, traction);

      // The Sigma dofs, and loads on them (hanging ones included).
      const IndexSet on_sigma =
        DoFTools::extract_boundary_dofs(condensed.dof_handler(),
                                        ComponentMask(),
                                        {BoundaryIds::sigma});
      const std::vector<types::global_dof_index> sigma(on_sigma.begin(),
                                                       on_sigma.end());
      const AffineConstraints<double>           &hanging =
        condensed.zero_displacement_constraints();
      unsigned int n_constrained = 0;
      for (const auto i : sigma)
        n_constrained += hanging.is_constrained(i);
      Vector<double> load(condensed.n_dofs());
      for (const auto i : sigma)
        load(i) = uniform(random);

      std::cout << c.name << ": " << sigma.size() << " Sigma dofs, "
                << n_constrained << " constrained" << std::endl;
      std::cout << "  condensed, with S of all unconstrained Sigma dofs: "
                << verdict(condensed.condensed() &&
                           condensed.n_schur_dofs() ==
                             sigma.size() - n_constrained)
                << std::endl;
      std::cout << "  not condensed unless asked: "
                << verdict(!plain.condensed()) << std::endl;
      if (!condensed.condensed())
        continue;

      Vector<double> whole, on_sigma_only;
      plain.solve(load, whole);
      condensed.solve_on_sigma(load, on_sigma_only, false);
      const double d_whole = largest_difference_on(sigma, on_sigma_only, whole);
      plain.solve_homogeneous(load, whole);
      condensed.solve_on_sigma(load, on_sigma_only, true);
      const double d_homogeneous =
        largest_difference_on(sigma, on_sigma_only, whole);
      std::cout << "  solve_on_sigma = solve on Sigma (< 1e-10): "
                << verdict(d_whole < 1e-10 && d_homogeneous < 1e-10)
                << std::endl;
      // Three loads at once (blocked, LAPACK's dpotrs) against the plain
      // homogeneous solves of each.
      {
        std::vector<Vector<double>> loads(3, load), together;
        loads[1] *= -2.;
        for (const auto i : sigma)
          loads[2](i) = uniform(random);
        std::vector<const Vector<double> *> pointers;
        for (const auto &l : loads)
          pointers.push_back(&l);
        condensed.solve_homogeneous_on_sigma(pointers, together);
        double worst = 0;
        for (unsigned int k = 0; k < loads.size(); ++k)
          {
            plain.solve_homogeneous(loads[k], whole);
            worst =
              std::max(worst, largest_difference_on(sigma, together[k], whole));
          }
        std::cout << "  several loads at once = solve on Sigma (< 1e-10): "
                  << verdict(together.size() == 3 && worst < 1e-10)
                  << std::endl;
      }
      // The whole solves of the condensed subproblem (the forward
      // substitution on Sigma alone, solve_from_trailing()) against the
      // plain sparse ones, on every dof.
      std::vector<types::global_dof_index> all(condensed.n_dofs());
      for (unsigned int i = 0; i < all.size(); ++i)
        all[i] = i;
      Vector<double> reference, condensed_whole;
      plain.solve(load, reference);
      condensed.solve(load, condensed_whole);
      const double d_all =
        largest_difference_on(all, condensed_whole, reference);
      plain.solve_homogeneous(load, reference);
      condensed.solve_homogeneous(load, condensed_whole);
      const double d_all_homogeneous =
        largest_difference_on(all, condensed_whole, reference);
      std::cout << "  whole solve = plain solve on every dof (< 1e-10): "
                << verdict(d_all < 1e-10 && d_all_homogeneous < 1e-10)
                << std::endl;
      if (n_constrained > 0)
        {
          // The prescribed values at the corner (0, 1): 1e-3 and 3e-3.
          Vector<double> whole_on_sigma, homogeneous;
          condensed.solve_on_sigma(load, whole_on_sigma, false);
          condensed.solve_on_sigma(load, homogeneous, true);
          const IndexSet x_dofs =
            DoFTools::extract_dofs(condensed.dof_handler(),
                                   ComponentMask(
                                     std::vector<bool>{true, false}));
          bool prescribed_ok = true;
          for (const auto i : sigma)
            if (hanging.is_constrained(i))
              {
                const double expected = x_dofs.is_element(i) ? 1e-3 : 3e-3;
                prescribed_ok =
                  prescribed_ok &&
                  std::abs(whole_on_sigma(i) - expected) < 1e-15 &&
                  homogeneous(i) == 0.;
              }
          std::cout << "  clamped Sigma dofs: prescribed value, zero when "
                       "homogeneous: "
                    << verdict(prescribed_ok) << std::endl;
        }

      // S S^{-1} c = c on the unconstrained Sigma dofs, c the condensed load.
      Vector<double> condensed_load(load), back;
      hanging.condense(condensed_load);
      condensed.apply_schur_complement(on_sigma_only, back);
      std::vector<types::global_dof_index> free_sigma;
      for (const auto i : sigma)
        if (!hanging.is_constrained(i))
          free_sigma.push_back(i);
      std::cout << "  S S^-1 c = c (< 1e-10): "
                << verdict(largest_difference_on(free_sigma,
                                                 back,
                                                 condensed_load) < 1e-10)
                << std::endl;

      // Symmetry.
      Vector<double> x(condensed.n_dofs()), y(condensed.n_dofs()), sx, sy;
      for (const auto i : free_sigma)
        {
          x(i) = uniform(random);
          y(i) = uniform(random);
        }
      condensed.apply_schur_complement(x, sx);
      condensed.apply_schur_complement(y, sy);
      const double xsy = x * sy, ysx = y * sx;
      std::cout << "  S symmetric (< 1e-12): "
                << verdict(std::abs(xsy - ysx) <=
                           1e-12 * std::max(std::abs(xsy),
                                            x.l2_norm() * sy.l2_norm()))
                << std::endl;

      // The Dirichlet preconditioner's own S: equal where no hanging node
      // next to Sigma depends on a Sigma dof (its extension leaves such a
      // node at zero instead of interpolating it: a preconditioner may).
      if (!c.hanging)
        {
          const InterfaceStiffness dirichlet(plain, true);
          Vector<double>           reference;
          dirichlet.apply_schur_complement(x, reference);
          std::cout << "  S x = reaction of the discrete-harmonic extension "
                       "(< 1e-10): "
                    << verdict(largest_difference_on(free_sigma,
                                                     sx,
                                                     reference) < 1e-10)
                    << std::endl;
        }
    }
}
