#include <bilayer/output/output_directory.h>
#include <bilayer/output/output_marker.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <sys/xattr.h>
#include <unistd.h>

namespace bilayer
{
  namespace output_marker
  {
    namespace
    {
      namespace fs = std::filesystem;

      const std::string manifest_prefix  = "file: ";
      const std::string identity_prefix  = "identity: ";
      const std::string directory_prefix = "directory: ";
      const std::string marker_title = "This directory was written by bilayer";
      const std::string marker_text =
        marker_title +
        ". A later run into it replaces it as long as it is this very "
        "directory (identity: device, inode, token; directory: where it was "
        "made) and holds only the files listed here.\n";
      const char *attribute = "user.bilayer-output";
      /// The marker while it is rewritten (committing).
      const std::string marker_temporary = std::string(".bilayer-output.part");

      /// Whether @p path is a staging directory DIR.partial whose marker
      /// names DIR or DIR.failed (a run stopped while committing).
      bool
      committing(const fs::path &path, const std::string &named)
      {
        const std::string p      = path.string();
        const std::string suffix = ".partial";
        if (p.size() <= suffix.size() ||
            p.compare(p.size() - suffix.size(), suffix.size(), suffix) != 0)
          return false;
        const std::string final = p.substr(0, p.size() - suffix.size());
        return named == final || named == final + ".failed";
      }
    } // namespace


    std::string
    temporary_name()
    {
      return marker_temporary;
    }


    bool
    store_attribute_token(const std::string &path, const std::string &token)
    {
      return ::lsetxattr(
               path.c_str(), attribute, token.data(), token.size(), 0) == 0;
    }


    Marker
    read_marker(const fs::path &path)
    {
      Marker          m;
      std::error_code error;
      const fs::path  file = path / StagedDirectory::marker_name();
      if (!fs::is_regular_file(fs::symlink_status(file, error)))
        return m;
      std::ifstream in(file);
      std::string   line;
      m.present = std::getline(in, line) && line.rfind(marker_title, 0) == 0;
      while (m.present && std::getline(in, line))
        if (line.rfind(manifest_prefix, 0) == 0)
          m.files.push_back(line.substr(manifest_prefix.size()));
        else if (line.rfind(directory_prefix, 0) == 0)
          m.directory = line.substr(directory_prefix.size());
        else if (line.rfind(identity_prefix, 0) == 0)
          {
            std::istringstream words(line.substr(identity_prefix.size()));
            std::string        where;
            m.identity = static_cast<bool>(words >> m.device >> m.inode >>
                                           m.token >> where) &&
                         m.token.size() == 32;
            m.in_attribute = where == "attribute";
          }
      return m;
    }


    std::string
    attribute_token(const std::string &path)
    {
      char          value[64] = {};
      const ssize_t n         = ::lgetxattr(path.c_str(), attribute, value, 63);
      return n > 0 ? std::string(value, n) : std::string();
    }


    bool
    made_here(const fs::path &path, const Marker &m, std::string &why)
    {
      struct stat own;
      if (!m.identity)
        why = "was written by an earlier version of bilayer or by hand (its "
              "marker " +
              std::string(StagedDirectory::marker_name()) +
              " has no identity), and bilayer removes only directories it "
              "can tell are its own";
      else if (::lstat(path.c_str(), &own) != 0 ||
               static_cast<std::uintmax_t>(own.st_dev) != m.device ||
               static_cast<std::uintmax_t>(own.st_ino) != m.inode ||
               (m.in_attribute && attribute_token(path) != m.token))
        why = "is a copy of a bilayer output directory, not the directory "
              "bilayer made (its marker belongs to another directory)";
      else if (m.directory != path.string() && !committing(path, m.directory))
        why = "was moved or renamed (bilayer made it as '" + m.directory + "')";
      return why.empty();
    }


