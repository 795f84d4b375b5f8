// Unit tests of the elastic laws (elastic_law.h): the general plane laws
// against the isotropic plane-strain law and against 3-D elasticity
// computed here independently.
//
// Every printed verdict has a reason to be right, stated beside it:
// - Orthotropic plane strain with isotropic constants (E_i = E, nu_ij = nu,
//   G_12 = E / (2 (1 + nu))) is the isotropic law at every orientation (an
//   isotropic tensor is invariant under rotations): tangent and sigma_zz
//   equal IsotropicPlaneStrain's to 1e-12 relative at 0, 30 and 77 degrees;
//   in plane stress the tangent equals the isotropic plane-stress law's.
// - The anisotropic law of the isotropic plane-strain stiffness (C11 = C22
//   = lambda + 2 mu, C12 = lambda, C66 = mu, C16 = C26 = 0) is that law;
//   it has no sigma_zz (NaN).
// - An anisotropic stiffness with C16, C26 != 0: the stress is the matrix
//   product (s11, s22, s12) = C (e11, e22, 2 e12) written out here.
// - Isotropic plane stress: the stress is E / (1 - nu^2) [e11 + nu e22,
//   e22 + nu e11, (1 - nu) e12], sigma_zz = 0; nu = 0.5 is a law too.
// - Orthotropic plane strain at 37 degrees (E_1 = 140, E_2 = 10, E_3 = 12,
//   nu_12 = 0.3, nu_13 = 0.28, nu_23 = 0.45, G_12 = 5): the in-plane stress
//   and sigma_zz equal the 3-D stress of the strain (e, eps_zz = 0, no
//   out-of-plane shear) computed here: the strain turned into the material
//   axes (3-D rotation about z), the 6x6 orthotropic compliance inverted
//   (Gauss-Jordan), the stress turned back. Plane stress: the 3x3 block
//   (11, 22, 12) of the same compliance inverted in the material axes (the
//   3-D stress with s_zz = 0, s_13 = s_23 = 0), turned back; sigma_zz = 0.
//   Then the other way: the 3-D compliance applied to the law's 3-D stress
//   gives back the strain (and eps_zz = 0 in plane strain).
// - Objectivity: C(angle) applied to R e R^T equals R (C(0) e) R^T.
// - Every tangent is symmetric (C_ijkl = C_klij) and positive definite (the
//   eigenvalues of its Mandel matrix, by LAPACK, are positive);
//   energy_norm_scale() is the smallest of them, 2 mu for the isotropic
//   laws with nu >= 0; add_stiffness() adds the bilinear form.
// - load_constants(): E, nu, mu, lambda of the 3-D material for isotropic
//   plane stress (no lambda at nu = 0.5), none for orthotropic and
//   anisotropic laws.
// - plane_eigenstrain() of a thermal strain alpha dT (alpha = 1.2e-5,
//   dT = 85): isotropic plane strain gives eps*_eff = (1 + nu) alpha dT I
//   and the sigma_zz offset -E alpha dT, plane stress alpha dT I and 0
//   (closed forms, 1e-12); thermal_strain() of the material feeds it.
//   Orthotropic at 37 degrees (alpha_1, alpha_2, alpha_3 = 0.4e-5, 2.5e-5,
//   3.1e-5): in plane strain the 3-D stress K (eps - eps_th) of the strain
//   (e, eps_zz = 0) with the thermal strain diag(alpha) dT in the material
//   axes, K the inverted 6x6 compliance, equals (law.stress(e - eps*_eff),
//   Z : (e - eps*_eff) + offset) for e = 0 and the test strains (1e-12);
//   independently, the offset is the s_zz that makes eps_zz = S_33 s_zz +
//   alpha_3 dT vanish, -alpha_3 dT / S_33, and eps*_eff the in-plane strain
//   S_p3 s_zz + eps_th,p turned to x-y. Plane stress: eps*_eff the in-plane
//   thermal strain turned to x-y, offset 0. Anisotropic: the given
//   in-plane tensor per kelvin, offset 0.

