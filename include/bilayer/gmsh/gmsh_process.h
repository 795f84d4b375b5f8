#ifndef bilayer_gmsh_process_h
#define bilayer_gmsh_process_h

#include <bilayer/gmsh/gmsh_mesh.h>

#include <filesystem>
#include <string>

/**
 * @file
 * Running the gmsh command on a .geo scene, for gmsh_mesh.cc: in a
 * temporary directory of its own, within the time limit, stopped by the
 * signals that end bilayer.
 */
namespace bilayer
{
  /// A directory of our own, removed with everything in it at the end.
  class TemporaryDirectory
  {
  public:
    /// A new directory bilayer-gmsh-XXXXXX in the temporary directory
    /// (TMPDIR); messages name @p file.
    explicit TemporaryDirectory(const std::string &file);
    ~TemporaryDirectory();
    std::filesystem::path path;
  };

  /**
   * Run gmsh on the scene @p file followed by bilayer's script @p post in
   * @p directory (working directory and HOME, stdin /dev/null, its output
   * into gmsh.log), as a child in a process group of its own that dies
   * with bilayer, within @p options.time_limit seconds. SIGINT, SIGTERM
   * and SIGHUP while it runs stop it, remove the directory and end
   * bilayer by the signal. @p doing ("meshing", ...) is what the progress
   * messages say gmsh is doing with @p file.
   */
  void
  run_gmsh(const std::string        &file,
           const std::string        &post,
           const TemporaryDirectory &directory,
           const GmshOptions        &options,
           const std::string        &doing);
} // namespace bilayer

#endif
