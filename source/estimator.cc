#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/error_estimator.h>

#include <bilayer/estimator.h>
#include <bilayer/geometry.h>

namespace bilayer
{
  std::array<Vector<float>, 2>
  estimate_error(const std::array<const ElasticSubproblem *, 4> &subproblems,
                 const Interface                                &interface,
                 const Solutions                                &w,
                 const BlockVector<double>                      &mu,
                 const bool interface_terms)
  {
    std::array<Vector<float>, 2> eta;
    for (unsigned int s = 0; s < 4; ++s)
      {
        const ElasticSubproblem &sub  = *subproblems[s];
        const auto              &tria = sub.dof_handler().get_triangulation();
        const unsigned int       sd   = s % 2;
        if (eta[sd].size() != tria.n_active_cells())
          eta[sd].reinit(tria.n_active_cells());

        Vector<float> kelly(tria.n_active_cells());
        const auto    face_quadrature =
          ReferenceCells::Line.get_gauss_type_quadrature<1>(sub.fe().degree +
                                                            1);
        KellyErrorEstimator<2>::estimate(
          sub.mapping(), sub.dof_handler(), face_quadrature, {}, w[s], kelly);
        for (unsigned int i = 0; i < kelly.size(); ++i)
          eta[sd][i] = std::sqrt(double(eta[sd][i]) * eta[sd][i] +
                                 double(kelly[i]) * kelly[i]);
        if (!interface_terms)
          continue;

        // The residual of the multiplier load on the Sigma faces.
        FEFaceValues<2>                    fe_face(sub.mapping(),
                                sub.fe(),
                                face_quadrature,
                                update_gradients | update_quadrature_points |
                                  update_normal_vectors | update_JxW_values);
        const FEValuesExtractors::Vector   displacement(0);
        std::vector<SymmetricTensor<2, 2>> strain(face_quadrature.size());
        const double                       mu_material = sub.material().mu();
        const double                       lambda = sub.material().lambda();
        for (const auto &cell : sub.dof_handler().active_cell_iterators())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                (cell->face(f)->boundary_id() == BoundaryIds::glued ||
                 cell->face(f)->boundary_id() == BoundaryIds::crack))
              {
                fe_face.reinit(cell, f);
                fe_face[displacement].get_function_symmetric_gradients(w[s],
                                                                       strain);
                double sum = 0;
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    const SymmetricTensor<2, 2> stress =
                      2 * mu_material * strain[q] +
                      lambda * trace(strain[q]) * unit_symmetric_tensor<2>();
                    const Tensor<1, 2> residual =
                      stress * fe_face.normal_vector(q) -
                      interface.multiplier_traction(
                        mu, s, fe_face.quadrature_point(q)[0]);
                    sum += (residual * residual) /
                           (4 * mu_material * mu_material) * fe_face.JxW(q);
                  }
                const double       term = cell->face(f)->diameter() / 24. * sum;
                const unsigned int i    = cell->active_cell_index();
                eta[sd][i] = std::sqrt(double(eta[sd][i]) * eta[sd][i] + term);
              }
      }
    return eta;
  }
} // namespace bilayer