    bool
    removable(const fs::path &path, const bool staging, std::string &why)
    {
      std::error_code          error;
      const Marker             m = read_marker(path);
      std::vector<std::string> names;
      for (fs::directory_iterator it(path, error), end; !error && it != end;
           it.increment(error))
        names.push_back(it->path().filename().string());
      if (error)
        {
          why = "cannot be listed (" + error.message() + ")";
          return false;
        }
      if (names.empty())
        return true;
      std::string foreign;
      for (const auto &name : names)
        if (!(m.present && (name == StagedDirectory::marker_name() ||
                            (staging && name == marker_temporary))) &&
            !(m.present && staging &&
              StagedDirectory::is_output_name(name, true)) &&
            !(m.present && !staging &&
              std::count(m.files.begin(), m.files.end(), name) > 0 &&
              StagedDirectory::is_output_name(name, false)) &&
            foreign.empty())
          foreign = name;
      if (!m.present)
        {
          why = "holds files that bilayer did not write ('" + foreign +
                "', and no marker file " + StagedDirectory::marker_name() +
                " of a bilayer run)";
          return false;
        }
      if (!made_here(path, m, why))
        return false;
      for (const auto &file : m.files)
        if (!StagedDirectory::is_output_name(file, false))
          {
            why = "has a marker that lists '" + file +
                  "', which is no file bilayer writes";
            return false;
          }
      if (!foreign.empty())
        {
          why = "holds files that bilayer did not write ('" + foreign + "')";
          return false;
        }
      return true;
    }


    std::string
    remove_own(const fs::path &path, const bool staging)
    {
      std::error_code       error;
      const Marker          m = read_marker(path);
      std::set<std::string> own(m.files.begin(), m.files.end());
      // (Its own error code: a file gone between the listing and the test
      // must not end the listing's loop.)
      const auto is_mine = [&](const fs::directory_entry &entry) {
        std::error_code   status_error;
        const std::string name = entry.path().filename().string();
        return (name == StagedDirectory::marker_name() ||
                name == marker_temporary ||
                (staging ? StagedDirectory::is_output_name(name, true) :
                           own.count(name) > 0 &&
                             StagedDirectory::is_output_name(name, false))) &&
               !fs::is_directory(
                 fs::symlink_status(entry.path(), status_error));
      };
      // A staging directory discarded at a stop signal may still receive
      // the file a writing thread had opened before the stop: files of
      // output names that appear after a pass are this run's too, removed by
      // the next pass (for up to a second), never those of other names.
      for (unsigned int pass = 0;; ++pass)
        {
          for (fs::directory_iterator it(path, error), end; !error && it != end;
               it.increment(error))
            if (is_mine(*it))
              ::unlink(it->path().c_str());
          if (::rmdir(path.c_str()) == 0 || errno == ENOENT)
            return "";
          const int   why = errno;
          std::string left;
          bool        only_mine = staging && pass < 50;
          for (fs::directory_iterator it(path, error), end; !error && it != end;
               it.increment(error))
            {
              if (left.empty())
                left = it->path().filename().string();
              only_mine = only_mine && is_mine(*it);
            }
          if (!only_mine || left.empty())
            return left.empty() ? "(" + std::string(std::strerror(why)) + ")" :
                                  left;
          ::usleep(20000);
        }
    }


    bool
    write_marker(const std::string              &directory,
                 const std::string              &identity,
                 const std::string              &named,
                 const std::vector<std::string> &files)
    {
      const std::string temporary = directory + "/" + marker_temporary;
      {
        std::ofstream out(temporary);
        out << marker_text << identity_prefix << identity << "\n"
            << directory_prefix << named << "\n";
        for (const auto &file : files)
          out << manifest_prefix << file << "\n";
        out.close();
        if (!out)
          return false;
      }
      return std::rename(
               temporary.c_str(),
               (directory + "/" + StagedDirectory::marker_name()).c_str()) == 0;
    }
  } // namespace output_marker
} // namespace bilayer
