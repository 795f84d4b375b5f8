#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/output_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Output directory",
                      "results",
                      Patterns::Anything(),
                      "Directory for all output files, relative to the "
                      "working directory, written whole: the run writes into "
                      "DIR.partial, which replaces DIR when every cycle "
                      "passes its checks and becomes DIR.failed when one "
                      "does not (DIR then stays as it was).");
    prm.declare_entry("Write VTU",
                      "true",
                      Patterns::Bool(),
                      "Write solution.pvd with one .pvtu per cycle and one "
                      ".vtu per layer and subdomain.");
    prm.declare_entry("Write HDF5",
                      "false",
                      Patterns::Bool(),
                      "Write one .h5 file per layer, subdomain and cycle "
                      "(deal.II's HDF5 writer) and solution.xdmf over all "
                      "cycles, for ParaView's XDMF reader: compact binary "
                      "output for large meshes.");
    prm.declare_entry("Written cycles",
                      "every cycle",
                      Patterns::Selection("every cycle|last cycle|none"),
                      "The cycles whose solution fields (Write VTU, Write "
                      "HDF5: the layers' displacements and stresses, the "
                      "interface polyline) are written: every cycle, the "
                      "last cycle (or the cycle whose checks fail, where the "
                      "run ends), or none. The interface CSV, the table and "
                      "summary.json are written for every cycle.");
    prm.declare_entry("Compression",
                      "best speed",
                      Patterns::Selection(
                        "none|best speed|default|best compression"),
                      "zlib compression of the VTU data: none (largest files, "
                      "fastest), best speed, default or best compression "
                      "(smallest files, several times slower to write).");
    prm.declare_entry("Write interface CSV",
                      "true",
                      Patterns::Bool(),
                      "Write interface-NN.csv (jumps, gaps and multipliers "
                      "at the multiplier nodes on Sigma) per cycle.");
    prm.declare_entry("Progress interval",
                      "100",
                      Patterns::Integer(0),
                      "Print the iteration, the stopping value and the "
                      "constraint violation every this many iterations; 0 "
                      "prints none [-].");
    prm.declare_entry("Terminal output",
                      "full",
                      Patterns::Selection("full|checks"),
                      "full: progress, per-cycle report, table and timings; "
                      "checks: only the pass/fail lines of the acceptance "
                      "checks (for regression tests).");
    prm.leave_subsection();
  }


  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Output directory");
    AssertThrow(!directory.empty(),
                ExcMessage("Output/Output directory must not be empty"));
    write_vtu                = prm.get_bool("Write VTU");
    write_hdf5               = prm.get_bool("Write HDF5");
    write_interface          = prm.get_bool("Write interface CSV");
    const std::string cycles = prm.get("Written cycles");
    written_cycles           = cycles == "every cycle" ? WrittenCycles::every :
                               cycles == "last cycle"  ? WrittenCycles::last :
                                                         WrittenCycles::none;
    const std::string level  = prm.get("Compression");
    compression              = level == "none"       ? Compression::none :
                               level == "best speed" ? Compression::best_speed :
                               level == "default"    ? Compression::standard :
                                                       Compression::best;
    progress_interval        = prm.get_integer("Progress interval");
    terminal = prm.get("Terminal output") == "checks" ? TerminalOutput::checks :
                                                        TerminalOutput::full;
    prm.leave_subsection();
  }
} // namespace bilayer
