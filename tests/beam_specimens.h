#ifndef bilayer_tests_beam_specimens_h
#define bilayer_tests_beam_specimens_h

// The shipped fracture specimens parameter_files/dcb.prm and els.prm
// (docs/fracture.md, "Fracture specimens: DCB and ELS") run at a given
// crack length: the scene of the file with the crack (0, a), the cycles
// given and no files written.

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace beam_specimens
{
  using namespace bilayer;

  /// The scenes' constants: E = 1, nu = 0.3 (plane strain), the arm height
  /// h = 1, the force P = 1e-3, unit thickness.
  constexpr double E = 1, nu = 0.3, h = 1, P = 1e-3;
  /// The plane-strain modulus E' = E / (1 - nu^2).
  constexpr double E_prime = E / (1 - nu * nu);
  /// Kanninen's root rotation of an arm on an elastic foundation: the crack
  /// length correction chi h, chi = 6^(-1/4).
  inline double
  chi()
  {
    return std::pow(6., -0.25);
  }

  /// What the tests read from the last cycle of a run.
  struct Result
  {
    bool   accepted = false;
    bool   one_tip  = false; // one tip, at x = a, growing towards +x
    double G = std::nan(""), G_I = std::nan(""), G_II = std::nan("");
    double energy = std::nan("");
    /// The interface nodes on the crack (the mouth included).
    std::vector<InterfaceNode> crack;
    /// [u].tau at the mouth (x = 0).
    double mouth_sliding = std::nan("");
  };

  /// Runs parameter_files/@p file with the crack (0, @p a) on @p cycles
  /// adaptive cycles.
  inline Result
  run(const std::string &file, const double a, const unsigned int cycles)
  {
    std::ifstream in(std::string(SOURCE_DIR) + "/../parameter_files/" + file);
    std::ostringstream text;
    text << std::setprecision(17) << in.rdbuf()
         << "subsection Geometry\n set Crack interval on Sigma = 0, " << a
         << "\nend\nsubsection Mesh\n set Number of cycles = " << cycles
         << "\nend\nsubsection Output\n set Output directory = results\n"
            " set Write VTU = false\n set Write interface CSV = false\n"
            " set Progress interval = 0\n set Terminal output = checks\nend\n";
    std::ostringstream sink;
    Study  study(scene_from_string(text.str(), "beam_specimens"), sink);
    Result r;
    r.accepted = study.run();
    if (!r.accepted)
      return r;
    const auto &record = study.records().back();
    r.energy           = record.energy;
    r.one_tip          = record.release.size() == 1 &&
                std::abs(record.release[0].tip.point[0] - a) < 1e-12 &&
                record.release[0].tip.direction[0] == 1;
    if (r.one_tip)
      {
        r.G    = record.release[0].G;
        r.G_I  = record.release[0].G_I;
        r.G_II = record.release[0].G_II;
      }
    for (const InterfaceNode &n : interface_nodes(study.interface(),
                                                  study.solutions(),
                                                  study.multipliers()))
      if (n.on_crack)
        {
          r.crack.push_back(n);
          if (n.point[0] == 0)
            r.mouth_sliding = n.jump_tangential;
        }
    return r;
  }
} // namespace beam_specimens

#endif
