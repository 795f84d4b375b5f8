#ifndef bilayer_directory_anchor_h
#define bilayer_directory_anchor_h

#include <cstdint>
#include <string>

namespace bilayer
{
  /**
   * A path through which files are written into the very directory that
   * @p path names now, held open for the rest of the process: on Linux
   * /proc/self/fd/N of a descriptor of it (the path itself where /proc is
   * not mounted). Files written through it go nowhere else, even if the
   * directory is removed or replaced under its name during the run: a
   * removed directory takes no new files (the write fails, and the check
   * of the staging directory says why), a directory the user put in its
   * place never receives a file of bilayer's.
   *
   * Throws (a one-line message) unless the directory is the one with
   * @p device and @p inode (the staging directory the run made).
   */
  std::string
  anchor_directory(const std::string   &path,
                   const std::uintmax_t device,
                   const std::uintmax_t inode);

  /// @p text with each anchored path of this process replaced by the
  /// path the user knows (for messages).
  std::string
  unanchored(std::string text);

  /// Where the anchored directory with @p device and @p inode is now, if
  /// it was moved under another name during the run (its descriptor's path
  /// names it still); empty if it was removed, never anchored, or is where
  /// it was anchored.
  std::string
  moved_location(const std::uintmax_t device, const std::uintmax_t inode);
} // namespace bilayer

#endif
