#include <deal.II/base/utilities.h>

#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/suggestions.h>

#include <algorithm>
#include <cctype>
#include <numeric>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Levenshtein distance of @p a and @p b, letters compared without case.
    std::size_t
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<std::size_t> row(b.size() + 1);
      std::iota(row.begin(), row.end(), std::size_t(0));
      for (std::size_t i = 1; i <= a.size(); ++i)
        {
          std::size_t diagonal = row[0];
          row[0]               = i;
          for (std::size_t j = 1; j <= b.size(); ++j)
            {
              const std::size_t above = row[j];
              const bool        same  = std::tolower((unsigned char)a[i - 1]) ==
                                std::tolower((unsigned char)b[j - 1]);
              row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + !same});
              diagonal = above;
            }
        }
      return row[b.size()];
    }


    /**
     * The declared names of @p prm as paths "Section/.../Entry"
     * (@p subsections false) or "Section/.../Subsection" (true), read from
     * its ShortPRM listing.
     */
    std::vector<std::string>
    declared_paths(const ParameterHandler &prm, const bool subsections)
    {
      std::ostringstream listing;
      prm.print_parameters(listing, ParameterHandler::ShortPRM);
      std::istringstream       in(listing.str());
      std::vector<std::string> open, paths;
      const auto               joined = [&](const std::string &last) {
        std::string path;
        for (const auto &name : open)
          path += name + "/";
        return path + last;
      };
      for (std::string line; std::getline(in, line);)
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            {
              const std::string name = Utilities::trim(line.substr(11));
              if (subsections)
                paths.push_back(joined(name));
              open.push_back(name);
            }
          else if (line == "end" && !open.empty())
            open.pop_back();
          else if (line.rfind("set ", 0) == 0 && !subsections)
            paths.push_back(
              joined(Utilities::trim(line.substr(4, line.find('=') - 4))));
        }
      return paths;
    }


    /**
     * The text of @p message between the first @p before and the next
     * @p after, "" where either is missing.
     */
    std::string
    text_between(const std::string &message,
                 const std::string &before,
                 const std::string &after)
    {
      const auto a = message.find(before);
      if (a == std::string::npos)
        return "";
      const auto b = message.find(after, a + before.size());
      return b == std::string::npos ?
               "" :
               message.substr(a + before.size(), b - a - before.size());
    }


    /**
     * "; did you mean 'a', 'b' or 'c'?" for @p names, "" for none.
     */
    std::string
    suggestion(const std::vector<std::string> &names)
    {
      if (names.empty())
        return "";
      std::string text = "; did you mean ";
      for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0                ? "'" :
                 i + 1 == names.size() ? " or '" :
                                         ", '") +
                names[i] + "'";
      return text + "?";
    }
  } // namespace


  std::string
  did_you_mean(const ParameterHandler &prm,
               const std::string      &name,
               const bool              subsection)
  {
    // What bilayer does not model (README, "What bilayer models - and
    // what not"): a name about it is no misspelling of a real entry. (The
    // physics it models, friction, thermal loads, body forces and
    // eigenstrains, has entries: a name near one of them is a
    // misspelling.)
    const std::string not_modelled =
      "; what bilayer models and what not: the README's table 'What "
      "bilayer models - and what not'; every entry: bilayer "
      "--print-parameters";
    // The plane state is the layer's: the sides of Sigma have none.
    const std::string plane_state = "/Plane state";
    if ((name.find("/Omega-/") != std::string::npos ||
         name.find("/Omega+/") != std::string::npos) &&
        name.size() > plane_state.size() &&
        name.compare(name.size() - plane_state.size(),
                     plane_state.size(),
                     plane_state) == 0)
      return "; the plane state is one per layer (Materials/Layer k/Plane "
             "state), the same on both sides of Sigma";
    std::string lower;
    for (const char c : name)
      lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char *word : {"adhesion",
                             "toughness",
                             "critical",
                             "gravity",
                             "density",
                             "cohesive",
                             "growth",
                             "debond",
                             "plasticity",
                             "time step",
                             "load step"})
      if (lower.find(word) != std::string::npos)
        return not_modelled;
    // A plausible misspelling: a few letters apart (at most a third of
    // the name, at least 2, at most 4), not added or missing words.
    const bool  whole = name.find('/') != std::string::npos;
    std::size_t best =
      std::min<std::size_t>(4, std::max<std::size_t>(2, name.size() / 3)) + 1;
    std::vector<std::string> closest;
    for (const std::string &path : declared_paths(prm, subsection))
      {
        const std::string compared =
          whole ? path : path.substr(path.rfind('/') + 1);
        const std::size_t d = edit_distance(name, compared);
        if (d < best)
          best = d, closest.clear();
        if (d == best && closest.size() < 3)
          closest.push_back(path);
      }
    // (A whole path that is declared: the error is about something else;
    // a name that is declared elsewhere: that place.)
    if (whole && best == 0)
      return "";
    return closest.empty() ? not_modelled : suggestion(closest);
  }


  std::string
  closest_choice(const std::string &message,
                 const std::string &before,
                 const std::string &after)
  {
    const std::string choices = text_between(message, "[Selection ", "]");
    if (choices.empty() || message.find(before) == std::string::npos)
      return "";
    const auto normal = [](const std::string &text) {
      std::string result;
      for (const char c : text)
        if (std::isalnum(static_cast<unsigned char>(c)))
          result +=
            static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return result;
    };
    const std::string value = normal(text_between(message, before, after));
    std::size_t       best  = std::max<std::size_t>(2, value.size() / 3) + 1;
    std::vector<std::string> closest;
    for (const auto &choice : Utilities::split_string_list(choices, '|'))
      {
        const std::size_t d = edit_distance(value, normal(choice));
        if (d < best)
          best = d, closest.clear();
        if (d == best)
          closest.push_back(choice);
      }
    return suggestion(closest);
  }


  std::string
  with_suggestion(const ParameterHandler &prm, const ExceptionBase &e)
  {
    std::string message = one_line_message(e);
    if (!message.empty() && message.back() == '.')
      message.pop_back();
    const std::string entry =
      text_between(message, "No entry with name <", ">");
    if (!entry.empty())
      return message + did_you_mean(prm, entry, false);
    const std::string marker = "no such subsection to be entered: ";
    const auto        at     = message.find(marker);
    if (at != std::string::npos)
      {
        // (deal.II's text of this error leaves the file name's '<' open.)
        const std::string missing =
          Utilities::trim(message.substr(at + marker.size()));
        // A ply beyond the layer's: the count comes from its Ply heights
        // or Ply groups;
        // a layer beyond the stack's: from Materials/Number of layers.
        const bool layer = (missing.rfind("Materials.Layer ", 0) == 0 ||
                            missing.rfind("Loads.Layer ", 0) == 0) &&
                           missing.find(".Ply ") == std::string::npos &&
                           missing.find(".Omega") == std::string::npos;
        const std::string closest =
          missing.find(".Ply ") != std::string::npos ?
            "; a layer with n Materials/Layer k/Ply heights or n Ply "
            "groups has the subsections Ply 1 ... Ply n+1 (none without "
            "either)" :
          layer ? "; Materials/Number of layers = N gives the subsections "
                  "Layer 1 ... Layer max(2, N) of Materials and Loads" :
                  did_you_mean(prm, missing, true);
        const auto file = message.find(" of file <");
        const auto end  = message.find(": There is", file);
        if (file != std::string::npos && end != std::string::npos &&
            message.find('>', file) > end)
          message.insert(end, ">");
        return message + closest;
      }
    return message +
           closest_choice(message, "The entry value ", " for the entry");
  }
} // namespace bilayer
