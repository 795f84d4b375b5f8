// used_parameters.prm comments out the entries a scene does not use
// (parameters/scene.cc, applicable_entries). "Not used" is checked here
// against the solutions, not against the rule that made the comments: for
// each law and plane state of layer 1 (and a layer whose sides differ),
// every material entry of the layer is changed by itself; the energy of
// the accepted run must stay bit-identical exactly where the entry was
// commented out, and change where it was kept. A one-layer scene comments
// out every entry of layer 2.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "verdict.h"

using namespace bilayer;

namespace
{
  const std::string common =
    "subsection Loads\n set Constants = c = 0.078125\nend\n"
    "subsection Mesh\n set Cells along Sigma = 8\n set Number of cycles = 1\n"
    "end\n"
    "subsection Solver\n set Method = active set\n set Tolerance = 1e-10\nend\n"
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Progress interval = 0\n set Terminal output = checks\nend\n";

  /// Orthotropic constants far from isotropy (every entry matters).
  const std::string orthotropic =
    "  set E_1 = 200\n  set E_2 = 90\n  set E_3 = 120\n  set nu_12 = 0.25\n"
    "  set nu_13 = 0.3\n  set nu_23 = 0.35\n  set G_12 = 40\n"
    "  set Orientation angle = 20\n";

  /// Another admissible value of each material entry.
  const std::map<std::string, std::string> changed = {
    {"Young's modulus", "230"},
    {"Poisson's ratio", "0.2"},
    {"E_1", "210"},
    {"E_2", "95"},
    {"E_3", "150"},
    {"nu_12", "0.2"},
    {"nu_13", "0.25"},
    {"nu_23", "0.3"},
    {"G_12", "45"},
    {"Orientation angle", "35"},
    {"Stiffness", "260, 90, 10, 240, 5, 70"},
    {"Thermal expansion", "2e-5"},
    {"Plane state", "@"}};

  std::string
  base_text()
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/partial_closure.prm");
    std::ostringstream text;
    text << in.rdbuf() << common;
    return text.str();
  }

  double
  energy(const std::string &text)
  {
    std::ostringstream quiet;
    Study              study(scene_from_string(text, "used_entries"), quiet);
    study.run();
    const auto &record = study.records().back();
    return record.accepted() ? record.energy : std::nan("");
  }

  /// used_parameters.prm of the scene @p text.
  std::string
  used_entries(const std::string &text)
  {
    const std::string file = "used_entries.prm";
    std::ofstream(file) << text;
    dealii::ParameterHandler prm;
    const Scene              scene = read_scene(prm, file);
    std::ostringstream       entries;
    prm.print_parameters(entries, dealii::ParameterHandler::ShortPRM);
    return applicable_entries(entries.str(), scene);
  }

  /// Layer 1 given by @p layer (its entries) and @p sides (its side
  /// subsections): does each entry change the energy exactly when kept?
  void
  check(const std::string &name,
        const std::string &layer,
        const std::string &plane,
        const std::string &sides = "",
        const std::string &loads = "")
  {
    const auto materials = [&](const std::string &extra) {
      return "subsection Materials\n subsection Layer 1\n" + layer +
             "  set Plane state = " + plane + "\n" + extra + sides +
             " end\nend\n" + loads;
    };
    const std::string text      = base_text() + materials("");
    const std::string used      = used_entries(text);
    const double      reference = energy(text);
    unsigned int      kept = 0, commented = 0, wrong = 0;
    for (const auto &[entry, value] : changed)
      {
        const std::string v =
          value != "@" ?
            value :
            (plane == "plane strain" ? "plane stress" : "plane strain");
        const double e =
          energy(base_text() + materials("  set " + entry + " = " + v + "\n"));
        const bool is_commented =
          used.find("# Materials/Layer 1/" + entry + ":") != std::string::npos;
        (is_commented ? commented : kept) += 1;
        if (is_commented != (e == reference))
          {
            ++wrong;
            std::cout << "  " << entry << ": "
                      << (is_commented ? "commented out" : "kept")
                      << ", energy " << (e == reference ? "same" : "changed")
                      << std::endl;
          }
      }
    std::cout << name << ": " << kept << " entries kept, " << commented
              << " commented out; each changes the energy exactly when kept: "
              << yes(wrong == 0 && std::isfinite(reference)) << std::endl;
  }
} // namespace


int
main()
{
  check("isotropic, plane strain", "  set Law = isotropic\n", "plane strain");
  check("isotropic, plane stress", "  set Law = isotropic\n", "plane stress");
  check("orthotropic, plane strain",
        "  set Law = orthotropic\n" + orthotropic,
        "plane strain");
  check("orthotropic, plane stress",
        "  set Law = orthotropic\n" + orthotropic,
        "plane stress");
  check("anisotropic", "  set Law = anisotropic\n", "plane strain");
  check("isotropic, plane strain, cooled by 100 K (alpha = 1e-5)",
        "  set Law = isotropic\n  set Thermal expansion = 1e-5\n",
        "plane strain",
        "",
        "subsection Loads\n set Temperature change = -100\nend\n");
  check("orthotropic below Sigma, isotropic above",
        "  set Law = orthotropic\n" + orthotropic,
        "plane strain",
        "  subsection Omega+\n   set Law = isotropic\n"
        "   set Young's modulus = 150\n  end\n");

  // One layer (the Griffith scene): no entry of layer 2 is kept.
  dealii::ParameterHandler prm;
  const Scene              griffith =
    read_scene(prm,
               std::string(SOURCE_DIR) + "/../parameter_files/griffith.prm");
  std::ostringstream entries;
  prm.print_parameters(entries, dealii::ParameterHandler::ShortPRM);
  std::istringstream       in(applicable_entries(entries.str(), griffith));
  std::vector<std::string> sections;
  unsigned int             kept = 0, commented = 0;
  for (std::string line; std::getline(in, line);)
    {
      const auto first = line.find_first_not_of(' ');
      if (first == std::string::npos)
        continue;
      const std::string trimmed = line.substr(first);
      if (trimmed.rfind("subsection ", 0) == 0)
        sections.push_back(trimmed.substr(11));
      else if (trimmed == "end")
        sections.pop_back();
      else if (trimmed.rfind("set ", 0) == 0 && !sections.empty() &&
               (sections.size() > 1 && sections[1] == "Layer 2"))
        ++kept;
      else if (trimmed.rfind("# Materials/Layer 2/", 0) == 0 ||
               trimmed.rfind("# Loads/Layer 2/", 0) == 0)
        ++commented;
    }
  std::cout << "one layer: every entry of layer 2 commented out: "
            << yes(kept == 0 && commented > 0) << std::endl;
}
