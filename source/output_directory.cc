#include <deal.II/base/exceptions.h>

#include <bilayer/output_directory.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    namespace fs = std::filesystem;

    const std::string entry = "Output/Output directory";

    [[noreturn]] void
    refuse(const std::string &message)
    {
      throw dealii::ExcMessage(entry + ": " + message);
    }

    const std::string manifest_prefix = "file: ";
    const std::string marker_text =
      "This directory was written by bilayer. A later run into it replaces "
      "it whole as long as it holds only the files listed here.\n";

    /**
     * Whether bilayer may delete the directory @p path: it is empty, or its
     * marker lists every file in it (the marker of a committed directory
     * lists the files the run wrote; a staging directory's marker lists
     * none, which is enough for @p staging directories). Otherwise
     * @p foreign names one entry that bilayer did not write.
     */
    bool
    written_by_bilayer(const fs::path &path,
                       const bool      staging,
                       std::string    &foreign)
    {
      std::error_code       error;
      std::set<std::string> listed;
      bool                  marked = false;
      const fs::path        marker = path / StagedDirectory::marker_name();
      if (fs::is_regular_file(fs::symlink_status(marker, error)))
        {
          std::ifstream in(marker);
          std::string   line;
          marked = std::getline(in, line) &&
                   line.rfind("This directory was written by bilayer", 0) == 0;
          while (marked && std::getline(in, line))
            if (line.rfind(manifest_prefix, 0) == 0)
              listed.insert(line.substr(manifest_prefix.size()));
        }
      for (fs::directory_iterator it(path, error), end; !error && it != end;
           it.increment(error))
        {
          const std::string name = it->path().filename().string();
          if ((marked && name == StagedDirectory::marker_name()) ||
              listed.count(name) > 0 || (marked && staging))
            continue;
          if (foreign.empty())
            foreign = name;
        }
      if (error)
        {
          foreign = "(cannot list it: " + error.message() + ")";
          return false;
        }
      if (!foreign.empty())
        foreign = "'" + foreign + "'" +
                  (marked ? "" :
                            ", and no marker file " +
                              std::string(StagedDirectory::marker_name()) +
                              " of a bilayer run");
      return foreign.empty();
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
    final_path = resolved.string();
    // staging_path is set once this run has created the directory: until
    // then there is nothing of this run's to remove.
    const std::string staging = final_path + ".partial";
    lock_path                 = final_path + ".lock";

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
            if (!fs::is_regular_file(status))
              refuse(shown + " exists and is not a lock file of bilayer; "
                             "choose another directory");
            continue; // its content is checked once it is locked
          }
        if (fs::is_symlink(status))
          refuse(shown + " is a symbolic link; choose another directory");
        if (!fs::is_directory(status))
          refuse(shown + " exists and is not a directory");
        std::string foreign;
        if (!written_by_bilayer(path,
                                suffix != "" && suffix != ".failed",
                                foreign))
          refuse(shown + " holds files that bilayer did not write (" + foreign +
                 "); bilayer replaces an output directory only if it holds "
                 "nothing but what a run of bilayer wrote: choose another "
                 "directory or move the files");
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

    // One run at a time per directory. Parent directories the run creates
    // go again if it is refused.
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
    const auto unlocked = [&](const std::string &why) {
      if (lock_descriptor >= 0)
        ::close(lock_descriptor);
      lock_descriptor = -1;
      release();
      refuse(why);
    };
    for (;;)
      {
        // A lock file bilayer creates is bilayer's; one that exists must
        // say so (a killed run's), and is locked before it is read.
        lock_descriptor =
          ::open(lock_path.c_str(),
                 O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW,
                 0644);
        lock_created = lock_descriptor >= 0;
        if (!lock_created && errno == EEXIST)
          lock_descriptor =
            ::open(lock_path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
        if (lock_descriptor < 0)
          {
            if (errno == ENOENT)
              continue; // removed by its holder in between
            unlocked("cannot create the lock file '" + lock_path +
                     "': " + std::strerror(errno));
          }
        const auto content = [&]() {
          char          text[256] = {};
          const ssize_t n = ::pread(lock_descriptor, text, sizeof(text) - 1, 0);
          std::string   s(text, n > 0 ? n : 0);
          while (!s.empty() && s.back() == '\n')
            s.pop_back();
          return s;
        };
        const std::string prefix = "bilayer lock: ";
        if (::flock(lock_descriptor, LOCK_EX | LOCK_NB) != 0)
          {
            std::string holder = content();
            if (holder.rfind(prefix, 0) == 0)
              holder = holder.substr(prefix.size());
            lock_created = false;
            unlocked("'" + directory + "' is being written by another run (" +
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
          {
            if (!lock_created && content().rfind(prefix, 0) != 0)
              unlocked("'" + directory +
                       ".lock' exists and is not a lock "
                       "file of bilayer; choose another directory");
            break;
          }
        ::close(lock_descriptor);
        lock_descriptor = -1;
      }
    // From here on the lock file is bilayer's (created now, or a killed
    // run's), and release() removes it.
    lock_created = true;
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
    fs::create_directory(staging, error);
    std::string problem;
    if (error)
      problem = "cannot create '" + staging + "': " + error.message();
    else
      {
        staging_path = staging;
        // Directory permissions do not stop root: write a file too.
        std::ofstream marker(staging_path + "/" + marker_name());
        marker << marker_text;
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
        if (lock_created)
          ::unlink(lock_path.c_str());
        ::close(lock_descriptor);
        lock_descriptor = -1;
      }
    // Parent directories created for a run that did not commit, if empty.
    if (!committed)
      for (const auto &p : created_parents)
        fs::remove(p, error);
    created_parents.clear();
  }


  std::string
  StagedDirectory::commit(const bool success)
  {
    const std::string target = success ? final_path : final_path + ".failed";
    const std::string old    = target + ".old";
    std::error_code   error;
    // The marker lists what the run wrote: a later run replaces the
    // directory only while it holds nothing else.
    {
      std::vector<std::string> names;
      for (fs::directory_iterator it(staging_path, error), end;
           !error && it != end;
           it.increment(error))
        names.push_back(it->path().filename().string());
      std::sort(names.begin(), names.end());
      errno = 0;
      std::ofstream marker(staging_path + "/" + marker_name());
      marker << marker_text;
      for (const auto &name : names)
        if (name != marker_name())
          marker << manifest_prefix << name << "\n";
      marker.close();
      if (!marker || error)
        refuse("cannot write '" + staging_path + "/" + marker_name() +
               "': " + (error ? error.message() : std::strerror(errno)));
    }
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
            written_by_bilayer(failed, false, foreign))
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
