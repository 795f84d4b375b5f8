#ifndef bilayer_run_h
#define bilayer_run_h

/**
 * The program bilayer: the command line (command_line.h), the environment
 * (run_environment.h), the scene, MPI, the staged output directory and the
 * study, each refusal a one-line message and an exit status.
 */
namespace bilayer
{
  /// The exit statuses of bilayer (a run stopped by a signal: 128 + it).
  namespace ExitStatus
  {
    /// The run passed its checks (or --help, --version, ...).
    constexpr int success = 0;
    /// A refusal or an error: nothing published.
    constexpr int error = 1;
    /// A cycle failed its acceptance checks (results in DIR.failed).
    constexpr int failed_checks = 2;
  } // namespace ExitStatus

  /// Everything main() does; returns the exit status.
  int
  run_program(int argc, char **argv);
} // namespace bilayer

#endif
