#ifndef bilayer_parameter_includes_h
#define bilayer_parameter_includes_h

#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The parameter file @p filename and the files its "include" lines reach
   * (ParameterHandler opens them relative to the working directory), in the
   * order they are read. Refuses, with a one-line message that names the
   * file and what included it, a file that is not a regular readable file
   * (missing, a directory, a device, larger than 16 MiB) and includes that
   * recurse or go more than 16 levels deep, before ParameterHandler would
   * recurse into them.
   */
  std::vector<std::string>
  parameter_files(const std::string &filename);
} // namespace bilayer

#endif
