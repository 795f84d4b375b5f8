#ifndef bilayer_run_environment_h
#define bilayer_run_environment_h

#include <streambuf>

/**
 * The environment a run of bilayer starts in, checked and prepared before
 * MPI_Init: the MPI launcher's rank, closed standard streams, a standard
 * output that survives a closed pipe, the thread counts of the environment
 * and the variables that let a job of one process start quickly.
 */
namespace bilayer
{
  /// This process's rank as the MPI launcher set it (0 without one).
  int
  launch_rank();

  /**
   * A standard stream the program was started without (`>&-`, `2>&-`) is
   * opened on /dev/null: the descriptor would otherwise go to the first
   * file the program opens (a mesh, the lock file), and progress lines into
   * it. The run then goes on without that output.
   */
  void
  open_closed_standard_streams();

  /**
   * The standard output of a run: written to descriptor 1 as std::cout
   * would, but a write that fails (a closed pipe, `| head -1`; a full disk)
   * ends the output instead of setting the stream's error state, which
   * deal.II's writers (the tables) turn into an exception. The run goes on
   * and commits; its exit status says how it ended. std::cout writes
   * through it while it exists.
   */
  class TolerantOutput : public std::streambuf
  {
  public:
    TolerantOutput();
    ~TolerantOutput() override;

  protected:
    int_type
    overflow(const int_type c) override;
    std::streamsize
    xsputn(const char *text, const std::streamsize n) override;
    int
    sync() override;

  private:
    void
    write_out();

    std::streambuf *original;
    char            buffer[4096];
    bool            broken = false;
  };

  /**
   * The thread counts of the environment that bilayer's libraries read
   * while the program is loaded, before main(): deal.II's
   * DEAL_II_NUM_THREADS (garbage or 0 end in std::terminate there, a
   * negative count is taken modulo 2^32), OMP_NUM_THREADS (libgomp warns
   * and falls back), the BLAS's own (ignored when garbage). Each must be a
   * whole number from 1 to 1024 (OMP_NUM_THREADS: a comma-separated list
   * of them; empty counts as unset except for deal.II).
   *
   * Called from the executable's preinit array, before every shared
   * library's initialisation (plain C on constant data): an invalid thread
   * count is remembered and hidden from the libraries (the first letter of
   * its name replaced by '_'), so that check_environment() refuses it with
   * one line instead of deal.II's std::terminate or libgomp's warning.
   */
  void
  hide_invalid_thread_counts(int, char **, char **environment);

  /**
   * The environment that bilayer and its libraries read, checked before
   * MPI_Init (where Open MPI ends a bad TMPDIR or working directory with a
   * page of text): the working directory, the thread counts
   * (hide_invalid_thread_counts()), TMPDIR; mistakes throw a one-line
   * message.
   */
  void
  check_environment();

  /**
   * A process started without mpirun is a job of one process (an MPI
   * singleton). Open MPI's singleton start-up probes the network transports
   * and prepares a run-time server for processes it might spawn: 0.45 s of
   * the 1 s a small run takes on the development machine. One process
   * needs neither, so without a launcher (no OMPI_COMM_WORLD_SIZE, PMI or
   * PMIx rank in the environment) Open MPI is told to start isolated, with
   * the self transport only (0.07 s). Settings the user made win; other MPI
   * implementations ignore these variables.
   */
  void
  start_mpi_alone_quickly();
} // namespace bilayer

#endif
