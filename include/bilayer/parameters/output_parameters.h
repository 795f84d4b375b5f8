#ifndef bilayer_output_parameters_h
#define bilayer_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

/**
 * The subsection Output: the output directory, the files written and the
 * terminal output.
 */
namespace bilayer
{
  enum class TerminalOutput
  {
    full,
    checks
  };

  /// The cycles whose solution fields (VTU, HDF5) are written.
  enum class WrittenCycles
  {
    every,
    last,
    none
  };

  /// zlib's effort on the VTU data (deal.II's VtkFlags).
  enum class Compression
  {
    none,
    best_speed,
    standard,
    best
  };

  /// What the .pvd time of a growth step is (Output/Time of growth
  /// steps).
  enum class GrowthTime
  {
    load_factor,
    step,
    crack_length
  };

  /// The names of the units of a unit system (Output/Unit system), as the
  /// outputs and the scripts' axes write them.
  struct UnitNames
  {
    std::string system = "units of the input";
    std::string length = "length", stress = "stress", force = "stress x length",
                energy_release_rate = "stress x length",
                energy              = "stress x length^2";
  };

  struct OutputParameters
  {
    std::string    directory         = "results";
    bool           write_vtu         = true;
    bool           write_hdf5        = false;
    bool           write_interface   = true;
    WrittenCycles  written_cycles    = WrittenCycles::every;
    Compression    compression       = Compression::best_speed;
    unsigned int   progress_interval = 100;
    TerminalOutput terminal          = TerminalOutput::full;
    /// Output/Time of growth steps.
    GrowthTime growth_time = GrowthTime::load_factor;
    /// Output/Unit system: only names the units (nothing is converted).
    UnitNames units;
    /// Output/Written steps of crack growth: the solution fields (VTU,
    /// HDF5) and interface CSV of every this many steps (0: none), and of
    /// the last step if @p last_step.
    unsigned int written_steps_every = 1;
    bool         written_steps_last  = true;
    /// Output/Displacement points: where growth.csv reports the
    /// displacement of layer 1.
    std::vector<dealii::Point<2>> displacement_points;

    /// Whether the fields of growth step @p step are written (the last
    /// step is written at the end of the run where asked).
    bool
    writes_step(const unsigned int step) const
    {
      return written_steps_every > 0 && step % written_steps_every == 0;
    }

    /// Whether the solution fields of @p cycle of @p n_cycles are written
    /// (with the last cycle, also a cycle that fails its checks: the run
    /// ends there).
    bool
    writes_fields(const unsigned int cycle,
                  const unsigned int n_cycles,
                  const bool         accepted) const
    {
      if (!write_vtu && !write_hdf5)
        return false;
      switch (written_cycles)
        {
          case WrittenCycles::every:
            return true;
          case WrittenCycles::last:
            return cycle + 1 >= n_cycles || !accepted;
          default:
            return false;
        }
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

  private:
    /// Output/Written steps and Output/Displacement points.
    void
    parse_growth_outputs(const std::string &steps, const std::string &points);
  };
  /// The names of the units of Output/Unit system @p system.
  UnitNames
  unit_names(const std::string &system);
} // namespace bilayer

#endif
