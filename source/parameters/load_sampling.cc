#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>

#include <bilayer/parameters/scene_checks.h>
#include <bilayer/physics/elastic_law.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The range of load energies (stress x area) the rectangle's loads
    /// may reach, 10^-290 to 10^290: 1e18 inside the range of double
    /// precision (1.8e308, 2.2e-308), room for sums of squares over many
    /// unknowns.
    constexpr int max_load_energy_log10 = 290;

    const PerSide<Side> all_sides = {
      {Side::left, Side::right, Side::bottom, Side::top}};
  } // namespace


  void
  check_rectangle_loads(const Scene &scene, const BoundaryParts &parts)
  {
    const auto &geometry  = scene.geometry;
    const auto &materials = scene.materials;
    const auto &loads     = scene.loads;
    // Every load must be finite where it acts: tractions on their sides,
    // the prescribed displacement on the clamped sides (1001 points each).
    for (const Layer layer : materials.layers())
      for (const Side side : all_sides)
        {
          const unsigned int s = static_cast<unsigned int>(side);
          const std::string  where =
            "Loads/Layer " + std::to_string(static_cast<int>(layer) + 1) + "/" +
            (geometry.clamped[s] ? std::string("Prescribed displacement") :
                                   parts.traction_entry(s));
          const auto f       = geometry.clamped[s] ?
                                 loads.prescribed_function(layer) :
                                 loads.traction_function(layer, s);
          double     largest = 0;
          Point<2>   largest_at;
          for (unsigned int i = 0; i <= 1000; ++i)
            {
              // The point a fraction i/1000 along the side.
              const double t       = i / 1000.;
              const bool   at_side = side == Side::left || side == Side::right;
              const double x =
                at_side ?
                  (side == Side::left ? geometry.x_min : geometry.x_max) :
                  geometry.x_min + t * (geometry.x_max - geometry.x_min);
              const double y =
                !at_side ?
                  (side == Side::bottom ? geometry.y_min : geometry.y_max) :
                  geometry.y_min + t * (geometry.y_max - geometry.y_min);
              for (unsigned int c = 0; c < 2; ++c)
                {
                  const double value = f->value(Point<2>(x, y), c);
                  if (!std::isfinite(value))
                    {
                      std::ostringstream point;
                      point << "(" << x << ", " << y << ")";
                      AssertThrow(false,
                                  ExcMessage(where + " must be finite on the " +
                                             side_name(side) + " side, got " +
                                             std::to_string(value) + " at " +
                                             point.str()));
                    }
                  if (std::abs(value) > largest)
                    largest = std::abs(value), largest_at = Point<2>(x, y);
                }
            }
          if (!materials.has_layer(layer) || largest == 0)
            continue;
          // The energy of the loads (per unit thickness), to within factors
          // of order one: a traction t on a body of size D and modulus E
          // displaces by t D / E and stores t^2 D^2 / E; a prescribed
          // displacement g stores E g^2. Its squares (energies, norms of the
          // residuals, the error estimate) must be representable in double
          // precision, with room for sums over millions of unknowns.
          const double D = std::max(geometry.x_max - geometry.x_min,
                                    geometry.y_max - geometry.y_min);
          // (E of an isotropic layer; the energy-norm scale, the smallest
          // stiffness, of the other laws; of the side of the layer that
          // makes the energy the farthest from 1 where the sides differ.)
          double E = 0, log_energy = 0;
          for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
            {
              const LayerMaterial &material = materials.material(layer, sd);
              const double         E_side =
                material.law == MaterialLaw::isotropic ?
                          material.youngs_modulus :
                          make_elastic_law(material)->energy_norm_scale();
              // (In logarithms: the energy itself may overflow.)
              const double log_side =
                geometry.clamped[s] ?
                  std::log10(E_side) + 2 * std::log10(largest) :
                  2 * std::log10(largest) + 2 * std::log10(D) -
                    std::log10(E_side);
              if (sd == Subdomain::minus ||
                  std::abs(log_side) > std::abs(log_energy))
                E = E_side, log_energy = log_side;
            }
          // (Moduli beyond that range are refused where the stiffness is
          // assembled, naming the modulus.)
          if ((log_energy <= max_load_energy_log10 &&
               log_energy >= -max_load_energy_log10) ||
              std::abs(std::log10(E)) > max_load_energy_log10)
            continue;
          std::ostringstream message;
          message << std::setprecision(3) << where << " reaches " << largest
                  << " at (" << largest_at[0] << ", " << largest_at[1]
                  << "): the energy of such a load, about "
                  << (geometry.clamped[s] ? "E g^2" : "t^2 D^2 / E") << " = 10^"
                  << std::lround(log_energy) << ", is "
                  << (log_energy > 0 ? "above 10^" : "below 10^-")
                  << max_load_energy_log10
                  << ", beyond what double precision represents with its "
                     "squares; the problem is linear in the loads: scale "
                     "them (Loads/Constants or the expressions) by a power "
                     "of ten into that range and scale the results back "
                     "(displacements, stresses and multipliers with the "
                     "loads, the energy and G with their square)";
          AssertThrow(false, ExcMessage(message.str()));
        }
  }
} // namespace bilayer
