#ifndef bilayer_tests_friction_scenes_h
#define bilayer_tests_friction_scenes_h

// Parameter-file text of the scenes shared by the friction tests
// (friction_griffith, friction_limits, friction_solvers, friction_mpi).

#include <iomanip>
#include <sstream>
#include <string>

namespace friction_scenes
{
  /// Example 1's loads of layer 1 with a shear traction added: (shear c,
  /// -c x) on the top and (-shear c, c x) on the bottom side, c given by
  /// @p constant.
  inline std::string
  shear_loads(const std::string &shear, const std::string &constant)
  {
    return "subsection Loads\n set Constants = c = " + constant +
           "\n subsection Layer 1\n  set Traction on top side = " + shear +
           "*c; -c*x\n  set Traction on bottom side = -" + shear +
           "*c; c*x\n end\nend\n";
  }

  /// The Griffith crack (-a, a) on Sigma in (-1, 1)^2, one layer of modulus
  /// @p E and Poisson's ratio @p nu, every side clamped to the displacement
  /// of the uniform plane-strain state sigma_yy = -sigma, sigma_xy = tau:
  /// eps_xx = nu (1 + nu) sigma / E, eps_yy = -(1 - nu^2) sigma / E,
  /// eps_xy = (1 + nu) tau / E, u = (eps_xx x + 2 eps_xy y, eps_yy y). The
  /// Geometry, Materials and Loads subsections.
  inline std::string
  uniform_state_griffith(const double a,
                         const double E,
                         const double nu,
                         const double sigma,
                         const double tau)
  {
    std::ostringstream s;
    s << std::setprecision(17) << "subsection Geometry\n"
      << " set Crack interval on Sigma = " << -a << ", " << a
      << "\n set Clamped sides = left, right, bottom, top\nend\n"
      << "subsection Materials\n set Number of layers = 1\n"
      << " subsection Layer 1\n  set Young's modulus = " << E
      << "\n  set Poisson's ratio = " << nu << "\n end\nend\n"
      << "subsection Loads\n set Constants = exx = "
      << nu * (1 + nu) * sigma / E << "; eyy = " << -(1 - nu * nu) * sigma / E
      << "; exy = " << (1 + nu) * tau / E << "\n subsection Layer 1\n"
      << "  set Prescribed displacement = exx*x + 2*exy*y; eyy*y\n end\nend\n";
    return s.str();
  }
} // namespace friction_scenes

#endif
