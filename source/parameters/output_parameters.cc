#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/output_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <cmath>

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
    prm.declare_entry(
      "Time of growth steps",
      "load factor",
      Patterns::Selection("load factor|step|crack length"),
      "The time of a step of Fracture/Crack growth in solution.pvd and "
      "interface.pvd (ParaView's animation): its load factor, its number, or "
      "the total crack length. Steps of unstable growth at one load share "
      "their load factor: ParaView shows one of them (the terminal names "
      "them); step or crack length shows each.");
    prm.declare_entry(
      "Unit system",
      "units of the input",
      Patterns::Selection("units of the input|m, Pa|mm, MPa|um, GPa"),
      "The consistent units the scene's numbers are in, for the labels of "
      "summary.json (\"units\") and the pictures' axes; nothing is "
      "converted. units of the input: the labels say length, stress, ...; "
      "m, Pa: forces per thickness in N/m, G in J/m^2; mm, MPa: N/mm and "
      "N/mm (= kJ/m^2); um, GPa: GPa um (= kN/m) and GPa um (= kJ/m^2).");
    prm.declare_entry(
      "Written steps",
      "every 1",
      Patterns::Anything(),
      "The steps of Fracture/Crack growth whose solution fields (Write VTU, "
      "Write HDF5) and interface CSV are written: every N (steps 0, N, 2N, "
      "..., and the last), last (the last step only) or none; growth.csv, "
      "the table and summary.json hold every step.");
    prm.declare_entry(
      "Displacement points",
      "",
      Patterns::Anything(),
      "Points 'x1, y1; x2, y2; ...' [length] off Sigma where growth.csv "
      "reports the displacement of layer 1 at every step of Fracture/Crack "
      "growth (a load-displacement curve); empty: none.");
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
    const std::string time = prm.get("Time of growth steps");
    growth_time            = time == "step"         ? GrowthTime::step :
                             time == "crack length" ? GrowthTime::crack_length :
                                                      GrowthTime::load_factor;
    units                  = unit_names(prm.get("Unit system"));
    parse_growth_outputs(prm.get("Written steps"),
                         prm.get("Displacement points"));
    prm.leave_subsection();
  }


  UnitNames
  unit_names(const std::string &system)
  {
    UnitNames names;
    names.system = system;
    if (system == "m, Pa")
      {
        names.length = "m", names.stress = "Pa", names.force = "N/m";
        names.energy_release_rate = "J/m^2", names.energy = "J/m";
      }
    else if (system == "mm, MPa")
      {
        names.length = "mm", names.stress = "MPa", names.force = "N/mm";
        names.energy_release_rate = "N/mm", names.energy = "N mm/mm";
      }
    else if (system == "um, GPa")
      {
        names.length = "um", names.stress = "GPa", names.force = "GPa um";
        names.energy_release_rate = "GPa um", names.energy = "GPa um^2";
      }
    return names;
  }


  void
  OutputParameters::parse_growth_outputs(const std::string &steps,
                                         const std::string &points)
  {
    const std::string s = Utilities::trim(steps);
    written_steps_last  = s != "none";
    written_steps_every = 0;
    if (s.rfind("every", 0) == 0)
      {
        const std::string n = Utilities::trim(s.substr(5));
        AssertThrow(!n.empty() && n.size() < 9 &&
                      n.find_first_not_of("0123456789") == std::string::npos &&
                      std::stoul(n) >= 1,
                    ExcMessage("Output/Written steps must be 'every N' (N >= "
                               "1), 'last' or 'none', got '" +
                               steps + "'"));
        written_steps_every = std::stoul(n);
      }
    else
      AssertThrow(s == "last" || s == "none",
                  ExcMessage("Output/Written steps must be 'every N' (N >= "
                             "1), 'last' or 'none', got '" +
                             steps + "'"));
    displacement_points.clear();
    for (const std::string &item : Utilities::split_string_list(points, ';'))
      {
        if (Utilities::trim(item).empty())
          continue;
        const auto xy   = Utilities::split_string_list(item, ',');
        bool       ok   = xy.size() == 2;
        double     c[2] = {0, 0};
        for (unsigned int d = 0; ok && d < 2; ++d)
          {
            const std::string t   = Utilities::trim(xy[d]);
            std::size_t       end = 0;
            try
              {
                c[d] = std::stod(t, &end);
              }
            catch (const std::exception &)
              {
                end = 0;
              }
            ok = !t.empty() && end == t.size() && std::isfinite(c[d]);
          }
        AssertThrow(ok,
                    ExcMessage("Output/Displacement points must be 'x1, y1; "
                               "x2, y2; ...' (finite numbers), got '" +
                               points + "'"));
        displacement_points.emplace_back(c[0], c[1]);
      }
  }
} // namespace bilayer
