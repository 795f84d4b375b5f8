#ifndef bilayer_output_marker_h
#define bilayer_output_marker_h

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The marker file of a directory bilayer made (StagedDirectory::
   * marker_name()): the directory it was made for, its identity (device,
   * inode and a random token, also kept in the extended attribute
   * user.bilayer-output where the file system has one) and, once committed,
   * the files the run wrote. Whether bilayer may remove a directory is
   * decided from it, and only its own files go.
   */
  namespace output_marker
  {
    /// What a marker file says.
    struct Marker
    {
      bool                     present  = false; // a marker file of bilayer
      bool                     identity = false; // with an identity line
      std::uintmax_t           device = 0, inode = 0;
      std::string              token;
      bool                     in_attribute = false;
      std::string              directory;
      std::vector<std::string> files;
    };

    /// The name of the marker while it is rewritten (committing).
    std::string
    temporary_name();

    /// The marker of the directory @p path (not present: none of bilayer).
    Marker
    read_marker(const std::filesystem::path &path);

    /// The token in the directory's extended attribute, or "".
    std::string
    attribute_token(const std::string &path);

    /// Store @p token as the extended attribute of the directory @p path;
    /// whether the file system keeps it.
    bool
    store_attribute_token(const std::string &path, const std::string &token);

    /**
     * Whether @p path is a directory that bilayer made for @p path itself:
     * its marker's identity (device, inode, token in the extended attribute
     * where it was stored) and directory are those of @p path. Otherwise
     * @p why says what it is.
     */
    bool
    made_here(const std::filesystem::path &path,
              const Marker                &m,
              std::string                 &why);

    /**
     * Whether bilayer may remove the directory @p path, empty or after
     * removing the files of remove_own(): it is empty, or bilayer made it
     * here (made_here()), and every entry is a file its marker lists (a
     * committed directory) or, for @p staging directories, a file with the
     * name of one of bilayer's outputs. Otherwise @p why says why not.
     */
    bool
    removable(const std::filesystem::path &path,
              const bool                   staging,
              std::string                 &why);

    /**
     * Remove from @p path (a directory removable() allowed) the marker and
     * the files bilayer wrote: those its marker lists, or with @p staging
     * those with the names of bilayer's outputs; then the directory if it
     * is empty. Returns an entry that stays, or "".
     */
    std::string
    remove_own(const std::filesystem::path &path, const bool staging);

    /// Write the marker of @p directory (through a temporary file): its
    /// @p identity line, the directory it is @p named for, the @p files.
    bool
    write_marker(const std::string              &directory,
                 const std::string              &identity,
                 const std::string              &named,
                 const std::vector<std::string> &files);
  } // namespace output_marker
} // namespace bilayer

#endif
