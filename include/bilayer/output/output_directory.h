#ifndef bilayer_output_directory_h
#define bilayer_output_directory_h

#include <bilayer/output/directory_lock.h>

#include <cstdint>
#include <set>
#include <string>
#include <sys/types.h>
#include <vector>

namespace bilayer
{
  /**
   * A run's output directory, written whole or not at all, and never at the
   * cost of files that bilayer did not write.
   *
   * The run writes into staging() (DIR.partial next to DIR, created
   * afresh); commit(true) then replaces DIR by it, commit(false) puts it at
   * DIR.failed for inspection. A refused or failed run leaves DIR as it
   * was.
   *
   * Identity. Every directory bilayer creates holds the marker file
   * marker_name(), which records the directory it was made for (its
   * absolute path), the device and inode number of the directory and a
   * random token (also stored as the extended attribute user.bilayer-output
   * of the directory where the file system keeps one), and, once
   * committed, the files the run wrote. A directory is bilayer's own only
   * if all of these match the directory itself: a copy (cp -r, cp -a,
   * rsync, a tar round trip) has another inode, a moved or renamed one
   * another path, a marker of an earlier version (no identity) or a
   * hand-written one is not bilayer's. bilayer removes only its own
   * directories, and from them only the files its marker lists (names of
   * bilayer's outputs), then the directory if it is empty; whatever else it
   * holds stays. DIR, DIR.partial, DIR.failed and DIR.lock are the only
   * names beside DIR a run uses; DIR is moved aside under a name that
   * cannot exist yet (DIR.replaced-TOKEN, renamed without replacing) while
   * it is replaced, and a stopped run's staging directory to
   * DIR.partial.stopped-TOKEN while it is emptied.
   *
   * The constructor refuses, with a one-line message naming Output/Output
   * directory, before anything is computed:
   *  - a name that is no directory a run may replace ("", ".", "..", a
   *    root), a symbolic link (also a dangling one), a file, a mount point;
   *  - a directory that is, or contains, the working directory or one of
   *    the run's input files (compared as canonical paths, so "$PWD",
   *    "sub/..", "x/." and the like are recognised);
   *  - a DIR, DIR.partial or DIR.failed that is not empty and not bilayer's
   *    own (above), or holds files its marker does not list;
   *  - a directory another run is writing: runs hold an exclusive lock
   *    (flock) on DIR.lock for their whole duration, so a second run into
   *    the same directory stops at once with the first run's process id.
   *    The kernel releases the lock of a killed run.
   * A StagedDirectory destroyed without a successful commit() (an exception
   * during the run) removes its staging directory; a failed commit()
   * leaves DIR (and DIR.failed) as they were.
   */
  class StagedDirectory
  {
  public:
    /**
     * @p inputs are the files the run reads (parameter file, mesh files):
     * the directory may neither be one of them nor contain one.
     */
    StagedDirectory(const std::string              &directory,
                    const std::vector<std::string> &inputs);
    ~StagedDirectory();

    StagedDirectory(const StagedDirectory &) = delete;
    StagedDirectory &
    operator=(const StagedDirectory &) = delete;

    const std::string &
    staging() const
    {
      return staging_path;
    }

    /**
     * Throw (a one-line message) unless the staging directory is still the
     * one this run created (path, device, inode, token) and holds every
     * file it held at the previous call: a staging directory removed,
     * replaced or emptied during the run is not published. Called before
     * each cycle's files are written and by commit().
     */
    void
    verify();

    /// Move the staged results into place (@p success) or aside to
    /// DIR.failed; returns where they are. A successful run also removes a
    /// DIR.failed of an earlier failed run (it no longer describes DIR).
    std::string
    commit(const bool success);

    /// The device and inode number of the staging directory.
    std::uintmax_t
    device_id() const
    {
      return device;
    }

    std::uintmax_t
    inode_id() const
    {
      return inode;
    }

    /// Free bytes on the file system of the staging directory.
    std::uintmax_t
    free_bytes() const;

    /// The file that marks a directory as written by bilayer.
    static const char *
    marker_name();

    /// Whether @p name is the name of a file a run writes into its output
    /// directory (with @p temporary, also the name of a file being written).
    /// A new kind of output file needs its name here: the marker lists only
    /// these, and a later run refuses a directory holding anything else.
    static bool
    is_output_name(const std::string &name, const bool temporary);

  private:
    /// Remove the staging directory unless committed, release the lock.
    void
    release();

    /// Remove the staging directory's own files and the directory (if it
    /// is still this run's), after renaming it out of the way if
    /// @p move_first; names what stays on the standard error.
    void
    discard_staging(const bool move_first);
    void
    verify_locked();
    /// Create the missing parents of the output directory @p directory,
    /// noted in created_parents (removed again by release()).
    void
    create_parents(const std::string &directory);
    /// Create the staging directory @p staging with its identity and
    /// marker; "" or why it cannot.
    std::string
    create_staging(const std::string &staging);
    /// The identity line of the marker (device, inode, token).
    std::string
    identity() const;

    friend void
    stop_on_signal(const int signal);

    std::string   final_path, staging_path;
    DirectoryLock lock;
    bool          committed = false;
    /// The identity of the staging directory.
    dev_t       device = 0;
    ino_t       inode  = 0;
    std::string token;
    /// The files verify() found at its previous call.
    std::set<std::string> seen;
    /// Parent directories created for this run, deepest first.
    std::vector<std::string> created_parents;
  };

  /**
   * Note which of SIGHUP, SIGINT and SIGTERM the program was started with
   * ignored (nohup, a background job), before libraries install their
   * handlers (MPI_Init); ignore SIGPIPE: a closed pipe on the standard
   * output ends the progress output, not the run.
   */
  void
  prepare_stop_signals();

  /**
   * Catch SIGHUP, SIGINT and SIGTERM (those not ignored at
   * prepare_stop_signals()): a thread of its own then removes the staging
   * directory and the lock of the run (if any), says so in one line on the
   * standard error if @p report (the first process), and ends the process
   * by the signal (exit status 128 + signal). Call after MPI_Init.
   */
  void
  watch_stop_signals(const bool report);

  /**
   * Where a stop signal has arrived (watch_stop_signals()), wait for the
   * watching thread to end the process: called before an error line is
   * printed, so that a run stopped while it writes reports the stop alone.
   * Returns at once otherwise.
   */
  void
  wait_if_stopping();
} // namespace bilayer

#endif
