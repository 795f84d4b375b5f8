#ifndef bilayer_load_parameters_h
#define bilayer_load_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <bilayer/core/layout.h>
#include <bilayer/parameters/geometry_parameters.h>
#include <bilayer/parameters/material_parameters.h>
#include <bilayer/physics/volume_load.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

/**
 * The subsection Loads: named constants, tractions on the boundary parts,
 * prescribed displacements, body forces and eigenstrains, as expressions
 * (expressions.h).
 */
namespace bilayer
{
  /**
   * Tractions and prescribed displacements as muparser expressions of x and
   * y. The named constants may use the material constants E1, nu1, mu1,
   * lambda1, E2, nu2, mu2, lambda2 and the constants defined before them.
   */
  struct LoadParameters
  {
    std::string constants = "";
    /// The boundary parts the tractions refer to.
    BoundaryParts parts;
    /// traction[layer][part], "f_x; f_y"
    std::vector<std::vector<std::string>> traction{2};
    /// prescribed[layer], "u_x; u_y", on the clamped sides
    std::vector<std::string> prescribed = {"0; 0", "0; 0"};
    /// body_force[layer], "f_x; f_y" [stress / length]
    std::vector<std::string> body_force = {"0; 0", "0; 0"};
    /// eigenstrain[layer], "eps11; eps22; eps12" [-]
    std::vector<std::string> eigenstrain = {"0; 0; 0", "0; 0; 0"};
    /// Loads/Temperature change, dT(x, y) [K] (every layer)
    std::string temperature_change = "0";
    /// Loads/Load factor: the factors lambda of the proportional loads
    /// in order (Fracture/Crack growth); what they scale is
    /// load_factor_scales.
    std::vector<double> load_factors = {1.};
    /// Loads/Load factor scales: what lambda multiplies.
    enum class Scaled
    {
      /// tractions, body forces, prescribed displacements (the default)
      mechanical,
      /// the temperature change and the eigenstrains
      thermal,
      /// both
      all
    };
    Scaled load_factor_scales = Scaled::mechanical;
    /// The factors of the mechanical loads and of the thermal loads and
    /// eigenstrains at the load factor @p lambda.
    double
    mechanical_factor(const double lambda) const
    {
      return load_factor_scales == Scaled::thermal ? 1. : lambda;
    }
    double
    thermal_factor(const double lambda) const
    {
      return load_factor_scales == Scaled::mechanical ? 1. : lambda;
    }

    /// The evaluated constants (material constants included).
    std::map<std::string, double> constant_values;

    LoadParameters();

    /// Declare the entries, with the subsections Layer 1 ... Layer
    /// @p n_layer_slots.
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const BoundaryParts      &parts = BoundaryParts(),
                       const unsigned int        n_layer_slots = 2);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const MaterialParameters &materials,
                     const BoundaryParts      &parts);
    /// The per-layer entries of @p n_slots layer slots (new ones "0").
    void
    resize_layers(const unsigned int n_slots);

    std::unique_ptr<dealii::FunctionParser<2>>
    traction_function(const Layer layer, const unsigned int part) const;
    std::unique_ptr<dealii::FunctionParser<2>>
    prescribed_function(const Layer layer) const;
    /**
     * The body force and eigenstrain of @p layer as a VolumeLoad
     * (ExpressionVolumeLoad, its default gradients with the step 1e-3 of
     * @p length_scale), or null where both entries are "0" in every
     * component: such a layer passes no VolumeLoad, exactly as a scene
     * without these entries.
     */
    std::unique_ptr<VolumeLoad>
    volume_load(const Layer layer, const double length_scale) const;
    /**
     * The volume load of the subproblem of @p layer whose material is
     * @p material: volume_load(layer, length_scale), and where the
     * temperature changes and the material expands (has_thermal_load()),
     * that load inside a ThermalVolumeLoad with the plane eigenstrain of the
     * material's law. Null where there is neither.
     */
    std::unique_ptr<VolumeLoad>
    volume_load(const Layer          layer,
                const LayerMaterial &material,
                const double         length_scale) const;
    /**
     * The volume load of the subproblem of @p layer whose plies
     * (@p division) have the materials @p plies: that of its one
     * material, or a PlyVolumeLoad of each ply's (null where none has one).
     */
    std::unique_ptr<VolumeLoad>
    volume_load(const Layer                       layer,
                const std::vector<LayerMaterial> &plies,
                const PlyDivision                &division,
                const double                      length_scale) const;
    /// Whether Loads/Temperature change is not "0" and @p material expands.
    bool
    has_thermal_load(const LayerMaterial &material) const;
    /// Whether @p layer has a body force or an eigenstrain.
    bool
    has_volume_load(const Layer layer) const;
    /// Whether the traction expression of a part is identically "0; 0".
    bool
    traction_is_zero(const Layer layer, const unsigned int part) const;
  };
  /// The factors of Loads/Load factor @p text: "a, b, c" or
  /// "start:step:end"; refuses anything else in one line.
  std::vector<double>
  parse_load_factors(const std::string &text);
} // namespace bilayer

#endif
