#ifndef bilayer_command_line_h
#define bilayer_command_line_h

#include <ostream>
#include <string>
#include <vector>

namespace bilayer
{
  /// What the command line asks for.
  struct CommandLine
  {
    enum class Action
    {
      run,
      help,
      print_parameters,
      version,
      check_geometry
    } action = Action::run;
    std::string parameter_file;
    /// The file of --check-geometry FILE.
    std::string              geometry_file;
    std::vector<std::string> overrides;
    bool                     allow_gmsh_commands = false;
  };

  /// Read the command line; mistakes throw a one-line message.
  CommandLine
  parse_command_line(const int argc, char **argv);

  /// The message of --help.
  void
  print_usage(std::ostream &out);
} // namespace bilayer

#endif
