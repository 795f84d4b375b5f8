#include <deal.II/base/exceptions.h>

#include <bilayer/output/directory_anchor.h>

#include <cctype>
#include <climits>
#include <fcntl.h>
#include <map>
#include <mutex>
#include <sys/stat.h>
#include <unistd.h>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The anchored paths of this process and the paths they stand for
    /// (the descriptors stay open until the process ends).
    std::map<std::string, std::string> &
    anchors()
    {
      static std::map<std::string, std::string> all;
      return all;
    }

    std::mutex anchors_guard;
  } // namespace


  std::string
  anchor_directory(const std::string   &path,
                   const std::uintmax_t device,
                   const std::uintmax_t inode)
  {
    const int descriptor =
      ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC | O_NOFOLLOW);
    struct stat own;
    const bool  same = descriptor >= 0 && ::fstat(descriptor, &own) == 0 &&
                      static_cast<std::uintmax_t>(own.st_dev) == device &&
                      static_cast<std::uintmax_t>(own.st_ino) == inode;
    if (!same)
      {
        if (descriptor >= 0)
          ::close(descriptor);
        AssertThrow(false,
                    ExcMessage("'" + path +
                               "' was replaced or removed during the run: "
                               "the results are incomplete and nothing is "
                               "published; run again"));
      }
    const std::string anchored = "/proc/self/fd/" + std::to_string(descriptor);
    struct stat       through;
    if (::stat(anchored.c_str(), &through) != 0 ||
        through.st_dev != own.st_dev || through.st_ino != own.st_ino)
      {
        // No /proc: the path itself.
        ::close(descriptor);
        return path;
      }
    const std::lock_guard<std::mutex> hold(anchors_guard);
    anchors()[anchored] = path;
    return anchored;
  }


  std::string
  unanchored(std::string text)
  {
    const std::lock_guard<std::mutex> hold(anchors_guard);
    for (const auto &[anchored, path] : anchors())
      {
        std::size_t at = 0;
        while ((at = text.find(anchored, at)) != std::string::npos)
          {
            // (/proc/self/fd/1 is no prefix of /proc/self/fd/12.)
            const std::size_t end = at + anchored.size();
            if (end < text.size() && std::isdigit(text[end]))
              {
                at = end;
                continue;
              }
            text.replace(at, anchored.size(), path);
            at += path.size();
          }
      }
    return text;
  }


  std::string
  moved_location(const std::uintmax_t device, const std::uintmax_t inode)
  {
    const std::lock_guard<std::mutex> hold(anchors_guard);
    for (const auto &[anchored, path] : anchors())
      {
        struct stat through;
        if (::stat(anchored.c_str(), &through) != 0 ||
            static_cast<std::uintmax_t>(through.st_dev) != device ||
            static_cast<std::uintmax_t>(through.st_ino) != inode)
          continue;
        struct stat named;
        if (::lstat(path.c_str(), &named) == 0 &&
            named.st_dev == through.st_dev && named.st_ino == through.st_ino)
          return "";
        char          target[PATH_MAX + 1];
        const ssize_t length =
          ::readlink(anchored.c_str(), target, sizeof(target) - 1);
        if (length <= 0)
          return "";
        const std::string now(target, length);
        // (A removed directory's link ends in " (deleted)"; the name must
        // still be this directory's.)
        struct stat there;
        if (::lstat(now.c_str(), &there) != 0 || !S_ISDIR(there.st_mode) ||
            static_cast<std::uintmax_t>(there.st_dev) != device ||
            static_cast<std::uintmax_t>(there.st_ino) != inode)
          return "";
        return now;
      }
    return "";
  }
} // namespace bilayer
