#include <deal.II/base/exceptions.h>

#include <bilayer/output/directory_anchor.h>
#include <bilayer/output/output_directory.h>
#include <bilayer/output/output_marker.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <stdio.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/xattr.h>
#include <thread>
#include <unistd.h>

namespace bilayer
{
  using namespace dealii;
  using namespace output_marker;

  namespace
  {
    namespace fs = std::filesystem;

    const std::string entry = "Output/Output directory";

    [[noreturn]] void
    refuse(const std::string &message)
    {
      throw dealii::ExcMessage(entry + ": " + message);
    }

    /// The run whose staging directory a signal removes; guarded.
    std::mutex       guard;
    StagedDirectory *live = nullptr;

    /// Rename without replacing what exists at @p to (an empty directory
    /// too); errno on failure.
    bool
    rename_new(const std::string &from, const std::string &to)
    {
      if (::renameat2(
            AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) ==
          0)
        return true;
      if (errno != EINVAL && errno != ENOSYS)
        return false;
      // A file system without RENAME_NOREPLACE (NFS): checked, then
      // renamed (rename() would also replace an empty directory).
      struct stat existing;
      if (::lstat(to.c_str(), &existing) == 0)
        {
          errno = EEXIST;
          return false;
        }
      return std::rename(from.c_str(), to.c_str()) == 0;
    }
    /// Whether @p ancestor is @p path or one of its parent directories
    /// (both canonical).
    bool
    is_or_contains(const fs::path &ancestor, const fs::path &path)
    {
      auto a = ancestor.begin();
      auto p = path.begin();
      for (; a != ancestor.end(); ++a, ++p)
        if (p == path.end() || *a != *p)
          return false;
      return true;
    }

    std::string
    in_quotes(const fs::path &path)
    {
      return "'" + path.string() + "'";
    }

    /// The absolute path of the output directory @p directory, symbolic
    /// links among its parents resolved; refuses names that are no
    /// directory a run may replace and a symbolic link.
    fs::path
    resolve_directory(const std::string &directory)
    {
      std::error_code error;
      if (directory.empty())
        refuse("must name a directory, got ''");
      fs::path absolute = fs::absolute(directory, error).lexically_normal();
      if (!absolute.empty() && absolute.filename().empty())
        absolute = absolute.parent_path(); // a trailing separator
      const std::string name = absolute.filename().string();
      if (name.empty() || name == "." || name == ".." ||
          absolute == absolute.root_path())
        refuse("must name a directory that a run may create or replace (not "
               "'.', '..' or a root), got '" +
               directory + "'");
      if (fs::is_symlink(fs::symlink_status(absolute, error)))
        refuse("'" + directory +
               "' is a symbolic link; name the directory itself (a run "
               "replaces the directory, not what a link points to)");
      // Symbolic links among the parent directories are resolved.
      const fs::path resolved = fs::weakly_canonical(absolute, error);
      if (error)
        refuse("cannot resolve '" + directory + "': " + error.message());
      return resolved;
    }


    /// The names beside DIR that a run uses: DIR, DIR.partial, DIR.failed,
    /// DIR.lock.
    const std::vector<std::string> &
    companion_suffixes()
    {
      static const std::vector<std::string> suffixes = {"",
                                                        ".partial",
                                                        ".failed",
                                                        ".lock"};
      return suffixes;
    }


    /// Refuse an output directory (@p final_path, as the user wrote it
    /// @p directory) that is, or whose companions are or contain, the
    /// working directory or one of the @p inputs.
    void
    refuse_inputs_inside(const std::string              &final_path,
                         const std::string              &directory,
                         const std::vector<std::string> &inputs)
    {
      std::error_code error;
      const auto     &suffixes = companion_suffixes();
      // Nothing the run reads may be inside what it replaces.
      std::vector<std::pair<fs::path, std::string>> protected_paths;
      protected_paths.emplace_back(fs::current_path(error),
                                   "the working directory");
      for (const auto &input : inputs)
        {
          const fs::path p = fs::canonical(input, error);
          if (!error)
            protected_paths.emplace_back(p, "the input file '" + input + "'");
        }
      for (const auto &[path, what] : protected_paths)
        for (const auto &suffix : suffixes)
          if (is_or_contains(fs::path(final_path + suffix), path))
            refuse(
              "'" + directory + "' " +
              (suffix.empty() ? "" : "(its companion " + suffix + ") ") +
              (fs::path(final_path + suffix) == path ? "is " : "contains ") +
              what +
              ", which a run would delete; choose a directory of its own");
    }


