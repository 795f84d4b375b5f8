#include <deal.II/base/exceptions.h>

#include <bilayer/physics/elastic_law.h>

#include <cmath>
#include <limits>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    using Matrix3 = std::array<std::array<double, 3>, 3>;

    /// The index of the component (i, j) of a symmetric 2x2 tensor in the
    /// Voigt vector (11, 22, 12).
    unsigned int
    voigt_index(const unsigned int i, const unsigned int j)
    {
      return i == j ? i : 2;
    }
  } // namespace


  GeneralPlaneLaw::GeneralPlaneLaw(const SymmetricTensor<4, 2>  &C,
                                   const SymmetricTensor<2, 2>  &Z,
                                   const bool                    has_sigma_zz,
                                   std::map<std::string, double> constants,
                                   const SymmetricTensor<2, 2>  &P,
                                   const double                  E_zz)
    : C(C)
    , Z(Z)
    , has_sigma_zz(has_sigma_zz)
    , P(P)
    , E_zz(E_zz)
    , smallest_eigenvalue(plane_laws::smallest_mandel_eigenvalue(C))
    , constants(std::move(constants))
  {
    AssertThrow(smallest_eigenvalue > 0,
                ExcMessage("the tangent of an elastic law must be positive "
                           "definite, its smallest eigenvalue is " +
                           std::to_string(smallest_eigenvalue)));
  }


  double
  GeneralPlaneLaw::out_of_plane_stress(const SymmetricTensor<2, 2> &eps) const
  {
    if (!has_sigma_zz)
      return std::numeric_limits<double>::quiet_NaN();
    return Z * eps;
  }


  void
  GeneralPlaneLaw::add_stiffness(const std::vector<SymmetricTensor<2, 2>> &eps,
                                 const double                              JxW,
                                 FullMatrix<double> &cell_matrix) const
  {
    // The stresses once per shape function, then their products with the
    // strains: the same sum as bilinear_form().
    thread_local std::vector<SymmetricTensor<2, 2>> sigma;
    const unsigned int                              n = eps.size();
    sigma.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      sigma[i] = C * eps[i];
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i; j < n; ++j)
        cell_matrix(i, j) += (sigma[i] * eps[j]) * JxW;
  }


  namespace plane_laws
  {
    SymmetricTensor<4, 2>
    tangent_of_voigt(const Matrix3 &D)
    {
      // sigma_ij = sum_kl C_ijkl eps_kl counts the shear strain twice
      // (kl = 12 and 21): C_ijkl = D(voigt(ij), voigt(kl)) for every index.
      SymmetricTensor<4, 2> C;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = k; l < 2; ++l)
              C[i][j][k][l] = D[voigt_index(i, j)][voigt_index(k, l)];
      return C;
    }


    Matrix3
    voigt_of_stiffness(const std::array<double, 6> &c)
    {
      return {
        {{{c[0], c[1], c[2]}}, {{c[1], c[3], c[4]}}, {{c[2], c[4], c[5]}}}};
    }


    Tensor<2, 2>
    rotation(const double angle)
    {
      const double radians = angle * numbers::PI / 180.;
      const double c = std::cos(radians), s = std::sin(radians);
      Tensor<2, 2> R;
      R[0][0] = c;
      R[0][1] = -s;
      R[1][0] = s;
      R[1][1] = c;
      return R;
    }


    SymmetricTensor<4, 2>
    rotate(const SymmetricTensor<4, 2> &C_material, const Tensor<2, 2> &R)
    {
      // C_xy,ijkl = R_ia R_jb R_kc R_ld C_material,abcd.
      SymmetricTensor<4, 2> C;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = k; l < 2; ++l)
              {
                double sum = 0;
                for (unsigned int a = 0; a < 2; ++a)
                  for (unsigned int b = 0; b < 2; ++b)
                    for (unsigned int c = 0; c < 2; ++c)
                      for (unsigned int d = 0; d < 2; ++d)
                        sum += R[i][a] * R[j][b] * R[k][c] * R[l][d] *
                               C_material[a][b][c][d];
                C[i][j][k][l] = sum;
              }
      return C;
    }


    double
    smallest_mandel_eigenvalue(const SymmetricTensor<4, 2> &C)
    {
      const double          r = std::sqrt(2.);
      SymmetricTensor<2, 3> M;
      M[0][0] = C[0][0][0][0];
      M[1][1] = C[1][1][1][1];
      M[2][2] = 2 * C[0][1][0][1];
      M[0][1] = C[0][0][1][1];
      M[0][2] = r * C[0][0][0][1];
      M[1][2] = r * C[1][1][0][1];
      // Jacobi's method: accurate to round-off also for the double
      // eigenvalue 2 mu of an isotropic law (sorted in descending order).
      return eigenvectors(M, SymmetricTensorEigenvectorMethod::jacobi)[2].first;
    }


    std::unique_ptr<const ElasticLaw>
    isotropic_plane_stress(const double E, const double nu)
    {
      const double  a  = E / (1 - nu * nu);
      const double  mu = E / (2 * (1 + nu));
      const Matrix3 D  = {{{{a, a * nu, 0}}, {{a * nu, a, 0}}, {{0, 0, mu}}}};
      std::map<std::string, double> constants = {{"E", E},
                                                 {"nu", nu},
                                                 {"mu", mu}};
      // The Lame constant of the 3-D material (infinite for nu = 0.5).
      if (nu < 0.5)
        constants["lambda"] = 2 * nu * mu / (1 - 2 * nu);
      return std::make_unique<GeneralPlaneLaw>(tangent_of_voigt(D),
                                               SymmetricTensor<2, 2>(),
                                               true,
                                               constants);
    }


    std::unique_ptr<const ElasticLaw>
    orthotropic(const OrthotropicConstants &o,
                const PlaneState            state,
                const double                angle)
    {
      // In the material frame: the in-plane stiffness D and the row Z of
      // sigma_zz.
      Matrix3               D = {};
      SymmetricTensor<2, 2> Z, P;
      double                E_zz = 0;
      D[2][2]                    = o.G_12;
      if (state == PlaneState::plane_stress)
        {
          // sigma_zz = 0: the 2x2 compliance [[1/E_1, -nu_12/E_1],
          // [-nu_12/E_1, 1/E_2]] inverted.
          const double den = 1 - o.nu_12 * o.nu_12 * o.E_2 / o.E_1;
          D[0][0]          = o.E_1 / den;
          D[1][1]          = o.E_2 / den;
          D[0][1] = D[1][0] = o.nu_12 * o.E_2 / den;
        }
      else
        {
          // eps_zz = 0: the normal block of the 3-D stiffness, the inverse
          // of the normal block of the compliance; sigma_zz its third row.
          SymmetricTensor<2, 3> S;
          S[0][0]                       = 1 / o.E_1;
          S[1][1]                       = 1 / o.E_2;
          S[2][2]                       = 1 / o.E_3;
          S[0][1]                       = -o.nu_12 / o.E_1;
          S[0][2]                       = -o.nu_13 / o.E_1;
          S[1][2]                       = -o.nu_23 / o.E_2;
          const SymmetricTensor<2, 3> K = invert(S);
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              D[i][j] = K[i][j];
          Z[0][0] = K[2][0];
          Z[1][1] = K[2][1];
          // A 3-D eigenstrain's eps_zz under eps_zz = 0: the in-plane
          // eigenstrain gains -(S_p3 / S_33) eps_zz = (nu_31, nu_32)
          // eps_zz, sigma_zz gains -eps_zz / S_33 = -E_3 eps_zz.
          P[0][0] = -S[0][2] / S[2][2];
          P[1][1] = -S[1][2] / S[2][2];
          E_zz    = 1 / S[2][2];
        }
      const Tensor<2, 2> R = rotation(angle);
      // sigma_zz = Z : (R^T e R) = (R Z R^T) : e.
      const auto to_xy = [&R](const SymmetricTensor<2, 2> &T) {
        return symmetrize(Tensor<2, 2>(R * Tensor<2, 2>(T) * transpose(R)));
      };
      return std::make_unique<GeneralPlaneLaw>(rotate(tangent_of_voigt(D), R),
                                               to_xy(Z),
                                               true,
                                               std::map<std::string, double>(),
                                               to_xy(P),
                                               E_zz);
    }


    std::unique_ptr<const ElasticLaw>
    anisotropic(const std::array<double, 6> &stiffness)
    {
      return std::make_unique<GeneralPlaneLaw>(tangent_of_voigt(
                                                 voigt_of_stiffness(stiffness)),
                                               SymmetricTensor<2, 2>(),
                                               false);
    }
  } // namespace plane_laws
} // namespace bilayer
