#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/material_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    const MaterialParameters defaults;
    prm.declare_entry("Number of layers",
                      "2",
                      Patterns::Integer(1, 2),
                      "2: the two glued layers of the paper; 1: layer 2 is "
                      "absent, a single elastic body with a through crack "
                      "(only the layer-1 subproblems and the crack and "
                      "gluing multipliers are built; Materials/Layer 2 and "
                      "Loads/Layer 2 are not used) [-].");
    for (unsigned int l = 0; l < 2; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        prm.declare_entry("Young's modulus",
                          Patterns::Tools::to_string(
                            defaults.layer[l].youngs_modulus),
                          Patterns::Double(0),
                          "Young's modulus E of the layer [stress, e.g. GPa; "
                          "tractions use the same unit].");
        prm.declare_entry("Poisson's ratio",
                          Patterns::Tools::to_string(
                            defaults.layer[l].poisson_ratio),
                          Patterns::Double(-1, 0.5),
                          "Poisson's ratio nu of the layer, plane strain "
                          "[-], in (-1, 0.5).");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    n_layers = prm.get_integer("Number of layers");
    for (unsigned int l = 0; l < 2; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        layer[l].youngs_modulus = get_double(prm,
                                             "Materials/" + layer_subsection(l),
                                             "Young's modulus");
        layer[l].poisson_ratio  = get_double(prm,
                                            "Materials/" + layer_subsection(l),
                                            "Poisson's ratio");
        const std::string where = "Materials/" + layer_subsection(l) + "/";
        AssertThrow(layer[l].youngs_modulus > 0,
                    ExcMessage(where + "Young's modulus must be > 0, got " +
                               prm.get("Young's modulus")));
        AssertThrow(layer[l].poisson_ratio > -1 && layer[l].poisson_ratio < 0.5,
                    ExcMessage(where +
                               "Poisson's ratio must lie in "
                               "(-1, 0.5), got " +
                               prm.get("Poisson's ratio")));
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }
} // namespace bilayer