    /// Refuse a DIR, DIR.partial, DIR.failed that bilayer may not remove,
    /// a DIR.lock that is no regular file and a DIR that is a mount point.
    void
    refuse_foreign_companions(const fs::path    &resolved,
                              const std::string &directory)
    {
      std::error_code   error;
      const std::string final_path = resolved.string();
      const auto       &suffixes   = companion_suffixes();
      // Each directory a run may delete must be bilayer's own.
      for (const auto &suffix : suffixes)
        {
          const fs::path path   = final_path + suffix;
          const auto     status = fs::symlink_status(path, error);
          if (!fs::exists(status))
            continue;
          const std::string shown = "'" + directory + suffix + "'";
          if (suffix == ".lock")
            {
              if (!fs::is_regular_file(status))
                refuse(shown + " exists and is not a lock file of bilayer; "
                               "choose another directory");
              continue; // its content is checked once it is locked
            }
          if (fs::is_symlink(status))
            refuse(shown + " is a symbolic link; choose another directory");
          if (!fs::is_directory(status))
            refuse(shown + " exists and is not a directory");
          std::string why;
          if (!removable(path, suffix == ".partial", why))
            refuse(shown + " " + why +
                   "; bilayer replaces an output directory only if it is the "
                   "very directory a run of bilayer made there and holds "
                   "nothing but what that run wrote: choose another directory "
                   "or move it");
        }
      if (fs::is_directory(resolved, error))
        {
          struct stat own, parent;
          if (::stat(final_path.c_str(), &own) == 0 &&
              ::stat(resolved.parent_path().c_str(), &parent) == 0 &&
              own.st_dev != parent.st_dev)
            refuse("'" + directory +
                   "' is a mount point; a run replaces its output directory "
                   "by renaming, which cannot move a mount point: choose a "
                   "directory inside it");
        }
    }


    /// Remove a staging directory @p staging left by a killed run (its own
    /// files); "" or why it cannot.
    std::string
    clear_stale_staging(const std::string &staging,
                        const std::string &directory)
    {
      std::error_code error;
      // A staging directory left by a killed run is stale now (its own files
      // go; checked above).
      if (fs::exists(fs::symlink_status(staging, error)))
        {
          std::string why;
          if (!removable(staging, true, why))
            return "'" + directory + ".partial' " + why + "; move it";
          const std::string left = remove_own(staging, true);
          if (!left.empty())
            return "'" + directory + ".partial' (of an earlier run) holds '" +
                   left + "', which bilayer did not write; move it";
        }
      return "";
    }


    /// 32 random hexadecimal digits.
    std::string
    random_token()
    {
      std::random_device random;
      std::ostringstream hex;
      for (int i = 0; i < 4; ++i)
        {
          char word[9];
          std::snprintf(word, sizeof(word), "%08x", random());
          hex << word;
        }
      return hex.str();
    }
  } // namespace


  const char *
  StagedDirectory::marker_name()
  {
    return ".bilayer-output";
  }


