#include <deal.II/base/exceptions.h>

#include <bilayer/app/command_line.h>

namespace bilayer
{
  namespace
  {
    const char *usage_line =
      "usage: bilayer PARAMETER_FILE.prm [--set Section/Entry=value ...]; "
      "bilayer --help";
  } // namespace


  void
  print_usage(std::ostream &out)
  {
    out << "Usage: bilayer PARAMETER_FILE.prm [--set Section/Entry=value ...] "
           "[--allow-gmsh-commands]\n"
           "       bilayer --print-parameters   print every entry with its "
           "default and documentation\n"
           "       bilayer PARAMETER_FILE.prm --print-parameters [--set ...]\n"
           "                                    print every entry as the run "
           "would use it\n"
           "                                    (includes and --set applied), "
           "run nothing\n"
           "       bilayer --check-geometry FILE [--allow-gmsh-commands] "
           "[--set Mesh/Entry=value ...]\n"
           "                                    mesh a Gmsh scene (.geo or "
           ".msh) with bilayer's\n"
           "                                    checks and print its groups, "
           "cells, Sigma and\n"
           "                                    crack pieces (--set: Gmsh mesh "
           "size factor, Gmsh\n"
           "                                    time limit), run nothing\n"
           "       bilayer --version            print the version, the git "
           "commit, deal.II's\n"
           "                                    version and the BLAS in use\n"
           "       bilayer --help               print this message\n\n"
           "--set overrides an entry of the file, e.g.\n"
           "  --set \"Solver/Uzawa step theta=70\" --set "
           "\"Materials/Layer 1/Young's modulus=210\"\n"
           "--allow-gmsh-commands lets a Gmsh scene (Geometry/Gmsh file, "
           ".geo) run programs\n"
           "  and write files (SystemCall, Printf > file, Save, ...): only "
           "for files you\n"
           "  trust; without it such scenes are refused (docs/geometry.md)\n"
           "\n"
           "Computes the equilibrium of a two-layer elastic structure with a "
           "through\ncrack whose faces must not penetrate each other "
           "(domain decomposition\nand Uzawa iteration). Results go to the "
           "directory Output/Output directory.\n";
  }


  CommandLine
  parse_command_line(const int argc, char **argv)
  {
    using dealii::ExcMessage;
    CommandLine command;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          command.action = CommandLine::Action::help;
        else if (arg == "--print-parameters")
          command.action = CommandLine::Action::print_parameters;
        else if (arg == "--version")
          command.action = CommandLine::Action::version;
        else if (arg == "--set")
          {
            AssertThrow(i + 1 < argc,
                        ExcMessage("--set needs a value "
                                   "'Section/Entry=value' after it (" +
                                   std::string(usage_line) + ")"));
            command.overrides.emplace_back(argv[++i]);
          }
        else if (arg.rfind("--set=", 0) == 0)
          command.overrides.emplace_back(arg.substr(6));
        else if (arg == "--check-geometry")
          {
            AssertThrow(i + 1 < argc,
                        ExcMessage("--check-geometry needs the geometry "
                                   "file (.geo or .msh) after it (" +
                                   std::string(usage_line) + ")"));
            command.action        = CommandLine::Action::check_geometry;
            command.geometry_file = argv[++i];
          }
        else if (arg == "--allow-gmsh-commands")
          command.allow_gmsh_commands = true;
        else if (arg.size() > 1 && arg[0] == '-')
          {
            AssertThrow(false,
                        ExcMessage("unknown option '" + arg + "' (" +
                                   usage_line + ")"));
          }
        else
          {
            AssertThrow(command.parameter_file.empty(),
                        ExcMessage("more than one parameter file given ('" +
                                   command.parameter_file + "', '" + arg +
                                   "'): run them one at a time (" + usage_line +
                                   ")"));
            command.parameter_file = arg;
          }
      }
    AssertThrow(command.action != CommandLine::Action::version ||
                  (command.parameter_file.empty() && command.overrides.empty()),
                ExcMessage("--version takes no parameter file or --set"));
    AssertThrow(command.action != CommandLine::Action::check_geometry ||
                  command.parameter_file.empty(),
                ExcMessage("--check-geometry " + command.geometry_file +
                           " takes no parameter file, got '" +
                           command.parameter_file +
                           "' (--set of Mesh entries and "
                           "--allow-gmsh-commands apply)"));
    AssertThrow(command.action != CommandLine::Action::print_parameters ||
                  !command.parameter_file.empty() || command.overrides.empty(),
                ExcMessage("--print-parameters with --set needs the parameter "
                           "file the settings apply to (" +
                           std::string(usage_line) + ")"));
    AssertThrow(command.action != CommandLine::Action::run ||
                  !command.parameter_file.empty(),
                ExcMessage(std::string("no parameter file given (") +
                           usage_line + ")"));
    return command;
  }
} // namespace bilayer
