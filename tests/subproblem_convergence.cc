// One elasticity subproblem with a smooth exact solution: optimal rates.
//
// u = grad(phi), phi = exp(x) sin(y), solves the Navier equations without
// body force (div u = 0 and Laplace u = 0), so it is an exact solution of
// the plane-strain problem for any Lame constants. Its stress is
// sigma = 2 mu grad grad phi. The subproblem is clamped to u on the left,
// right and bottom sides and loaded by the exact traction sigma n on the top
// side; the errors must converge at the optimal rates k+1 (L2) and k (H1)
// for degree k on quadrilaterals and triangles.

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>

#include <bilayer/geometry/geometry.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace bilayer;

int
main()
{
  const LayerMaterial material{200.0, 0.28};
  // The shear modulus of E and nu.
  const std::map<std::string, double> constants = {
    {"mu", material.youngs_modulus / (2. * (1. + material.poisson_ratio))}};

  FunctionParser<2> exact(2);
  exact.initialize("x,y", "exp(x)*sin(y); exp(x)*cos(y)", constants);
  FunctionParser<2> top_traction(2);
  top_traction.initialize("x,y",
                          "2*mu*exp(x)*cos(y); -2*mu*exp(x)*sin(y)",
                          constants);
  const Functions::ZeroFunction<2>       zero(2);
  const std::vector<const Function<2> *> traction = {&zero,
                                                     &zero,
                                                     &zero,
                                                     &top_traction};
  const std::vector<bool>                clamped  = {true, true, true, false};

  for (const bool simplex : {false, true})
    for (const unsigned int degree : {1u, 2u})
      {
        double previous_l2 = 0, previous_h1 = 0;
        double l2_rate = 0, h1_rate = 0;
        for (unsigned int n = 4; n <= 32; n *= 2)
          {
            Triangulation<2> tria;
            if (simplex)
              GridGenerator::subdivided_hyper_rectangle_with_simplices(
                tria, {n, n}, Point<2>(0, 0), Point<2>(1, 1));
            else
              GridGenerator::subdivided_hyper_rectangle(tria,
                                                        {n, n},
                                                        Point<2>(0, 0),
                                                        Point<2>(1, 1));
            // Side ids as in bilayer::BoundaryIds: left, right, bottom, top.
            for (const auto &face : tria.active_face_iterators())
              if (face->at_boundary())
                {
                  const Point<2> c = face->center();
                  face->set_boundary_id(c[0] < 1e-12     ? BoundaryIds::left :
                                        c[0] > 1 - 1e-12 ? BoundaryIds::right :
                                        c[1] < 1e-12     ? BoundaryIds::bottom :
                                                           BoundaryIds::top);
                }

            ElasticSubproblem sub(
              Layer::first, Subdomain::minus, tria, degree, material);
            sub.setup(clamped, exact, traction);
            Vector<double> solution;
            sub.solve(Vector<double>(), solution);

            // Exact enough for the errors; the simplex Gauss rules of
            // deal.II 9.4 go up to 4 points per direction.
            const Quadrature<2> quadrature =
              sub.fe().reference_cell().get_gauss_type_quadrature<2>(degree +
                                                                     2);
            const auto error = [&](const VectorTools::NormType norm) {
              Vector<float> cellwise(tria.n_active_cells());
              VectorTools::integrate_difference(sub.mapping(),
                                                sub.dof_handler(),
                                                solution,
                                                exact,
                                                cellwise,
                                                quadrature,
                                                norm);
              return VectorTools::compute_global_error(tria, cellwise, norm);
            };
            const double l2 = error(VectorTools::L2_norm);
            const double h1 = error(VectorTools::H1_seminorm);
            if (previous_l2 > 0)
              {
                l2_rate = std::log2(previous_l2 / l2);
                h1_rate = std::log2(previous_h1 / h1);
              }
            previous_l2 = l2;
            previous_h1 = h1;
          }
        // Rates between the two finest meshes, within 0.1 of the optimum.
        std::cout << (simplex ? "P" : "Q") << degree << ": L2 rate "
                  << degree + 1 << " +- 0.1: "
                  << (std::abs(l2_rate - (degree + 1)) < 0.1 ? "yes" : "NO")
                  << ", H1 rate " << degree << " +- 0.1: "
                  << (std::abs(h1_rate - degree) < 0.1 ? "yes" : "NO")
                  << std::endl;
      }
}
