#ifndef bilayer_output_directory_h
#define bilayer_output_directory_h

#include <cstdint>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * A run's output directory, written whole or not at all, and never at the
   * cost of files that bilayer did not write.
   *
   * The run writes into staging() (DIR.partial next to DIR, created
   * afresh); commit(true) then replaces DIR by it, commit(false) renames it
   * to DIR.failed for inspection. A refused or failed run leaves DIR as it
   * was. Every directory bilayer creates holds the marker file
   * marker_name(); bilayer deletes or replaces a directory (DIR,
   * DIR.partial, DIR.failed) only if it holds that marker, is empty, or
   * holds nothing but files with the names of bilayer's outputs (results of
   * versions before the marker).
   *
   * The constructor refuses, with a one-line message naming Output/Output
   * directory, before anything is computed:
   *  - a name that is no directory a run may replace ("", ".", "..", a
   *    root), a symbolic link (also a dangling one), a file, a mount point;
   *  - a directory that is, or contains, the working directory or one of
   *    the run's input files (compared as canonical paths, so "$PWD",
   *    "sub/..", "x/." and the like are recognised);
   *  - a directory holding files that bilayer did not write;
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

    /// Move the staged results into place (@p success) or aside to
    /// DIR.failed; returns where they are. A successful run also removes a
    /// DIR.failed of an earlier failed run (it no longer describes DIR).
    std::string
    commit(const bool success);

    /// Free bytes on the file system of the staging directory.
    std::uintmax_t
    free_bytes() const;

    /// The file that marks a directory as written by bilayer.
    static const char *
    marker_name();

  private:
    /// Remove the staging directory unless committed, release the lock.
    void
    release();

    std::string final_path, staging_path, lock_path;
    int         lock_descriptor = -1;
    bool        lock_created    = false;
    bool        committed       = false;
    /// Parent directories created for this run, deepest first.
    std::vector<std::string> created_parents;
  };
} // namespace bilayer

#endif
