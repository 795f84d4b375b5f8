// The check of a .geo scene before gmsh runs it: Gmsh's script language
// split into tokens, and the statements that run programs, write files or
// load files that cannot be checked, in the scene and the files it
// includes.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh/gmsh_file_entry.h>
#include <bilayer/gmsh/gmsh_mesh.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// A token of Gmsh's script language.
    struct Token
    {
      enum class Kind
      {
        name,
        string,
        number,
        symbol
      } kind;
      std::string  text;
      unsigned int line;
      std::size_t  offset;
    };

    /// The tokens of a .geo file: comments (// and /* */) dropped, strings
    /// one token each, ">>" one symbol.
    std::vector<Token>
    tokenize(const std::string &c)
    {
      std::vector<Token> tokens;
      unsigned int       line = 1;
      for (std::size_t i = 0; i < c.size();)
        {
          const char ch = c[i];
          if (ch == '\n')
            {
              ++line;
              ++i;
            }
          else if (std::isspace(static_cast<unsigned char>(ch)))
            ++i;
          else if (c.compare(i, 2, "//") == 0)
            {
              while (i < c.size() && c[i] != '\n')
                ++i;
            }
          else if (c.compare(i, 2, "/*") == 0)
            {
              i += 2;
              while (i < c.size() && c.compare(i, 2, "*/") != 0)
                line += c[i++] == '\n';
              i = std::min(c.size(), i + 2);
            }
          else if (ch == '"')
            {
              const unsigned int first = line;
              const std::size_t  start = i;
              std::string        text;
              // Gmsh's strings have no escapes: the next " ends them.
              for (++i; i < c.size() && c[i] != '"'; ++i)
                {
                  text += c[i];
                  line += c[i] == '\n';
                }
              ++i;
              tokens.push_back({Token::Kind::string, text, first, start});
            }
          else if (std::isalpha(static_cast<unsigned char>(ch)) || ch == '_')
            {
              const std::size_t start = i;
              while (
                i < c.size() &&
                (std::isalnum(static_cast<unsigned char>(c[i])) || c[i] == '_'))
                ++i;
              tokens.push_back(
                {Token::Kind::name, c.substr(start, i - start), line, start});
            }
          else if (std::isdigit(static_cast<unsigned char>(ch)))
            {
              const std::size_t start = i;
              while (i < c.size() &&
                     (std::isalnum(static_cast<unsigned char>(c[i])) ||
                      c[i] == '.' ||
                      ((c[i] == '+' || c[i] == '-') &&
                       (c[i - 1] == 'e' || c[i - 1] == 'E'))))
                ++i;
              tokens.push_back(
                {Token::Kind::number, c.substr(start, i - start), line, start});
            }
          else
            {
              const std::size_t n = c.compare(i, 2, ">>") == 0 ? 2 : 1;
              tokens.push_back({Token::Kind::symbol, c.substr(i, n), line, i});
              i += n;
            }
        }
      return tokens;
    }

    /// The index of the token after the parenthesis that closes the one at
    /// @p open (or the end).
    std::size_t
    after_parentheses(const std::vector<Token> &t, std::size_t open)
    {
      int depth = 0;
      for (std::size_t i = open; i < t.size(); ++i)
        if (t[i].kind == Token::Kind::symbol)
          {
            depth += t[i].text == "(" ? 1 : t[i].text == ")" ? -1 : 0;
            if (depth == 0)
              return i + 1;
          }
      return t.size();
    }

    bool
    is(const std::vector<Token> &t, const std::size_t i, const char *text)
    {
      return i < t.size() && t[i].kind != Token::Kind::string &&
             t[i].text == text;
    }

    /// Why the option @p category.@p name may not be set by a scene, or "".
    std::string
    writing_option(const std::string &category, const std::string &name)
    {
      if (category == "Solver")
        return "Solver options start external solver programs";
      if (category == "Print")
        return "Print options control writing pictures";
      if (category == "General" &&
          (name.find("FileName") != std::string::npos ||
           name.rfind("Save", 0) == 0 || name.rfind("RecentFile", 0) == 0 ||
           name.rfind("Watch", 0) == 0 || name == "TextEditor" ||
           name == "WebBrowser" || name.rfind("Executable", 0) == 0))
        return "this option makes gmsh write or run files";
      return "";
    }

    struct Scan
    {
      const std::string                 &top;
      std::vector<std::filesystem::path> stack;
      std::vector<std::string>           findings;

      void
      file(const std::filesystem::path &path, const std::string &from)
      {
        namespace fs = std::filesystem;
        std::error_code error;
        const fs::path  canonical = fs::weakly_canonical(path, error);
        if (std::find(stack.begin(), stack.end(), canonical) != stack.end())
          {
            findings.push_back(from + ": includes '" + path.string() +
                               "' again inside itself (an endless Include)");
            return;
          }
        std::ifstream in(path);
        if (!fs::is_regular_file(path, error) || !in)
          {
            findings.push_back(from + ": cannot read the included file '" +
                               path.string() + "'");
            return;
          }
        std::stringstream text;
        text << in.rdbuf();
        stack.push_back(canonical);
        statements(path, text.str());
        stack.pop_back();
      }

      void
      statements(const std::filesystem::path &path, const std::string &c)
      {
        const std::vector<Token> t     = tokenize(c);
        const auto               where = [&](const std::size_t i) {
          std::string text = c.substr(t[i].offset, 60);
          text = text.substr(0, text.find_first_of(";\n"));
          return path.string() + ":" + std::to_string(t[i].line) + ": '" +
                 Utilities::trim(text) + "'";
        };
        for (std::size_t i = 0; i < t.size(); ++i)
          {
            // (A name after '.' is an option's or a plugin's.)
            if (t[i].kind != Token::Kind::name || (i > 0 && is(t, i - 1, ".")))
              continue;
            const std::string                              &k = t[i].text;
            static const std::map<std::string, std::string> commands = {
              {"SystemCall", "runs a shell command"},
              {"NonBlockingSystemCall", "runs a shell command"},
              {"System", "runs a shell command"},
              {"OnelabRun", "runs a ONELAB client program"},
              {"Save", "writes a file"},
              {"Print", "writes a picture file"},
              {"SendToServer", "sends data to a ONELAB server"},
              {"CreateDir", "creates a directory"},
              {"RemoveDir", "removes a directory"},
              {"CreateFile", "creates a file"},
              {"DeleteFile", "deletes a file"},
              {"RenameFile", "renames a file"},
              {"ShapeFromFile", "loads a CAD file"},
              {"MergeWithBoundingBox", "loads another file"},
              {"ExternalProcess",
               "runs an external program (a mesh size field)"},
              {"Solver", "Solver options start external solver programs"}};
            const auto command = commands.find(k);
            if (command != commands.end())
              findings.push_back(where(i) + " " + command->second);
            else if (k == "Delete" && i + 1 < t.size() &&
                     (t[i + 1].text == "File" || t[i + 1].text == "Dir" ||
                      t[i + 1].text == "Directory"))
              findings.push_back(where(i) + " deletes a file");
            else if ((k == "Printf" || k == "Sprintf") && is(t, i + 1, "("))
              {
                const std::size_t j = after_parentheses(t, i + 1);
                if (is(t, j, ">") || is(t, j, ">>"))
                  findings.push_back(where(i) + " writes a file");
              }
            else if (k == "Plugin" && is(t, i + 1, "("))
              {
                const std::size_t j = after_parentheses(t, i + 1);
                if (is(t, j, ".") && is(t, j + 1, "Run"))
                  findings.push_back(where(i) +
                                     " runs a plugin (plugins may write "
                                     "files)");
              }
            else if (k == "Include" || k == "Merge")
              {
                if (i + 2 < t.size() && t[i + 1].kind == Token::Kind::string &&
                    is(t, i + 2, ";"))
                  {
                    std::filesystem::path included(t[i + 1].text);
                    if (included.is_relative())
                      included = path.parent_path() / included;
                    if (k == "Include" || included.extension() == ".geo")
                      file(included, where(i));
                    else
                      findings.push_back(where(i) + " loads another file");
                  }
                else
                  findings.push_back(where(i) +
                                     " has a computed path, which cannot "
                                     "be checked; write the file name as a "
                                     "literal string");
              }
            else if ((k == "General" || k == "Print" || k == "Solver") &&
                     is(t, i + 1, ".") && i + 2 < t.size())
              {
                const std::string why = writing_option(k, t[i + 2].text);
                if (!why.empty())
                  findings.push_back(where(i) + ": " + why);
              }
          }
      }
    };
  } // namespace


  void
  scan_geo(const std::string &file, const bool allow_commands)
  {
    open(file);
    if (allow_commands)
      return;
    Scan scan{file, {}, {}};
    scan.file(file, file);
    AssertThrow(
      scan.findings.empty(),
      ExcMessage(where(file) + ": " + scan.findings.front() +
                 (scan.findings.size() > 1 ?
                    " (and " + std::to_string(scan.findings.size() - 1) +
                      " more such statements)" :
                    std::string()) +
                 "; a scene file may not run programs, write, rename or delete "
                 "files or load files bilayer cannot check: remove it, or run "
                 "bilayer with --allow-gmsh-commands if you trust the file "
                 "(docs/geometry.md)"));
  }
} // namespace bilayer