  bool
  StagedDirectory::is_output_name(const std::string &name, const bool temporary)
  {
    static const std::regex output(
      "(used_parameters\\.prm|summary\\.json|table\\.(txt|tex|csv)|growth\\.csv|"
      "cohesive(-[0-9]{4,})?\\.csv|"
      "interface([2-9]|[1-9][0-9]+)?\\.pvd|solution\\.(pvd|xdmf)|"
      "interface([2-9]|[1-9][0-9]+)?-[0-9]{2,}\\.(csv|vtu)|"
      "solution-[0-9]{2,}\\.pvtu|"
      "solution-[0-9]{2,}-(u|v|w[0-9]+)-(minus|plus|r[0-9]+)(\\.[0-9]+)?\\."
      "(vtu|h5))");
    const std::string suffix = ".part";
    if (temporary && name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      return std::regex_match(name.substr(0, name.size() - suffix.size()),
                              output);
    return std::regex_match(name, output);
  }


  void
  StagedDirectory::create_parents(const std::string &directory)
  {
    std::error_code error;
    const fs::path  resolved = directory;
    for (fs::path p = resolved.parent_path();
         !p.empty() && !fs::exists(fs::symlink_status(p, error));
         p = p.parent_path())
      {
        created_parents.push_back(p.string());
        if (p == p.root_path())
          break;
      }
    fs::create_directories(resolved.parent_path(), error);
    if (error)
      {
        const std::string why = error.message();
        release();
        refuse("cannot create '" + resolved.parent_path().string() +
               "': " + why);
      }
  }


  std::string
  StagedDirectory::create_staging(const std::string &staging)
  {
    std::string problem;
    if (::mkdir(staging.c_str(), 0777) != 0)
      problem = "cannot create '" + staging + "': " + std::strerror(errno);
    else
      {
        staging_path = staging;
        struct stat own;
        ::lstat(staging_path.c_str(), &own);
        device = own.st_dev;
        inode  = own.st_ino;
        token  = random_token();
        // Directory permissions do not stop root: write a file too.
        errno = 0;
        if (!write_marker(staging_path, identity(), staging_path, {}))
          {
            problem = "cannot write into '" + staging_path +
                      "': " + std::strerror(errno);
            // Neither marker nor attribute names the directory this run:
            // it goes now, with the marker's temporary if that was made
            // (rmdir removes only an empty directory).
            ::unlink((staging_path + "/" + temporary_name()).c_str());
            if (::rmdir(staging_path.c_str()) == 0)
              staging_path.clear();
          }
        seen = {marker_name()};
      }
    return problem;
  }


  StagedDirectory::StagedDirectory(const std::string              &directory,
                                   const std::vector<std::string> &inputs)
  {
    // A signal waits until the directory is set up (or refused).
    const std::lock_guard<std::mutex> hold(guard);
    const fs::path                    resolved = resolve_directory(directory);
    final_path                                 = resolved.string();
    // staging_path is set once this run has created the directory: until
    // then there is nothing of this run's to remove.
    const std::string staging = final_path + ".partial";
    refuse_inputs_inside(final_path, directory, inputs);
    refuse_foreign_companions(resolved, directory);

    // One run at a time per directory. Parent directories the run creates
    // go again if it is refused.
    create_parents(final_path);
    const std::string locked = lock.acquire(final_path + ".lock", directory);
    if (!locked.empty())
      {
        release();
        refuse(locked);
      }
    live = this;

    std::string problem = clear_stale_staging(staging, directory);
    if (problem.empty())
      problem = create_staging(staging);
    if (!problem.empty())
      {
        release();
        refuse(problem);
      }
  }


  std::string
  StagedDirectory::identity() const
  {
    // Where the file system keeps extended attributes, the token is one
    // of the directory's too (a copy that keeps the marker's inode number
    // by chance does not have it).
    const bool in_attribute = store_attribute_token(staging_path, token);
    return std::to_string(static_cast<std::uintmax_t>(device)) + " " +
           std::to_string(static_cast<std::uintmax_t>(inode)) + " " + token +
           (in_attribute ? " attribute" : " file");
  }


  StagedDirectory::~StagedDirectory()
  {
    const std::lock_guard<std::mutex> hold(guard);
    release();
  }


  void
  StagedDirectory::discard_staging(const bool move_first)
  {
    if (committed || staging_path.empty())
      return;
    std::string staged = staging_path;
    staging_path.clear();
    // Moved under another name during the run: the files written into it
    // since are this run's too, removed where the directory is now.
    const std::string moved = moved_location(device, inode);
    if (!moved.empty())
      staged = moved;
    // Only the directory this run made (its marker or, if the marker was
    // removed, its extended attribute holds the token), and only its own
    // files in it.
    struct stat own;
    if (::lstat(staged.c_str(), &own) != 0 || own.st_dev != device ||
        own.st_ino != inode ||
        (read_marker(staged).token != token &&
         attribute_token(staged) != token))
      return;
    std::string path = staged;
    // (Writes still under way then fail instead of adding files.)
    if (move_first && moved.empty() &&
        rename_new(staged, staged + ".stopped-" + token))
      path = staged + ".stopped-" + token;
    const std::string left = remove_own(path, true);
    if (!left.empty())
      std::cerr << "bilayer: note: kept '" << path << "': it holds '" << left
                << "', which bilayer did not write" << std::endl;
  }


  void
  StagedDirectory::release()
  {
    discard_staging(false);
    lock.release();
    // Parent directories created for a run that did not commit, if empty.
    std::error_code error;
    if (!committed)
      for (const auto &p : created_parents)
        fs::remove(p, error);
    created_parents.clear();
    if (live == this)
      live = nullptr;
  }


  void
  StagedDirectory::verify()
  {
    const std::lock_guard<std::mutex> hold(guard);
    verify_locked();
  }


  void
  StagedDirectory::verify_locked()
  {
    const std::string shown = in_quotes(staging_path);
    struct stat       own;
    if (::lstat(staging_path.c_str(), &own) != 0)
      refuse(shown + " was removed during the run (" + std::strerror(errno) +
             "): the results are incomplete and nothing is published; run "
             "again");
    if (own.st_dev != device || own.st_ino != inode ||
        read_marker(staging_path).token != token)
      refuse(shown +
             " was replaced during the run by a directory this run did not "
             "make: the results are incomplete and nothing is published (" +
             shown + " is left as it is); run again");
    std::error_code       error;
    std::set<std::string> now;
    for (fs::directory_iterator it(staging_path, error), end;
         !error && it != end;
         it.increment(error))
      now.insert(it->path().filename().string());
    if (error)
      refuse("cannot list " + shown + ": " + error.message());
    for (const auto &name : seen)
      if (now.count(name) == 0)
        refuse("'" + name + "' was removed from " + shown +
               " during the run: the results are incomplete and nothing is "
               "published; run again");
    seen.clear();
    for (const auto &name : now)
      if (name != temporary_name() &&
          !(name.size() > 5 && name.compare(name.size() - 5, 5, ".part") == 0))
        seen.insert(name);
  }


  std::string
  StagedDirectory::commit(const bool success)
  {
    const std::lock_guard<std::mutex> hold(guard);
    const std::string target = success ? final_path : final_path + ".failed";
    // Only the complete directory this run made is published.
    verify_locked();
    for (const std::string required : {"used_parameters.prm", "summary.json"})
      if ((success || required != "summary.json") && seen.count(required) == 0)
        refuse("'" + staging_path + "' lacks " + required +
               ": the results are incomplete and nothing is published");
    std::error_code error;
    // Checked again (it may have changed since the run began), before the
    // marker names it.
    const bool replacing = fs::exists(fs::symlink_status(target, error));
    if (replacing)
      {
        std::string why;
        if (!fs::is_directory(fs::symlink_status(target, error)) ||
            !removable(target, false, why))
          {
            // The results stay where they are (a later run removes them).
            const std::string staged = staging_path;
            staging_path.clear();
            refuse("'" + target + "' " +
                   (why.empty() ? std::string("is no directory") : why) +
                   " (it changed during the run and is left as it is); the "
                   "results are in '" +
                   staged + "'");
          }
      }
    // The marker lists bilayer's files of the run and names the directory
    // they go to: a later run replaces it only while it is this directory
    // and holds nothing else (a file the user put into DIR.partial goes
    // along, unlisted, and keeps DIR from being replaced).
    {
      std::vector<std::string> names;
      for (const auto &name : seen)
        if (is_output_name(name, false))
          names.push_back(name);
      errno = 0;
      if (!write_marker(staging_path, identity(), target, names))
        refuse("cannot write '" + staging_path + "/" + marker_name() +
               "': " + std::strerror(errno));
    }
    const std::string aside       = target + ".replaced-" + token;
    bool              moved_aside = false;
    if (replacing)
      {
        if (!rename_new(target, aside))
          refuse("cannot move the previous '" + target + "' aside to '" +
                 aside + "': " + std::strerror(errno) + " (it is unchanged)");
        moved_aside = true;
      }
    if (!rename_new(staging_path, target))
      {
        const std::string why = std::strerror(errno);
        if (moved_aside)
          rename_new(aside, target);
        refuse("cannot move the results from '" + staging_path + "' to '" +
               target + "': " + why + " ('" + target + "' is unchanged)");
      }
    committed = true;
    if (moved_aside)
      {
        const std::string left = remove_own(aside, false);
        if (!left.empty())
          std::cerr << "bilayer: note: kept the previous '" << target
                    << "' as '" << aside << "': it holds '" << left
                    << "', which bilayer did not write" << std::endl;
      }
    if (success)
      {
        // A failed run's results no longer describe the directory.
        std::string       why;
        const std::string failed = final_path + ".failed";
        if (fs::is_directory(fs::symlink_status(failed, error)) &&
            removable(failed, false, why))
          remove_own(failed, false);
      }
    return target;
  }


  std::uintmax_t
  StagedDirectory::free_bytes() const
  {
    std::error_code error;
    const auto      space = fs::space(staging_path, error);
    return error ? static_cast<std::uintmax_t>(-1) : space.available;
  }


  namespace
  {
    const int stop_signals[] = {SIGHUP, SIGINT, SIGTERM};
    /// Per signal of stop_signals: ignored when the program started.
    bool ignored_at_start[3] = {false, false, false};
    int  stop_pipe[2]        = {-1, -1};
    /// Set by the signal handler: the watching thread is ending the run.
    volatile std::sig_atomic_t stop_requested = 0;

    extern "C" void
    on_stop_signal(int signal)
    {
      // (Async-signal-safe: the watching thread does the work.)
      stop_requested                       = 1;
      const int                      saved = errno;
      const unsigned char            byte  = static_cast<unsigned char>(signal);
      [[maybe_unused]] const ssize_t n     = ::write(stop_pipe[1], &byte, 1);
      errno                                = saved;
    }
  } // namespace


  void
  stop_on_signal(const int signal)
  {
    const std::lock_guard<std::mutex> hold(guard);
    std::string                       removed;
    if (live != nullptr)
      {
        if (!live->committed && !live->staging_path.empty())
          removed = in_quotes(live->staging_path) + " and ";
        removed += in_quotes(live->lock.path());
        live->discard_staging(true);
        live->release();
      }
    const char *name = signal == SIGHUP ? "SIGHUP" :
                       signal == SIGINT ? "SIGINT" :
                                          "SIGTERM";
    if (!removed.empty())
      std::cerr << "bilayer: error: stopped by " << name << " (removed "
                << removed << "; the output directory is as it was)"
                << std::endl;
    std::signal(signal, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, signal);
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    std::raise(signal);
    std::_Exit(128 + signal);
  }


  void
  wait_if_stopping()
  {
    // The watching thread removes the staging directory, says why in one
    // line and ends the process: an error of the run caused by that (a
    // file written while the directory goes) is not a second line.
    if (stop_requested)
      while (true)
        ::pause();
  }


  void
  prepare_stop_signals()
  {
    for (unsigned int i = 0; i < 3; ++i)
      {
        struct sigaction old;
        if (::sigaction(stop_signals[i], nullptr, &old) == 0)
          ignored_at_start[i] = old.sa_handler == SIG_IGN;
      }
    std::signal(SIGPIPE, SIG_IGN);
  }


  void
  watch_stop_signals(const bool report)
  {
    // Libraries initialised since (PETSc with MPI) install handlers that
    // turn these signals into an error report and MPI_Abort.
    std::signal(SIGPIPE, SIG_IGN);
    if (::pipe2(stop_pipe, O_CLOEXEC) != 0)
      {
        for (unsigned int i = 0; i < 3; ++i)
          std::signal(stop_signals[i], ignored_at_start[i] ? SIG_IGN : SIG_DFL);
        return;
      }
    std::thread([report]() {
      unsigned char byte = 0;
      while (::read(stop_pipe[0], &byte, 1) != 1)
        if (errno != EINTR)
          return;
      if (!report)
        {
          // Other processes have no staging directory to remove.
          std::signal(byte, SIG_DFL);
          std::raise(byte);
        }
      stop_on_signal(byte);
    }).detach();
    for (unsigned int i = 0; i < 3; ++i)
      if (ignored_at_start[i])
        std::signal(stop_signals[i], SIG_IGN);
      else
        {
          struct sigaction action;
          std::memset(&action, 0, sizeof(action));
          action.sa_handler = on_stop_signal;
          sigfillset(&action.sa_mask);
          action.sa_flags = SA_RESTART;
          ::sigaction(stop_signals[i], &action, nullptr);
        }
  }
} // namespace bilayer
