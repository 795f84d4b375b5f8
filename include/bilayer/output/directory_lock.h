#ifndef bilayer_directory_lock_h
#define bilayer_directory_lock_h

#include <string>

namespace bilayer
{
  /**
   * The lock of an output directory DIR: an exclusive flock() on the file
   * DIR.lock, held for the whole run, so that a second run into the same
   * directory stops at once with the first run's process id (the file
   * says "bilayer lock: process PID on HOST"). The kernel releases the lock
   * of a killed run; its file is then taken over by the next run. A file
   * DIR.lock that bilayer did not write is refused.
   */
  class DirectoryLock
  {
  public:
    DirectoryLock() = default;
    ~DirectoryLock();

    DirectoryLock(const DirectoryLock &) = delete;
    DirectoryLock &
    operator=(const DirectoryLock &) = delete;

    /**
     * Lock the file @p path (created if missing) of the directory the user
     * named @p directory, and write this process's id into it. Returns ""
     * or, holding nothing, why it could not: another run holds it, the file
     * is not bilayer's, it cannot be created or written.
     */
    std::string
    acquire(const std::string &path, const std::string &directory);

    /// Remove the lock file (while still holding it: a run waiting for the
    /// same file notices that the file it locked is gone and locks a new
    /// one) and release the lock; nothing if none is held.
    void
    release();

    /// The lock file.
    const std::string &
    path() const
    {
      return lock_path;
    }

  private:
    std::string lock_path;
    int         descriptor = -1;
  };
} // namespace bilayer

#endif
