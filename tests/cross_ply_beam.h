#ifndef bilayer_tests_cross_ply_beam_h
#define bilayer_tests_cross_ply_beam_h

// Corrected beam theory of the [0/90/0] cross-ply double cantilever beam
// (parameter_files/cross_ply_dcb.prm, tests/cross_ply_dcb.geo): carbon/epoxy
// plies of thickness t = 1 (E_L = 140, E_T = 10, nu_LT = 0.3, nu_TT = 0.45,
// G_LT = 5, G_TT = E_T / (2 (1 + nu_TT))), plane strain, the delamination
// at the lower 0/90 interface, the force P = 1e-3 on each arm. The arms'
// bending stiffness from classical lamination (D_1 = E'_0 t^3 / 12; the
// upper [90/0] arm D_2 = D - B^2 / A about its neutral axis) and each
// arm's root rotation (Williams' elastic-foundation correction):
//   G = P^2 / 2 ((a + Delta_1)^2 / D_1 + (a + Delta_2)^2 / D_2).

#include <cmath>

namespace cross_ply_beam
{
  /// The plane-strain modulus along material axis 1 of a ply whose axes
  /// 1, 3 have the moduli E_1, E_3 and Poisson's ratio nu_13.
  double
  plane_strain_modulus(const double E1, const double nu13, const double E3)
  {
    return 1 / (1 / E1 - nu13 * nu13 / (E1 * E1) * E3);
  }

  /// Williams' root-rotation factor chi of an orthotropic arm.
  double
  chi(const double E11, const double E22, const double G13)
  {
    const double Gamma = 1.18 * std::sqrt(E11 * E22) / G13;
    const double r     = Gamma / (1 + Gamma);
    return std::sqrt(E11 / (11 * G13) * (3 - 2 * r * r));
  }

  /// Corrected beam theory of the cross-ply DCB at crack length @p a.
  double
  cross_ply_G(const double a)
  {
    const double E_L = 140, E_T = 10, nu_LT = 0.3, G_LT = 5;
    const double G_TT = E_T / (2 * (1 + 0.45)), P = 1e-3, t = 1;
    const double E0  = plane_strain_modulus(E_L, nu_LT, E_T);
    const double E90 = plane_strain_modulus(E_T, nu_LT * E_T / E_L, E_L);
    const double D1  = E0 * t * t * t / 12;
    // The upper arm: the 90 ply on 0 < y < t, the 0 ply on t < y < 2t.
    const double A  = (E90 + E0) * t;
    const double B  = (E90 * t * t + E0 * 3 * t * t) / 2;
    const double D  = (E90 * t * t * t + E0 * 7 * t * t * t) / 3;
    const double D2 = D - B * B / A;
    const double d1 = chi(E0, E_T, G_LT) * t;
    const double d2 =
      chi(12 * D2 / (8 * t * t * t), E_T, 2 / (1 / G_TT + 1 / G_LT)) * 2 * t;
    return P * P / 2 * ((a + d1) * (a + d1) / D1 + (a + d2) * (a + d2) / D2);
  }

} // namespace cross_ply_beam

#endif
