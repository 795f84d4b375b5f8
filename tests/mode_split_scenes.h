#ifndef bilayer_tests_mode_split_scenes_h
#define bilayer_tests_mode_split_scenes_h

// The scene of the mode split tests (mode_split_griffith,
// mode_split_convergence, mode_split_bimaterial): the uniform-state Griffith
// crack of friction_scenes.h under a normal stress and a shear on the crack
// line, adaptive Q2 from 20 cells along Sigma with the tips fitted to
// vertices, active set to 1e-10.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "friction_scenes.h"

namespace mode_split_scenes
{
  /// The crack (-a, a) in (-1, 1)^2, one layer (E, nu), the displacement of
  /// the uniform state sigma_yy = @p sigma_n (tension positive), sigma_xy =
  /// @p tau on the whole boundary; @p contact: non-penetration on the
  /// crack; @p extra: more subsections (Fracture, Materials sides).
  inline std::string
  griffith(const double       a,
           const double       E,
           const double       nu,
           const double       sigma_n,
           const double       tau,
           const bool         contact,
           const unsigned int cycles,
           const std::string &extra = "")
  {
    std::ostringstream s;
    s << std::setprecision(17)
      << friction_scenes::uniform_state_griffith(a, E, nu, -sigma_n, tau)
      << "subsection Mesh\n set Cells along Sigma = 20\n"
      << " set Fit crack tips = true\n"
      << " set Polynomial degree of layer 1 = 2\n"
      << " set Refinement = adaptive\n set Refinement fraction = 0.8\n"
      << " set Number of cycles = " << cycles << "\nend\n"
      << "subsection Contact\n set Non-penetration on the crack = "
      << (contact ? "true" : "false") << "\nend\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-10\nend\n"
      << extra << "subsection Output\n set Output directory = results\n"
      << " set Write VTU = false\n set Write interface CSV = false\n"
      << " set Terminal output = checks\nend\n";
    return s.str();
  }

  /// (1 - nu^2) pi a t^2 / E: G of the Griffith crack (-a, a) in the
  /// infinite plane-strain plate under the remote traction t on its line
  /// (normal: mode I, shear: mode II).
  inline double
  infinite_plate(const double a,
                 const double E,
                 const double nu,
                 const double t)
  {
    return (1 - nu * nu) * M_PI * a * t * t / E;
  }
} // namespace mode_split_scenes

#endif
