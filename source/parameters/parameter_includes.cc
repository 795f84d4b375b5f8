#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/parameter_includes.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /**
     * Refuse a parameter file that is not a regular readable file, and
     * follow its "include" lines (ParameterHandler opens them relative to
     * the working directory) to refuse missing, unreadable or recursive
     * includes before ParameterHandler would recurse into them. Appends the
     * files read to @p files; @p chain holds the files that include it.
     */
    void
    check_parameter_file(const std::string        &filename,
                         std::vector<std::string> &chain,
                         std::vector<std::string> &files)
    {
      namespace fs = std::filesystem;
      const std::string where =
        chain.empty() ?
          "parameter file '" + filename + "'" :
          "file '" + filename + "' included from '" + chain.back() + "'";
      std::error_code error;
      const auto      status = fs::status(filename, error);
      AssertThrow(fs::exists(status),
                  ExcMessage("cannot open " + where + ": no such file"));
      AssertThrow(!fs::is_directory(status),
                  ExcMessage("cannot read " + where + ": it is a directory"));
      AssertThrow(fs::is_regular_file(status),
                  ExcMessage("cannot read " + where +
                             ": it is not a regular file (a device, pipe or "
                             "socket)"));
      constexpr std::uintmax_t limit = 1 << 24;
      AssertThrow(fs::file_size(filename, error) <= limit,
                  ExcMessage("cannot read " + where +
                             ": larger than 16 MiB, not a parameter file"));
      const std::string canonical = fs::canonical(filename, error).string();
      for (const auto &open : chain)
        AssertThrow(fs::canonical(open, error).string() != canonical,
                    ExcMessage("the " + where +
                               " includes itself (directly or through other "
                               "files)"));
      AssertThrow(chain.size() < 16,
                  ExcMessage("the " + where +
                             " is included more than 16 levels deep"));
      std::ifstream in(filename);
      AssertThrow(in,
                  ExcMessage("cannot read " + where + ": " +
                             std::strerror(errno)));
      files.push_back(filename);
      chain.push_back(filename);
      std::string  line;
      unsigned int n = 0;
      while (std::getline(in, line))
        {
          ++n;
          const auto comment = line.find('#');
          if (comment != std::string::npos)
            line.erase(comment);
          line = Utilities::trim(line);
          if (line.rfind("include ", 0) == 0 || line.rfind("INCLUDE ", 0) == 0)
            check_parameter_file(Utilities::trim(line.substr(8)), chain, files);
        }
      AssertThrow(!in.bad(),
                  ExcMessage("reading " + where + " failed at line " +
                             std::to_string(n + 1) + ": " +
                             std::strerror(errno)));
      chain.pop_back();
    }
  } // namespace


  std::vector<std::string>
  parameter_files(const std::string &filename)
  {
    std::vector<std::string> chain, files;
    check_parameter_file(filename, chain, files);
    return files;
  }
} // namespace bilayer
