// Example 1 (parameter_files/partial_closure.prm, one cycle of 8 cells
// along Sigma, the active set at KKT 1e-10) with the same materials stated
// by three laws: isotropic (the paper's E, nu), orthotropic with isotropic
// constants (E_i = E, nu_ij = nu, G_12 = E / (2 (1 + nu))) at 30 degrees,
// and anisotropic with the isotropic plane-strain stiffness (C11 = C22 =
// lambda + 2 mu, C12 = lambda, C66 = mu). An isotropic tensor does not
// change under rotation, so the three describe one discrete problem: the
// accepted runs' energies agree to 1e-10 relative (their tangents differ
// in the last bits). The load is c = 1e-3 mu1 written as its value
// 0.078125 (mu1 = 200 / 2.56 = 78.125): the load expressions know the
// material constants of isotropic layers only. The printed energy, rounded
// to 7 digits, is not this program's: it is that of the independent
// monolithic solver of tests/prm_references.cc for this discrete problem
// (tests/partial_closure.prm, whose .output holds it: -6.6695252e-6).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

using namespace bilayer;

namespace
{
  struct Layer
  {
    double E, nu;
  };
  const Layer layers[2] = {{200, 0.28}, {112, 0.32}};

  /// The Materials subsection of the law @p law.
  std::string
  materials(const std::string &law)
  {
    std::ostringstream s;
    s << std::setprecision(17) << "subsection Materials\n";
    for (unsigned int l = 0; l < 2; ++l)
      {
        const double E = layers[l].E, nu = layers[l].nu;
        const double mu     = E / (2 * (1 + nu));
        const double lambda = 2 * nu * mu / (1 - 2 * nu);
        s << " subsection Layer " << l + 1 << "\n  set Law = " << law << "\n";
        if (law == "orthotropic")
          s << "  set E_1 = " << E << "\n  set E_2 = " << E
            << "\n  set E_3 = " << E << "\n  set nu_12 = " << nu
            << "\n  set nu_13 = " << nu << "\n  set nu_23 = " << nu
            << "\n  set G_12 = " << mu << "\n  set Orientation angle = 30\n";
        if (law == "anisotropic")
          s << "  set Stiffness = " << lambda + 2 * mu << ", " << lambda
            << ", 0, " << lambda + 2 * mu << ", 0, " << mu << "\n";
        s << " end\n";
      }
    s << "end\n";
    return s.str();
  }

  /// The energy of the run, NaN unless accepted.
  double
  energy(const std::string &law)
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/partial_closure.prm");
    std::ostringstream text;
    text << in.rdbuf() << materials(law)
         << "subsection Loads\n set Constants = c = 0.078125\nend\n"
            "subsection Mesh\n set Cells along Sigma = 8\n"
            " set Number of cycles = 1\nend\n"
            "subsection Solver\n set Method = active set\n"
            " set Tolerance = 1e-10\nend\n"
            "subsection Output\n set Output directory = results\n"
            " set Write VTU = false\n set Write interface CSV = false\n"
            " set Progress interval = 0\n set Terminal output = checks\nend\n";
    std::ostringstream quiet;
    Study study(scene_from_string(text.str(), "partial_closure_" + law), quiet);
    const bool accepted = study.run();
    return accepted ? study.records().back().energy : std::nan("");
  }
} // namespace


int
main()
{
  const double isotropic = energy("isotropic");
  std::cout << "isotropic: accepted: " << yes(std::isfinite(isotropic))
            << ", energy Pi [10^-6]: " << std::fixed << std::setprecision(6)
            << isotropic * 1e6 << std::endl;
  for (const std::string law : {"orthotropic", "anisotropic"})
    {
      const double e = energy(law);
      std::cout << law << ": accepted: " << yes(std::isfinite(e))
                << ", energy Pi [10^-6]: " << e * 1e6 << std::endl
                << law << ": energy = the isotropic law's (1e-10 relative): "
                << yes(std::abs(e - isotropic) <= 1e-10 * std::abs(isotropic))
                << std::endl;
    }
}