#include <deal.II/base/numbers.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <bilayer/physics/elastic_law.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  using Strain = SymmetricTensor<2, 2>;

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << yes(ok) << "\n";
  }

  /// |a - b| <= tol * scale for every component.
  bool
  close(const SymmetricTensor<4, 2> &a,
        const SymmetricTensor<4, 2> &b,
        const double                 tol)
  {
    const double scale = b.norm();
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            if (std::abs(a[i][j][k][l] - b[i][j][k][l]) > tol * scale)
              return false;
    return true;
  }

  bool
  close(const Strain &a, const Strain &b, const double tol)
  {
    return (a - b).norm() <= tol * b.norm();
  }

  bool
  close(const double a, const double b, const double tol)
  {
    return std::abs(a - b) <= tol * std::abs(b);
  }

  /// Test strains: not coaxial with the axes, one with a negative trace.
  std::vector<Strain>
  strains()
  {
    std::vector<Strain> e(3);
    e[0][0][0] = 1.3e-3, e[0][1][1] = -0.4e-3, e[0][0][1] = 0.7e-3;
    e[1][0][0] = -2e-3, e[1][1][1] = 0.5e-3, e[1][0][1] = -1.1e-3;
    e[2][0][0] = 0.2e-3, e[2][1][1] = 0.9e-3, e[2][0][1] = 0.3e-3;
    return e;
  }

  /// The rotation by @p degrees counter-clockwise, written out here.
  FullMatrix<double>
  rotation3(const double degrees)
  {
    const double       a = degrees * numbers::PI / 180;
    FullMatrix<double> Q(3, 3);
    Q(0, 0) = std::cos(a), Q(0, 1) = -std::sin(a);
    Q(1, 0) = std::sin(a), Q(1, 1) = std::cos(a);
    Q(2, 2) = 1;
    return Q;
  }

  /// Q^T A Q (@p to_material) or Q A Q^T.
  FullMatrix<double>
  turn(const FullMatrix<double> &A,
       const FullMatrix<double> &Q,
       const bool                to_material)
  {
    FullMatrix<double> B(3, 3), C(3, 3);
    if (to_material)
      Q.Tmmult(B, A), B.mmult(C, Q);
    else
      Q.mmult(B, A), B.mTmult(C, Q);
    return C;
  }

  /// The 3-D tensor of an in-plane tensor @p e and its zz component.
  FullMatrix<double>
  embed(const Strain &e, const double zz)
  {
    FullMatrix<double> A(3, 3);
    A(0, 0) = e[0][0], A(1, 1) = e[1][1], A(0, 1) = A(1, 0) = e[0][1];
    A(2, 2) = zz;
    return A;
  }

  // Voigt order 11, 22, 33, 23, 13, 12, engineering shear strains.
  const unsigned int voigt_i[6] = {0, 1, 2, 1, 0, 0};
  const unsigned int voigt_j[6] = {0, 1, 2, 2, 2, 1};

  Vector<double>
  voigt(const FullMatrix<double> &A, const double shear_factor)
  {
    Vector<double> v(6);
    for (unsigned int a = 0; a < 6; ++a)
      v(a) = A(voigt_i[a], voigt_j[a]) * (a < 3 ? 1. : shear_factor);
    return v;
  }

  FullMatrix<double>
  tensor(const Vector<double> &v, const double shear_factor)
  {
    FullMatrix<double> A(3, 3);
    for (unsigned int a = 0; a < 6; ++a)
      A(voigt_i[a], voigt_j[a]) = A(voigt_j[a], voigt_i[a]) =
        v(a) / (a < 3 ? 1. : shear_factor);
    return A;
  }

  /// The 6x6 compliance of orthotropic constants (G_13, G_23 arbitrary:
  /// no out-of-plane shear in a plane problem).
  FullMatrix<double>
  compliance(const OrthotropicConstants &o)
  {
    FullMatrix<double> S(6, 6);
    const double       E[3]     = {o.E_1, o.E_2, o.E_3};
    const double       nu[3][3] = {{0, o.nu_12, o.nu_13},
                                   {o.nu_12 * o.E_2 / o.E_1, 0, o.nu_23},
                                   {o.nu_13 * o.E_3 / o.E_1,
                                    o.nu_23 * o.E_3 / o.E_2,
                                    0}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        S(i, j) = i == j ? 1 / E[i] : -nu[i][j] / E[i];
    S(3, 3) = 1 / 3.1, S(4, 4) = 1 / 4.7, S(5, 5) = 1 / o.G_12;
    return S;
  }

  /// The 3-D stress of orthotropic plane strain: (in-plane stress, s_zz).
  std::pair<Strain, double>
  plane_strain_3d(const OrthotropicConstants &o,
                  const double                degrees,
                  const Strain               &e)
  {
    const FullMatrix<double> Q = rotation3(degrees);
    FullMatrix<double>       K = compliance(o);
    K.gauss_jordan();
    const Vector<double> eps = voigt(turn(embed(e, 0), Q, true), 2.);
    Vector<double>       sigma(6);
    K.vmult(sigma, eps);
    const FullMatrix<double> s = turn(tensor(sigma, 1.), Q, false);
    Strain                   in_plane;
    in_plane[0][0] = s(0, 0), in_plane[1][1] = s(1, 1),
    in_plane[0][1] = s(0, 1);
    return {in_plane, s(2, 2)};
  }

  /// The in-plane stress of orthotropic plane stress.
  Strain
  plane_stress_3d(const OrthotropicConstants &o,
                  const double                degrees,
                  const Strain               &e)
  {
    const FullMatrix<double> Q       = rotation3(degrees);
    const FullMatrix<double> S       = compliance(o);
    const unsigned int       rows[3] = {0, 1, 5};
    FullMatrix<double>       K(3, 3);
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        K(a, b) = S(rows[a], rows[b]);
    K.gauss_jordan();
    const Vector<double> eps = voigt(turn(embed(e, 0), Q, true), 2.);
    Vector<double>       sigma(6), reduced(3), in(3);
    for (unsigned int a = 0; a < 3; ++a)
      in(a) = eps(rows[a]);
    K.vmult(reduced, in);
    for (unsigned int a = 0; a < 3; ++a)
      sigma(rows[a]) = reduced(a);
    const FullMatrix<double> s = turn(tensor(sigma, 1.), Q, false);
    Strain                   in_plane;
    in_plane[0][0] = s(0, 0), in_plane[1][1] = s(1, 1),
    in_plane[0][1] = s(0, 1);
    return in_plane;
  }

  /**
   * The other way: the 3-D strain of the law's stress (s, s_zz) by the
   * compliance, turned back to x-y, against e (and eps_zz = 0 in
   * @p plane_strain): whether it agrees to 1e-12.
   */
  bool
  strain_back(const OrthotropicConstants &o,
              const double                degrees,
              const Strain               &s,
              const double                s_zz,
              const Strain               &e,
              const bool                  plane_strain)
  {
    const FullMatrix<double> Q     = rotation3(degrees);
    const Vector<double>     sigma = voigt(turn(embed(s, s_zz), Q, true), 1.);
    Vector<double>           eps(6);
    compliance(o).vmult(eps, sigma);
    const FullMatrix<double> eps_xy = turn(tensor(eps, 2.), Q, false);
    Strain                   in_plane;
    in_plane[0][0] = eps_xy(0, 0), in_plane[1][1] = eps_xy(1, 1),
    in_plane[0][1] = eps_xy(0, 1);
    return close(in_plane, e, 1e-12) && std::abs(eps_xy(0, 2)) < 1e-15 &&
           (!plane_strain || std::abs(eps_xy(2, 2)) <= 1e-12 * e.norm());
  }

  /// The eigenvalues of the Mandel matrix of @p C (LAPACK), ascending.
  std::vector<double>
  mandel_eigenvalues(const SymmetricTensor<4, 2> &C)
  {
    const unsigned int       i[3] = {0, 1, 0}, j[3] = {0, 1, 1};
    const double             f[3] = {1, 1, std::sqrt(2.)};
    LAPACKFullMatrix<double> M(3, 3);
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        M(a, b) = f[a] * f[b] * C[i[a]][j[a]][i[b]][j[b]];
    M.compute_eigenvalues();
    std::vector<double> lambda;
    for (unsigned int a = 0; a < 3; ++a)
      lambda.push_back(M.eigenvalue(a).real());
    std::sort(lambda.begin(), lambda.end());
    return lambda;
  }

  /**
   * Symmetric and positive definite, energy_norm_scale() the smallest
   * Mandel eigenvalue (and @p expected_scale when > 0), add_stiffness() the
   * bilinear form.
   */
  void
  check_tangent(const ElasticLaw &law, const double expected_scale)
  {
    const SymmetricTensor<4, 2> C         = law.tangent();
    bool                        symmetric = true;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            symmetric = symmetric && std::abs(C[i][j][k][l] - C[k][l][i][j]) <=
                                       1e-14 * C.norm();
    const std::vector<double> lambda = mandel_eigenvalues(C);
    check("tangent symmetric (C_ijkl = C_klij)", symmetric);
    check("tangent positive definite (Mandel eigenvalues > 0)",
          lambda[0] > 1e-12 * lambda[2]);
    check("energy_norm_scale() = smallest Mandel eigenvalue (1e-12)",
          close(law.energy_norm_scale(), lambda[0], 1e-12));
    if (expected_scale > 0)
      check("energy_norm_scale() = 2 mu (1e-12)",
            close(law.energy_norm_scale(), expected_scale, 1e-12));
    const std::vector<Strain> e = strains();
    FullMatrix<double>        K(3, 3);
    law.add_stiffness(e, 0.5, K);
    bool same = true;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = a; b < 3; ++b)
        {
          const double tol  = 1e-14 * C.norm() * e[a].norm() * e[b].norm();
          const double form = law.bilinear_form(e[a], e[b]);
          same              = same && std::abs(K(a, b) - 0.5 * form) <= tol &&
                 std::abs(form - law.stress(e[a]) * e[b]) <= tol;
        }
    check("add_stiffness() = bilinear_form() * JxW = stress : eps", same);
  }

  LayerMaterial
  orthotropic(const OrthotropicConstants &o,
              const PlaneState            state,
              const double                angle)
  {
    LayerMaterial m;
    m.law               = MaterialLaw::orthotropic;
    m.plane_state       = state;
    m.orthotropic       = o;
    m.orientation_angle = angle;
    return m;
  }

  OrthotropicConstants
  isotropic_constants(const double E, const double nu)
  {
    OrthotropicConstants o;
    o.E_1 = o.E_2 = o.E_3 = E;
    o.nu_12 = o.nu_13 = o.nu_23 = nu;
    o.G_12                      = E / (2 * (1 + nu));
    return o;
  }


  void
  isotropic_as_orthotropic_and_anisotropic()
  {
    for (const auto &[E, nu] : {std::pair{200., 0.28}, std::pair{112., 0.32}})
      {
        const IsotropicPlaneStrain iso(E, nu);
        const double               mu     = E / (2 * (1 + nu));
        const double               lambda = 2 * nu * mu / (1 - 2 * nu);
        std::cout << "Isotropic E = " << E << ", nu = " << nu
                  << " (mu = " << std::setprecision(8) << mu
                  << ", lambda = " << lambda << ")\n";
        for (const double angle : {0., 30., 77.})
          {
            const auto law = make_elastic_law(orthotropic(
              isotropic_constants(E, nu), PlaneState::plane_strain, angle));
            bool       zz  = true;
            for (const Strain &e : strains())
              zz = zz && close(law->out_of_plane_stress(e),
                               iso.out_of_plane_stress(e),
                               1e-12);
            std::cout << " orthotropic plane strain at " << angle
                      << " degrees\n";
            check("tangent = IsotropicPlaneStrain's (1e-12)",
                  close(law->tangent(), iso.tangent(), 1e-12));
            check("sigma_zz = IsotropicPlaneStrain's (1e-12)", zz);
            check("no load constants", law->load_constants().empty());
            check_tangent(*law, nu >= 0 ? 2 * mu : 0);
            LayerMaterial stress_state(E, nu);
            stress_state.plane_state = PlaneState::plane_stress;
            const auto plane_stress  = make_elastic_law(orthotropic(
              isotropic_constants(E, nu), PlaneState::plane_stress, angle));
            check("plane stress: tangent = isotropic plane stress's (1e-12)",
                  close(plane_stress->tangent(),
                        make_elastic_law(stress_state)->tangent(),
                        1e-12));
          }
        LayerMaterial m;
        m.law          = MaterialLaw::anisotropic;
        m.stiffness    = {{lambda + 2 * mu, lambda, 0, lambda + 2 * mu, 0, mu}};
        const auto law = make_elastic_law(m);
        std::cout << " anisotropic with the isotropic plane-strain stiffness\n";
        check("tangent = IsotropicPlaneStrain's (1e-12)",
              close(law->tangent(), iso.tangent(), 1e-12));
        check("sigma_zz not defined (NaN)",
              std::isnan(law->out_of_plane_stress(strains()[0])));
        check("no load constants", law->load_constants().empty());
        check_tangent(*law, 2 * mu);
      }
  }


  void
  anisotropic_voigt()
  {
    // A positive definite stiffness with shear coupling.
    const double  c[6] = {180, 40, 12, 90, -7, 35};
    LayerMaterial m;
    m.law = MaterialLaw::anisotropic;
    std::copy(c, c + 6, m.stiffness.begin());
    const auto law = make_elastic_law(m);
    bool       ok  = true;
    for (const Strain &e : strains())
      {
        const double g = 2 * e[0][1];
        Strain       s;
        s[0][0] = c[0] * e[0][0] + c[1] * e[1][1] + c[2] * g;
        s[1][1] = c[1] * e[0][0] + c[3] * e[1][1] + c[4] * g;
        s[0][1] = c[2] * e[0][0] + c[4] * e[1][1] + c[5] * g;
        ok      = ok && close(law->stress(e), s, 1e-14);
      }
    std::cout << "Anisotropic C11, C12, C16, C22, C26, C66 = 180, 40, 12, 90, "
                 "-7, 35\n";
    check("(s11, s22, s12) = C (e11, e22, 2 e12) (1e-14)", ok);
    check("sigma_zz not defined (NaN)",
          std::isnan(law->out_of_plane_stress(strains()[1])));
    check_tangent(*law, 0);
  }


  void
  isotropic_plane_stress()
  {
    for (const auto &[E, nu] :
         {std::pair{200., 0.28}, std::pair{70., 0.5}, std::pair{10., -0.3}})
      {
        LayerMaterial m(E, nu);
        m.plane_state  = PlaneState::plane_stress;
        const auto law = make_elastic_law(m);
        bool       ok = true, zz = true;
        for (const Strain &e : strains())
          {
            const double a = E / (1 - nu * nu);
            Strain       s;
            s[0][0] = a * (e[0][0] + nu * e[1][1]);
            s[1][1] = a * (e[1][1] + nu * e[0][0]);
            s[0][1] = a * (1 - nu) * e[0][1];
            ok      = ok && close(law->stress(e), s, 1e-14);
            zz      = zz && law->out_of_plane_stress(e) == 0;
          }
        const double mu = E / (2 * (1 + nu));
        const auto   k  = law->load_constants();
        const bool   constants =
          k.size() == (nu < 0.5 ? 4u : 3u) && k.at("E") == E &&
          k.at("nu") == nu && close(k.at("mu"), mu, 1e-15) &&
          (nu == 0.5 ||
           close(k.at("lambda"), 2 * nu * mu / (1 - 2 * nu), 1e-15));
        std::cout << "Isotropic plane stress E = " << E << ", nu = " << nu
                  << "\n";
        check("stress = E/(1-nu^2) [e11 + nu e22, e22 + nu e11, (1-nu) e12] "
              "(1e-14)",
              ok);
        check("sigma_zz = 0", zz);
        check(nu < 0.5 ? "load constants E, nu, mu, lambda (3-D)" :
                         "load constants E, nu, mu (lambda infinite)",
              constants);
        check_tangent(*law, nu >= 0 ? 2 * mu : 0);
      }
  }


  void
  orthotropic_against_3d()
  {
    OrthotropicConstants o;
    o.E_1 = 140, o.E_2 = 10, o.E_3 = 12;
    o.nu_12 = 0.3, o.nu_13 = 0.28, o.nu_23 = 0.45, o.G_12 = 5;
    const double angle = 37;
    std::cout << "Orthotropic E_1, E_2, E_3 = 140, 10, 12, nu_12, nu_13, "
                 "nu_23 = 0.3, 0.28, 0.45, G_12 = 5 at 37 degrees\n";
    for (const PlaneState state :
         {PlaneState::plane_strain, PlaneState::plane_stress})
      {
        const bool strain = state == PlaneState::plane_strain;
        const auto law    = make_elastic_law(orthotropic(o, state, angle));
        bool       stress = true, zz = true, back = true;
        for (const Strain &e : strains())
          {
            const Strain s    = law->stress(e);
            const double s_zz = law->out_of_plane_stress(e);
            if (strain)
              {
                const auto [s3, s3_zz] = plane_strain_3d(o, angle, e);
                stress                 = stress && close(s, s3, 1e-12);
                zz = zz && std::abs(s_zz - s3_zz) <= 1e-12 * s3.norm();
              }
            else
              {
                stress =
                  stress && close(s, plane_stress_3d(o, angle, e), 1e-12);
                zz = zz && s_zz == 0;
              }
            back = back && strain_back(o, angle, s, s_zz, e, strain);
          }
        std::cout << (strain ? " plane strain\n" : " plane stress\n");
        check(strain ? "stress = the 3-D stress with eps_zz = 0 (1e-12)" :
                       "stress = the 3-D stress with s_zz = 0 (1e-12)",
              stress);
        check(strain ? "sigma_zz = the 3-D s_zz (1e-12)" : "sigma_zz = 0", zz);
        check(strain ? "compliance of (s, sigma_zz) = (e, eps_zz = 0) (1e-12)" :
                       "compliance of (s, 0) = e in the plane (1e-12)",
              back);
        check("no load constants", law->load_constants().empty());
        check_tangent(*law, 0);

        // Objectivity: C(angle)(R e R^T) = R (C(0) e) R^T.
        const auto   law0 = make_elastic_law(orthotropic(o, state, 0));
        const double a    = angle * numbers::PI / 180;
        Tensor<2, 2> R;
        R[0][0] = std::cos(a), R[0][1] = -std::sin(a);
        R[1][0] = std::sin(a), R[1][1] = std::cos(a);
        bool objective = true;
        for (const Strain &e : strains())
          {
            const Strain turned =
              symmetrize(Tensor<2, 2>(R * Tensor<2, 2>(e) * transpose(R)));
            const Strain expected = symmetrize(
              Tensor<2, 2>(R * Tensor<2, 2>(law0->stress(e)) * transpose(R)));
            objective =
              objective && close(law->stress(turned), expected, 1e-12) &&
              std::abs(law->out_of_plane_stress(turned) -
                       law0->out_of_plane_stress(e)) <= 1e-12 * expected.norm();
          }
        check("objectivity: C(37)(R e R^T) = R (C(0) e) R^T, sigma_zz "
              "alike (1e-12)",
              objective);
      }
  }

  /// Thermal strains: dT [K].
  const double dT = 85;


  /// plane_eigenstrain() of isotropic laws against the closed forms.
  void
  thermal_isotropic()
  {
    const double alpha = 1.2e-5;
    for (const auto &[E, nu] : {std::pair{200., 0.28}, std::pair{70., 0.33}})
      for (const PlaneState state :
           {PlaneState::plane_strain, PlaneState::plane_stress})
        {
          const bool    strain = state == PlaneState::plane_strain;
          LayerMaterial m(E, nu);
          m.plane_state          = state;
          m.thermal_expansion[0] = alpha;
          const auto    law      = make_elastic_law(m);
          Eigenstrain3D eps3;
          eps3.in_plane            = alpha * dT * unit_symmetric_tensor<2>();
          eps3.zz                  = alpha * dT;
          const PlaneEigenstrain p = law->plane_eigenstrain(eps3);
          const Strain           expected =
            (strain ? 1 + nu : 1.) * alpha * dT * unit_symmetric_tensor<2>();
          const double offset = strain ? -E * alpha * dT : 0.;
          // thermal_strain() per kelvin, times dT, gives the same.
          const Eigenstrain3D per_kelvin = thermal_strain(m);
          const bool          material =
            close(dT * per_kelvin.in_plane, eps3.in_plane, 1e-15) &&
            close(dT * per_kelvin.zz, eps3.zz, 1e-15);
          std::cout << "Thermal strain alpha dT = 1.2e-5 * 85, isotropic E = "
                    << E << ", nu = " << nu
                    << (strain ? ", plane strain\n" : ", plane stress\n");
          check(strain ? "eps*_eff = (1 + nu) alpha dT I (1e-12)" :
                         "eps*_eff = alpha dT I (1e-12)",
                close(p.in_plane, expected, 1e-12));
          check(strain ? "sigma_zz offset = -E alpha dT (1e-12)" :
                         "sigma_zz offset = 0",
                strain ? close(p.sigma_zz_offset, offset, 1e-12) :
                         p.sigma_zz_offset == 0);
          check("thermal_strain() = alpha I, eps_zz = alpha (per kelvin)",
                material);
        }
  }


  /**
   * plane_eigenstrain() of an orthotropic law at 37 degrees against the
   * 3-D thermoelastic stress computed here.
   */
  void
  thermal_orthotropic()
  {
    OrthotropicConstants o;
    o.E_1 = 140, o.E_2 = 10, o.E_3 = 12;
    o.nu_12 = 0.3, o.nu_13 = 0.28, o.nu_23 = 0.45, o.G_12 = 5;
    const double             angle = 37;
    const double             a[3]  = {0.4e-5, 2.5e-5, 3.1e-5};
    const FullMatrix<double> Q     = rotation3(angle);
    // The thermal strain diag(alpha) dT in the material axes, and in x-y.
    FullMatrix<double> th_material(3, 3);
    for (unsigned int i = 0; i < 3; ++i)
      th_material(i, i) = a[i] * dT;
    const FullMatrix<double> th_xy = turn(th_material, Q, false);
    std::cout << "Thermal strain of the orthotropic layer at 37 degrees, "
                 "alpha_1, alpha_2, alpha_3 = 0.4e-5, 2.5e-5, 3.1e-5, dT = "
                 "85\n";
    for (const PlaneState state :
         {PlaneState::plane_strain, PlaneState::plane_stress})
      {
        const bool    strain     = state == PlaneState::plane_strain;
        LayerMaterial m          = orthotropic(o, state, angle);
        m.thermal_expansion      = {{a[0], a[1], a[2]}};
        const auto          law  = make_elastic_law(m);
        const Eigenstrain3D per  = thermal_strain(m);
        Eigenstrain3D       eps3 = per;
        eps3.in_plane *= dT;
        eps3.zz *= dT;
        const PlaneEigenstrain p     = law->plane_eigenstrain(eps3);
        const double           scale = o.E_2 * a[1] * dT;
        // thermal_strain(): R diag(alpha_1, alpha_2) R^T, alpha_3 along z.
        Strain th_plane;
        th_plane[0][0] = th_xy(0, 0), th_plane[1][1] = th_xy(1, 1),
        th_plane[0][1]      = th_xy(0, 1);
        const bool material = close(eps3.in_plane, th_plane, 1e-14) &&
                              close(eps3.zz, a[2] * dT, 1e-14);
        std::cout << (strain ? " plane strain\n" : " plane stress\n");
        check("thermal_strain() = R diag(alpha_1, alpha_2) R^T, alpha_3 "
              "along z",
              material);
        if (strain)
          {
            // The s_zz alone that keeps eps_zz = 0: S_33 s + alpha_3 dT = 0
            // (a rotation about z leaves S_33 and s_zz as they are).
            const FullMatrix<double> S = compliance(o);
            const double             s = -a[2] * dT / S(2, 2);
            Vector<double>           sigma(6), eps(6);
            sigma(2) = s;
            S.vmult(eps, sigma);
            FullMatrix<double> total = tensor(eps, 2.);
            total.add(1., th_material);
            const FullMatrix<double> total_xy = turn(total, Q, false);
            Strain                   eff;
            eff[0][0] = total_xy(0, 0), eff[1][1] = total_xy(1, 1),
            eff[0][1] = total_xy(0, 1);
            check("eps*_eff = S_p3 s_zz + eps_th,p turned to x-y, s_zz = "
                  "-alpha_3 dT / S_33 (1e-12)",
                  close(p.in_plane, eff, 1e-12) &&
                    std::abs(total(2, 2)) <= 1e-12 * a[2] * dT);
            check("sigma_zz offset = -alpha_3 dT / S_33 (1e-12)",
                  close(p.sigma_zz_offset, s, 1e-12));
            // The 3-D stress K (eps - eps_th) of (e, eps_zz = 0).
            FullMatrix<double> K = S;
            K.gauss_jordan();
            bool                stress = true, zz = true;
            const Strain        zero;
            std::vector<Strain> es = strains();
            es.insert(es.begin(), zero);
            for (const Strain &e : es)
              {
                FullMatrix<double> mech = turn(embed(e, 0), Q, true);
                mech.add(-1., th_material);
                const Vector<double> eps_m = voigt(mech, 2.);
                Vector<double>       sigma3(6);
                K.vmult(sigma3, eps_m);
                const FullMatrix<double> s3 =
                  turn(tensor(sigma3, 1.), Q, false);
                Strain in_plane;
                in_plane[0][0] = s3(0, 0), in_plane[1][1] = s3(1, 1),
                in_plane[0][1]  = s3(0, 1);
                const Strain ls = law->stress(e - p.in_plane);
                const double lzz =
                  law->out_of_plane_stress(e - p.in_plane) + p.sigma_zz_offset;
                stress = stress && (ls - in_plane).norm() <=
                                     1e-12 * std::max(in_plane.norm(), scale);
                zz = zz && std::abs(lzz - s3(2, 2)) <=
                             1e-12 * std::max(std::abs(s3(2, 2)), scale);
              }
            check("stress C (e - eps*_eff) = the 3-D K (eps - eps_th), "
                  "eps_zz = 0, for e = 0 and the test strains (1e-12)",
                  stress);
            check("sigma_zz Z : (e - eps*_eff) + offset = the 3-D s_zz "
                  "(1e-12)",
                  zz);
          }
        else
          {
            check("eps*_eff = the in-plane thermal strain in x-y (1e-12)",
                  close(p.in_plane, th_plane, 1e-12));
            check("sigma_zz offset = 0", p.sigma_zz_offset == 0);
          }
      }
  }


  /// Anisotropic: the given in-plane tensor per kelvin, no offset.
  void
  thermal_anisotropic()
  {
    LayerMaterial m;
    m.law                   = MaterialLaw::anisotropic;
    m.stiffness             = {{200, 60, 10, 150, -8, 45}};
    m.thermal_expansion     = {{1.1e-5, 2.3e-5, -0.4e-5}};
    const auto          law = make_elastic_law(m);
    const Eigenstrain3D per = thermal_strain(m);
    Strain              given;
    given[0][0] = 1.1e-5 * dT, given[1][1] = 2.3e-5 * dT,
    given[0][1]        = -0.4e-5 * dT;
    Eigenstrain3D eps3 = per;
    eps3.in_plane *= dT;
    const PlaneEigenstrain p = law->plane_eigenstrain(eps3);
    std::cout << "Thermal strain of an anisotropic layer (alpha_11, alpha_22, "
                 "alpha_12 = 1.1e-5, 2.3e-5, -0.4e-5), dT = 85\n";
    check("eps*_eff = the given tensor times dT, eps_zz = 0 (1e-14)",
          close(p.in_plane, given, 1e-14) && per.zz == 0);
    check("sigma_zz offset = 0", p.sigma_zz_offset == 0);
  }
} // namespace


int
main()
{
  std::cout << std::setprecision(8);
  isotropic_as_orthotropic_and_anisotropic();
  anisotropic_voigt();
  isotropic_plane_stress();
  orthotropic_against_3d();
  thermal_isotropic();
  thermal_orthotropic();
  thermal_anisotropic();
}
