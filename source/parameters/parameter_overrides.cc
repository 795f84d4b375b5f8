#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/parameter_overrides.h>
#include <bilayer/parameters/suggestions.h>

namespace bilayer
{
  using namespace dealii;


  void
  apply_overrides(ParameterHandler               &prm,
                  const std::vector<std::string> &overrides)
  {
    for (const auto &assignment : overrides)
      {
        const auto equal = assignment.find('=');
        AssertThrow(equal != std::string::npos,
                    ExcMessage("--set expects 'Section/Entry=value', got '" +
                               assignment + "'"));
        const auto path =
          Utilities::split_string_list(assignment.substr(0, equal), '/');
        AssertThrow(path.size() >= 2,
                    ExcMessage("--set expects 'Section/Entry=value', got '" +
                               assignment + "'"));
        unsigned int entered = 0;
        try
          {
            for (; entered + 1 < path.size(); ++entered)
              prm.enter_subsection(path[entered]);
            prm.set(path.back(), Utilities::trim(assignment.substr(equal + 1)));
          }
        catch (const ExceptionBase &e)
          {
            std::string joined;
            for (const auto &name : path)
              joined += (joined.empty() ? "" : "/") + name;
            std::string message = one_line_message(e);
            if (!message.empty() && message.back() == '.')
              message.pop_back();
            // (deal.II's text for a name that is not declared.)
            if (message.find("you have not yet declared") != std::string::npos)
              message = "no entry '" + joined + "' is declared";
            AssertThrow(false,
                        ExcMessage("--set " + assignment + ": " + message +
                                   did_you_mean(prm, joined, false) +
                                   closest_choice(message,
                                                  "The string <",
                                                  "> does not match")));
          }
        for (; entered > 0; --entered)
          prm.leave_subsection();
      }
  }


  std::string
  overridden_value(const std::vector<std::string> &overrides,
                   const std::vector<std::string> &path,
                   const std::string              &value)
  {
    std::string result = value;
    for (const auto &assignment : overrides)
      {
        const auto equal = assignment.find('=');
        const auto named =
          equal == std::string::npos ?
            std::vector<std::string>() :
            Utilities::split_string_list(assignment.substr(0, equal), '/');
        if (named == path)
          result = assignment.substr(equal + 1);
      }
    return result;
  }
} // namespace bilayer
