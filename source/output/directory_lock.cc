#include <bilayer/output/directory_lock.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace bilayer
{
  namespace
  {
    const std::string prefix = "bilayer lock: ";

    /// The text of the lock file open at @p descriptor, without its final
    /// newlines.
    std::string
    content(const int descriptor)
    {
      char          text[256] = {};
      const ssize_t n         = ::pread(descriptor, text, sizeof(text) - 1, 0);
      std::string   s(text, n > 0 ? n : 0);
      while (!s.empty() && s.back() == '\n')
        s.pop_back();
      return s;
    }
  } // namespace


  DirectoryLock::~DirectoryLock()
  {
    release();
  }


  std::string
  DirectoryLock::acquire(const std::string &path, const std::string &directory)
  {
    lock_path           = path;
    bool       created  = false;
    const auto unlocked = [&](const std::string &why) {
      if (descriptor >= 0)
        ::close(descriptor);
      descriptor = -1;
      return why;
    };
    for (;;)
      {
        // A lock file bilayer creates is bilayer's; one that exists must
        // say so (a killed run's), and is locked before it is read.
        descriptor = ::open(lock_path.c_str(),
                            O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW,
                            0644);
        created    = descriptor >= 0;
        if (!created && errno == EEXIST)
          descriptor =
            ::open(lock_path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
        if (descriptor < 0)
          {
            if (errno == ENOENT)
              continue; // removed by its holder in between
            return unlocked("cannot create the lock file '" + lock_path +
                            "': " + std::strerror(errno));
          }
        if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
          {
            std::string holder = content(descriptor);
            if (holder.rfind(prefix, 0) == 0)
              holder = holder.substr(prefix.size());
            return unlocked(
              "'" + directory + "' is being written by another run (" +
              (holder.empty() ? "lock '" + lock_path + "'" : holder) +
              "); wait for it to end or choose another directory");
          }
        // The holder before us may have removed the file after we opened
        // it: then lock the new one.
        struct stat held, named;
        if (::fstat(descriptor, &held) == 0 &&
            ::stat(lock_path.c_str(), &named) == 0 &&
            held.st_ino == named.st_ino && held.st_dev == named.st_dev)
          {
            if (!created && content(descriptor).rfind(prefix, 0) != 0)
              return unlocked("'" + directory +
                              ".lock' exists and is not a lock "
                              "file of bilayer; choose another directory");
            break;
          }
        ::close(descriptor);
        descriptor = -1;
      }
    // From here on the lock file is bilayer's (created now, or a killed
    // run's), and release() removes it.
    char host[256] = {};
    ::gethostname(host, sizeof(host) - 1);
    const std::string text =
      prefix + "process " + std::to_string(::getpid()) + " on " + host + "\n";
    if (::ftruncate(descriptor, 0) != 0 ||
        ::pwrite(descriptor, text.data(), text.size(), 0) !=
          static_cast<ssize_t>(text.size()))
      {
        const std::string why = std::strerror(errno);
        release();
        return "cannot write the lock file '" + lock_path + "': " + why;
      }
    return "";
  }


  void
  DirectoryLock::release()
  {
    if (descriptor < 0)
      return;
    ::unlink(lock_path.c_str());
    ::close(descriptor);
    descriptor = -1;
  }
} // namespace bilayer
