#include <deal.II/base/exceptions.h>

#include <bilayer/output_directory.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace bilayer
{
  namespace
  {
    namespace fs = std::filesystem;

    const std::string entry = "Output/Output directory";

    [[noreturn]] void
    refuse(const std::string &message)
    {
      throw dealii::ExcMessage(entry + ": " + message);
    }

    /// The names of the files bilayer writes into an output directory.
    bool
    is_output_name(const std::string &name)
    {
      const auto starts = [&](const std::string &prefix) {
        return name.compare(0, prefix.size(), prefix) == 0;
      };
      const auto ends = [&](const std::string &suffix) {
        return name.size() >= suffix.size() &&
               name.compare(name.size() - suffix.size(),
                            suffix.size(),
                            suffix) == 0;
      };
      std::string base = name;
      if (ends(".part"))
        base = name.substr(0, name.size() - 5);
      for (const char *fixed : {"used_parameters.prm",
                                "summary.json",
                                "table.txt",
                                "table.tex",
                                "table.csv",
                                "solution.pvd",
                                "solution.xdmf",
                                ".probe"})
        if (base == fixed)
          return true;
      const auto has = [&](const std::string &prefix,
                           const std::string &suffix) {
        return base.size() > prefix.size() + suffix.size() &&
               base.compare(0, prefix.size(), prefix) == 0 &&
               base.compare(base.size() - suffix.size(),
                            suffix.size(),
                            suffix) == 0;
      };
      return (starts("solution-") &&
              (has("solution-", ".vtu") || has("solution-", ".pvtu") ||
               has("solution-", ".h5"))) ||
             has("interface-", ".csv");
    }

    /**
     * Whether bilayer may delete the directory @p path: it holds the
     * marker, is empty, or holds only regular files with the names of
     * bilayer's outputs. Otherwise @p foreign names one entry that is not
     * bilayer's.
     */
    bool
    written_by_bilayer(const fs::path &path, std::string &foreign)
    {
      std::error_code error;
      if (fs::is_regular_file(
            fs::symlink_status(path / StagedDirectory::marker_name(), error)))
        return true;
      for (fs::directory_iterator it(path, error), end; !error && it != end;
           it.increment(error))
        {
          const std::string name = it->path().filename().string();
          if (!is_output_name(name) ||
              !fs::is_regular_file(fs::symlink_status(it->path(), error)))
            {
              foreign = name;
              return false;
            }
        }
      if (error)
        {
          foreign = "(cannot list it: " + error.message() + ")";
          return false;
        }
      return true;
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
  } // namespace


  const char *
  StagedDirectory::marker_name()
  {
    return ".bilayer-output";
  }


  StagedDirectory::StagedDirectory(const std::string              &directory,
                                   const std::vector<std::string> &inputs)
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
    final_path   = resolved.string();
    staging_path = final_path + ".partial";
    lock_path    = final_path + ".lock";

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
    const std::vector<std::string> suffixes = {
      "", ".partial", ".failed", ".old", ".failed.old", ".lock"};
    for (const auto &[path, what] : protected_paths)
      for (const auto &suffix : suffixes)
        if (is_or_contains(fs::path(final_path + suffix), path))
          refuse("'" + directory + "' " +
                 (suffix.empty() ? "" : "(its companion " + suffix + ") ") +
                 (fs::path(final_path + suffix) == path ? "is " : "contains ") +
                 what +
                 ", which a run would delete; choose a directory of its own");

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
            std::ifstream lock(path);
            std::string   first;
            std::getline(lock, first);
            if (!fs::is_regular_file(status) ||
                (!first.empty() && first.rfind("bilayer lock", 0) != 0))
              refuse(shown + " exists and is not a lock file of bilayer; "
                             "choose another directory");
            continue;
          }
        if (fs::is_symlink(status))
          refuse(shown + " is a symbolic link; choose another directory");
        if (!fs::is_directory(status))
          refuse(shown + " exists and is not a directory");
        std::string foreign;
        if (!written_by_bilayer(path, foreign))
          refuse(shown + " holds files that bilayer did not write ('" +
                 foreign +
                 "'); a run replaces its output directory whole and only "
                 "ever deletes directories it created: choose another "
                 "directory");
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

    // One run at a time per directory.
    fs::create_directories(resolved.parent_path(), error);
    if (error)
      refuse("cannot create '" + resolved.parent_path().string() +
             "': " + error.message());
    for (;;)
      {
        lock_descriptor = ::open(lock_path.c_str(),
                                 O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW,
                                 0644);
        if (lock_descriptor < 0)
          refuse("cannot create the lock file '" + lock_path +
                 "': " + std::strerror(errno));
        if (::flock(lock_descriptor, LOCK_EX | LOCK_NB) != 0)
          {
            char          text[256] = {};
            const ssize_t n =
              ::pread(lock_descriptor, text, sizeof(text) - 1, 0);
            ::close(lock_descriptor);
            lock_descriptor = -1;
            std::string holder(text, n > 0 ? n : 0);
            while (!holder.empty() && holder.back() == '\n')
              holder.pop_back();
            const std::string prefix = "bilayer lock: ";
            if (holder.rfind(prefix, 0) == 0)
              holder = holder.substr(prefix.size());
            refuse("'" + directory + "' is being written by another run (" +
                   (holder.empty() ?
                      std::string("lock ") + in_quotes(lock_path) :
                      holder) +
                   "); wait for it to end or choose another directory");
          }
        // The holder before us may have removed the file after we opened
        // it: then lock the new one.
        struct stat held, named;
        if (::fstat(lock_descriptor, &held) == 0 &&
            ::stat(lock_path.c_str(), &named) == 0 &&
            held.st_ino == named.st_ino && held.st_dev == named.st_dev)
          break;
        ::close(lock_descriptor);
        lock_descriptor = -1;
      }
    {
      char host[256] = {};
      ::gethostname(host, sizeof(host) - 1);
      const std::string text = "bilayer lock: process " +
                               std::to_string(::getpid()) + " on " + host +
                               "\n";
      if (::ftruncate(lock_descriptor, 0) != 0 ||
          ::pwrite(lock_descriptor, text.data(), text.size(), 0) !=
            static_cast<ssize_t>(text.size()))
        {
          const std::string why = std::strerror(errno);
          release();
          refuse("cannot write the lock file '" + lock_path + "': " + why);
        }
    }

    // A staging or aside directory left by a killed run is stale now.
    for (const std::string suffix : {".partial", ".old", ".failed.old"})
      fs::remove_all(final_path + suffix, error);
    fs::create_directory(staging_path, error);
    std::string problem;
    if (error)
      problem = "cannot create '" + staging_path + "': " + error.message();
    else
      {
        // Directory permissions do not stop root: write a file too.
        std::ofstream marker(staging_path + "/" + marker_name());
        marker << "This directory was written by bilayer; a later run into "
                  "it replaces it whole.\n";
        marker.flush();
        if (!marker)
          problem =
            "cannot write into '" + staging_path + "': " + std::strerror(errno);
      }
    if (!problem.empty())
      {
        release();
        refuse(problem);
      }
  }


  StagedDirectory::~StagedDirectory()
  {
    release();
  }


  void
  StagedDirectory::release()
  {
    std::error_code error;
    if (!committed && !staging_path.empty())
      fs::remove_all(staging_path, error);
    staging_path.clear();
    if (lock_descriptor >= 0)
      {
        // Unlink while holding the lock: a run waiting for the same file
        // notices that the file it locked is gone and locks a new one.
        ::unlink(lock_path.c_str());
        ::close(lock_descriptor);
        lock_descriptor = -1;
      }
  }


  std::string
  StagedDirectory::commit(const bool success)
  {
    const std::string target = success ? final_path : final_path + ".failed";
    const std::string old    = target + ".old";
    std::error_code   error;
    fs::remove_all(old, error);
    bool moved_aside = false;
    if (fs::exists(fs::symlink_status(target, error)))
      {
        fs::rename(target, old, error);
        if (error)
          refuse("cannot move the previous '" + target + "' aside to '" + old +
                 "': " + error.message() + " (it is unchanged)");
        moved_aside = true;
      }
    fs::rename(staging_path, target, error);
    if (error)
      {
        const std::string why = error.message();
        if (moved_aside)
          fs::rename(old, target, error);
        refuse("cannot move the results from '" + staging_path + "' to '" +
               target + "': " + why + " ('" + target + "' is unchanged)");
      }
    committed = true;
    fs::remove_all(old, error);
    if (success)
      {
        // A failed run's results no longer describe the directory.
        std::string       foreign;
        const std::string failed = final_path + ".failed";
        if (fs::is_directory(fs::symlink_status(failed, error)) &&
            written_by_bilayer(failed, foreign))
          fs::remove_all(failed, error);
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
} // namespace bilayer
