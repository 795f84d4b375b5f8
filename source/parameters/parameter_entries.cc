#include <deal.II/base/utilities.h>

#include <bilayer/parameters/parameter_entries.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace entries
  {
    double
    to_double(const std::string &text, const std::string &entry)
    {
      const std::string trimmed = Utilities::trim(text);
      errno                     = 0;
      char        *end          = nullptr;
      const double value        = std::strtod(trimmed.c_str(), &end);
      AssertThrow(!trimmed.empty() && end == trimmed.c_str() + trimmed.size(),
                  ExcMessage(entry + ": cannot read '" + text +
                             "' as a number"));
      AssertThrow(errno != ERANGE && std::isfinite(value) &&
                    (value == 0 || std::isnormal(value)),
                  ExcMessage(entry + ": '" + text +
                             "' is outside the range of normal double "
                             "numbers (0 or 2.3e-308 <= |value| <= 1.7e308)"));
      return value;
    }

    double
    get_double(const ParameterHandler &prm,
               const std::string      &section,
               const std::string      &name)
    {
      return to_double(prm.get(name), section + "/" + name);
    }

    std::array<double, 2>
    parse_pair(const ParameterHandler &prm,
               const std::string      &section,
               const std::string      &name)
    {
      const auto parts = Utilities::split_string_list(prm.get(name), ',');
      AssertThrow(parts.size() == 2,
                  ExcMessage(section + "/" + name +
                             " must be two numbers 'a, b', got '" +
                             prm.get(name) + "'"));
      return {{to_double(parts[0], section + "/" + name),
               to_double(parts[1], section + "/" + name)}};
    }

    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    std::string
    layer_subsection(const unsigned int layer)
    {
      return "Layer " + std::to_string(layer + 1);
    }
  } // namespace entries


  std::string
  one_line_message(const ExceptionBase &exception)
  {
    std::ostringstream info;
    exception.print_info(info);
    std::string collapsed;
    for (char c : info.str())
      {
        if (c == '\n' || c == '\t')
          c = ' ';
        if (!(c == ' ' && (collapsed.empty() || collapsed.back() == ' ')))
          collapsed += c;
      }
    while (!collapsed.empty() && collapsed.back() == ' ')
      collapsed.pop_back();
    return collapsed;
  }
} // namespace bilayer
