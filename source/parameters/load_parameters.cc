#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/expression_volume_load.h>
#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/load_parameters.h>
#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/thermal_volume_load.h>
#include <bilayer/physics/elastic_law.h>
#include <bilayer/physics/plies.h>

#include <array>
#include <cmath>
#include <map>
#include <set>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  namespace
  {
    /**
     * Why the material @p m of the layer @p l, given in the subsection
     * @p section, does not define one of the constants E, nu, mu, lambda of
     * the load expressions.
     */
    std::string
    absent_constant(const LayerMaterial &m,
                    const unsigned int   l,
                    const std::string   &section)
    {
      const std::string n = std::to_string(l + 1);
      if (m.law == MaterialLaw::isotropic)
        return "which is infinite for " + section +
               "/Poisson's ratio = 0.5 (plane stress): the loads cannot use "
               "it";
      return "a constant of isotropic layers only (E" + n + ", nu" + n +
             ", mu" + n + ", lambda" + n + "), but " + section + "/Law = " +
             (m.law == MaterialLaw::orthotropic ? "orthotropic" :
                                                  "anisotropic") +
             ": write its value as a number";
    }


    /**
     * The constants E, nu, mu, lambda of the layer @p l that both its sides
     * define alike (@p values, with the layer number), and why the others
     * are not defined (@p why_absent): a side whose law does not define
     * one, or sides whose values differ.
     */
    void
    layer_constants(const MaterialParameters           &materials,
                    const unsigned int                  l,
                    std::map<std::string, double>      &values,
                    std::map<std::string, std::string> &why_absent)
    {
      const Layer       layer   = static_cast<Layer>(l);
      const std::string n       = std::to_string(l + 1);
      const std::string section = "Materials/" + layer_subsection(l);
      if (!materials.has_layer(layer))
        {
          // An absent layer's entries are not used (used_parameters.prm
          // comments them out): nothing may depend on them.
          for (const std::string name : {"E", "nu", "mu", "lambda"})
            why_absent[name + n] = "a constant of layer " + n +
                                   ", which is absent (Materials/Number of "
                                   "layers = " +
                                   std::to_string(materials.n_layers) + ")";
          return;
        }
      std::array<std::map<std::string, double>, 2> given;
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        given[static_cast<unsigned int>(sd)] =
          make_elastic_law(materials.material(layer, sd))->load_constants();
      // A constant that a ply changes is no constant of the layer.
      std::set<std::string> ply_differs;
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        for (const LayerMaterial &m : materials.ply_materials(layer, sd))
          {
            const auto  ply  = make_elastic_law(m)->load_constants();
            const auto &side = given[static_cast<unsigned int>(sd)];
            for (const std::string name : {"E", "nu", "mu", "lambda"})
              if (ply.count(name) != side.count(name) ||
                  (ply.count(name) && ply.at(name) != side.at(name)))
                ply_differs.insert(name);
          }
      for (const std::string name : {"E", "nu", "mu", "lambda"})
        {
          if (ply_differs.count(name))
            {
              why_absent[name + n] =
                "which differs between the plies of the layer (" + section +
                (materials.ply_groups[l].empty() ? "/Ply heights" :
                                                   "/Ply groups") +
                "): write the value of one ply as a number";
              continue;
            }
          const bool minus = given[0].count(name) > 0;
          const bool plus  = given[1].count(name) > 0;
          if (minus && plus && given[0].at(name) == given[1].at(name))
            values[name + n] = given[0].at(name);
          else if (minus && plus)
            why_absent[name + n] =
              "which differs between the sides of the layer (" + name + " = " +
              number(given[0].at(name)) + " on " + section + "/Omega-, " +
              number(given[1].at(name)) +
              " on Omega+): write the value of one side as a number";
          else
            {
              const unsigned int s = minus ? 1 : 0;
              why_absent[name + n] =
                absent_constant(materials.material(layer,
                                                   static_cast<Subdomain>(s)),
                                l,
                                materials.side[l][s] ?
                                  section + (s == 0 ? "/Omega-" : "/Omega+") :
                                  section);
            }
        }
    }
  } // namespace


  LoadParameters::LoadParameters()
  {
    for (auto &layer : traction)
      layer.assign(parts.size(), "0; 0");
  }


  std::vector<double>
  parse_load_factors(const std::string &text)
  {
    const std::string refusal =
      "Loads/Load factor must be a ','-separated list of numbers >= 0 or "
      "start:step:end with 0 <= start <= end and step > 0 (at most 100000 "
      "factors), got '" +
      text + "'";
    const auto number = [&](const std::string &item) {
      const std::string t = Utilities::trim(item);
      double            value;
      std::size_t       end = 0;
      try
        {
          value = std::stod(t, &end);
        }
      catch (const std::exception &)
        {
          end = 0;
        }
      AssertThrow(!t.empty() && end == t.size() && std::isfinite(value) &&
                    value >= 0,
                  ExcMessage(refusal));
      return value;
    };
    std::vector<double> factors;
    if (text.find(':') != std::string::npos)
      {
        const auto parts = Utilities::split_string_list(text, ':');
        AssertThrow(parts.size() == 3, ExcMessage(refusal));
        const double start = number(parts[0]), step = number(parts[1]),
                     end = number(parts[2]);
        AssertThrow(step > 0 && end >= start && (end - start) / step < 100000,
                    ExcMessage(refusal));
        const unsigned int n =
          static_cast<unsigned int>(std::floor((end - start) / step + 1e-9));
        for (unsigned int k = 0; k <= n; ++k)
          factors.push_back(start + k * step);
      }
    else
      for (const std::string &item : Utilities::split_string_list(text, ','))
        factors.push_back(number(item));
    AssertThrow(!factors.empty() && factors.size() <= 100000,
                ExcMessage(refusal));
    return factors;
  }


  void
  LoadParameters::declare_parameters(ParameterHandler    &prm,
                                     const BoundaryParts &parts,
                                     const unsigned int   n_layer_slots)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Constants",
      "",
      Patterns::Anything(),
      "Named constants for the expressions below, as 'name = expression; "
      "name = expression'. An expression may use E1, nu1, mu1, lambda1, E2, "
      "nu2, mu2, lambda2 (Young's modulus, Poisson's ratio and the Lame "
      "constants of isotropic layers, from Materials; not defined for "
      "orthotropic and anisotropic layers) and the constants defined "
      "before it, e.g. 'c = 1e-3*mu1'.");
    prm.declare_entry(
      "Temperature change",
      "0",
      Patterns::Anything(),
      "Temperature change dT from the stress-free state [K], an expression "
      "of x and y and the constants, on every layer: the thermal strain "
      "alpha dT (Materials/Layer k/Thermal expansion) enters as an "
      "eigenstrain, in plane strain with eps_zz = 0 (isotropic: (1 + nu) "
      "alpha dT in the plane, sigma_zz = nu (sigma_xx + sigma_yy) - E alpha "
      "dT), in plane stress alpha dT. '0': none.");
    prm.declare_entry(
      "Load factor",
      "1",
      Patterns::Anything(),
      "The load factors lambda [-] of Fracture/Crack growth: a ','-separated "
      "list of numbers >= 0 (increasing with quasi-static growth; one with "
      "sweep), or start:step:end (step > 0). lambda multiplies the loads "
      "that Loads/Load factor scales names; the others stay as given (a "
      "preload). Without crack growth only 1.");
    prm.declare_entry(
      "Load factor scales",
      "mechanical",
      Patterns::Selection("mechanical|thermal|all"),
      "What Loads/Load factor multiplies: 'mechanical' the tractions, body "
      "forces and prescribed displacements (the temperature change and the "
      "eigenstrains are a preload); 'thermal' the temperature change and the "
      "eigenstrains (the mechanical loads are the preload: lambda is a "
      "factor of dT, e.g. the critical temperature drop of a film); 'all' "
      "every load. A growth run whose factors scale no load is refused.");
    for (unsigned int l = 0; l < n_layer_slots; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        for (unsigned int i = 0; i < parts.size(); ++i)
          prm.declare_entry(parts.traction_entry(i),
                            "0; 0",
                            Patterns::Anything(),
                            "Traction (x-component; y-component) on this part "
                            "of the boundary of the layer as expressions of x "
                            "and y [stress]. Used where the part is not "
                            "clamped; must be '0; 0' on clamped parts.");
        prm.declare_entry("Prescribed displacement",
                          "0; 0",
                          Patterns::Anything(),
                          "Displacement (x-component; y-component) of the "
                          "layer on the clamped sides Gamma_D as expressions "
                          "of x and y [length].");
        prm.declare_entry(
          "Body force",
          "0; 0",
          Patterns::Anything(),
          "Body force (x-component; y-component) on the layer, a force per "
          "unit volume [stress / length], as expressions of x and y and the "
          "constants; fixed in space (the energy release rate moves the "
          "crack, not the load). '0; 0': none.");
        prm.declare_entry(
          "Eigenstrain",
          "0; 0; 0",
          Patterns::Anything(),
          "Eigenstrain eps* of the layer (eps11; eps22; eps12: the tensor "
          "components in the x-y frame, eps12 the tensor shear, half the "
          "engineering shear; eps*_zz = 0) [dimensionless], as expressions of "
          "x and y and the constants: misfit, swelling or a thermal strain "
          "worked out by hand. The stress is sigma = C (eps(w) - eps*) and "
          "the energy 1/2 int (eps(w) - eps*) : C (eps(w) - eps*) minus the "
          "work of the loads. '0; 0; 0': none.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }


  void
  LoadParameters::resize_layers(const unsigned int n_slots)
  {
    traction.resize(n_slots);
    prescribed.resize(n_slots, "0; 0");
    body_force.resize(n_slots, "0; 0");
    eigenstrain.resize(n_slots, "0; 0; 0");
  }


  void
  LoadParameters::parse_parameters(ParameterHandler         &prm,
                                   const MaterialParameters &materials,
                                   const BoundaryParts      &boundary_parts)
  {
    parts = boundary_parts;
    constant_values.clear();
    // The material constants: E, nu, mu, lambda of each layer are reserved
    // names; a layer whose law does not define one (orthotropic and
    // anisotropic layers, lambda at nu = 0.5 in plane stress) or whose
    // sides give it different values leaves it out, and an expression that
    // names it is refused (why_absent).
    std::set<std::string>              materials_constants;
    std::map<std::string, std::string> why_absent;
    const unsigned int                 n_slots = materials.layer.size();
    resize_layers(n_slots);
    for (unsigned int l = 0; l < n_slots; ++l)
      {
        std::map<std::string, double> values;
        layer_constants(materials, l, values, why_absent);
        for (const auto &[name, value] : values)
          constant_values[name] = value;
        for (const std::string name : {"E", "nu", "mu", "lambda"})
          materials_constants.insert(name + std::to_string(l + 1));
      }
    const auto refuse_absent = [&](const std::string &entry,
                                   const std::string &text) {
      for (const std::string &name : expressions::names_in(text))
        AssertThrow(why_absent.count(name) == 0,
                    ExcMessage(entry + ": '" + text + "' uses " + name + ", " +
                               why_absent.at(name)));
    };

    prm.enter_subsection("Loads");
    load_factors             = parse_load_factors(prm.get("Load factor"));
    const std::string scales = prm.get("Load factor scales");
    load_factor_scales       = scales == "thermal" ? Scaled::thermal :
                               scales == "all"     ? Scaled::all :
                                                     Scaled::mechanical;
    constants                = prm.get("Constants");
    AssertThrow(constants.size() <= expressions::max_length,
                ExcMessage("Loads/Constants: longer than " +
                           std::to_string(expressions::max_length) +
                           " characters"));
    for (const auto &item : Utilities::split_string_list(constants, ';'))
      {
        if (Utilities::trim(item).empty())
          continue;
        const auto        equal = item.find('=');
        const std::string name =
          Utilities::trim(item.substr(0, std::min(equal, item.size())));
        const std::string value = equal == std::string::npos ?
                                    "" :
                                    Utilities::trim(item.substr(equal + 1));
        AssertThrow(equal != std::string::npos &&
                      expressions::is_identifier(name) && !value.empty(),
                    ExcMessage("Loads/Constants must read 'name = expression; "
                               "...' with names of letters, digits and '_', "
                               "cannot read '" +
                               item + "'"));
        AssertThrow(!expressions::is_reserved_name(name) &&
                      materials_constants.count(name) == 0,
                    ExcMessage("Loads/Constants: the name '" + name +
                               "' is reserved (the coordinates x, y, the "
                               "material constants E1, nu1, mu1, lambda1, E2, "
                               "nu2, mu2, lambda2 and the functions of the "
                               "expressions): choose another name"));
        refuse_absent("Loads/Constants", item);
        double     result = 0;
        const bool evaluated =
          expressions::evaluate_constant(value, constant_values, result);
        AssertThrow(evaluated,
                    ExcMessage("Loads/Constants: cannot evaluate '" + value +
                               "' for constant '" + name + "'"));
        AssertThrow(std::isfinite(result),
                    ExcMessage("Loads/Constants: constant '" + name + "' = '" +
                               value + "' is not a finite number"));
        constant_values[name] = result;
      }

    temperature_change = prm.get("Temperature change");
    refuse_absent("Loads/Temperature change", temperature_change);
    expressions::function(
      temperature_change, 1, "dT", constant_values, "Loads/Temperature change");
    for (unsigned int l = 0; l < n_slots; ++l)
      {
        prm.enter_subsection(layer_subsection(l));
        traction[l].assign(parts.size(), "0; 0");
        const std::string where = "Loads/" + layer_subsection(l) + "/";
        for (unsigned int i = 0; i < parts.size(); ++i)
          {
            traction[l][i] = prm.get(parts.traction_entry(i));
            refuse_absent(where + parts.traction_entry(i), traction[l][i]);
          }
        prescribed[l] = prm.get("Prescribed displacement");
        refuse_absent(where + "Prescribed displacement", prescribed[l]);
        body_force[l] = prm.get("Body force");
        refuse_absent(where + "Body force", body_force[l]);
        eigenstrain[l] = prm.get("Eigenstrain");
        refuse_absent(where + "Eigenstrain", eigenstrain[l]);
        prm.leave_subsection();
      }
    prm.leave_subsection();

    // Evaluate every expression once now, so that errors name the entry.
    for (const Layer layer : materials.layers())
      {
        prescribed_function(layer);
        for (unsigned int i = 0; i < parts.size(); ++i)
          traction_function(layer, i);
        const unsigned int l = static_cast<unsigned int>(layer);
        // (Also the ones that volume_load() skips as zero.)
        expressions::vector_function(body_force[l],
                                     constant_values,
                                     "Loads/" + layer_subsection(l) +
                                       "/Body force");
        expressions::function(eigenstrain[l],
                              3,
                              "eps11; eps22; eps12",
                              constant_values,
                              "Loads/" + layer_subsection(l) + "/Eigenstrain");
      }
  }


  bool
  LoadParameters::has_volume_load(const Layer layer) const
  {
    const unsigned int l = static_cast<unsigned int>(layer);
    return !expressions::is_zero(body_force[l]) ||
           !expressions::is_zero(eigenstrain[l]);
  }


  std::unique_ptr<VolumeLoad>
  LoadParameters::volume_load(const Layer  layer,
                              const double length_scale) const
  {
    if (!has_volume_load(layer))
      return nullptr;
    const unsigned int l = static_cast<unsigned int>(layer);
    return std::make_unique<ExpressionVolumeLoad>(body_force[l],
                                                  eigenstrain[l],
                                                  constant_values,
                                                  "Loads/" +
                                                    layer_subsection(l),
                                                  length_scale);
  }


  std::unique_ptr<VolumeLoad>
  LoadParameters::volume_load(const Layer                       layer,
                              const std::vector<LayerMaterial> &plies,
                              const PlyDivision                &division,
                              const double length_scale) const
  {
    if (plies.size() == 1)
      return volume_load(layer, plies[0], length_scale);
    std::vector<std::unique_ptr<VolumeLoad>> loads;
    bool                                     any = false;
    for (const LayerMaterial &m : plies)
      {
        loads.push_back(volume_load(layer, m, length_scale));
        any = any || loads.back() != nullptr;
      }
    if (!any)
      return nullptr;
    return std::make_unique<PlyVolumeLoad>(std::move(loads), division);
  }


  bool
  LoadParameters::has_thermal_load(const LayerMaterial &material) const
  {
    return !expressions::is_zero(temperature_change) &&
           has_thermal_expansion(material);
  }


  std::unique_ptr<VolumeLoad>
  LoadParameters::volume_load(const Layer          layer,
                              const LayerMaterial &material,
                              const double         length_scale) const
  {
    auto load = volume_load(layer, length_scale);
    if (!has_thermal_load(material))
      return load;
    return std::make_unique<ThermalVolumeLoad>(
      std::move(load),
      expressions::function(temperature_change,
                            1,
                            "dT",
                            constant_values,
                            "Loads/Temperature change"),
      material,
      length_scale);
  }


  std::unique_ptr<FunctionParser<2>>
  LoadParameters::traction_function(const Layer        layer,
                                    const unsigned int part) const
  {
    const unsigned int l = static_cast<unsigned int>(layer);
    return expressions::vector_function(traction[l][part],
                                        constant_values,
                                        "Loads/" + layer_subsection(l) + "/" +
                                          parts.traction_entry(part));
  }


  std::unique_ptr<FunctionParser<2>>
  LoadParameters::prescribed_function(const Layer layer) const
  {
    const unsigned int l = static_cast<unsigned int>(layer);
    return expressions::vector_function(prescribed[l],
                                        constant_values,
                                        "Loads/" + layer_subsection(l) +
                                          "/Prescribed displacement");
  }


  bool
  LoadParameters::traction_is_zero(const Layer        layer,
                                   const unsigned int part) const
  {
    const auto components = Utilities::split_string_list(
      traction[static_cast<unsigned int>(layer)][part], ';');
    for (const auto &p : components)
      if (p != "0" && p != "0.0" && p != "0.")
        return false;
    return true;
  }
} // namespace bilayer
