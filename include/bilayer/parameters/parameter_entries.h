#ifndef bilayer_parameter_entries_h
#define bilayer_parameter_entries_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>

namespace bilayer
{
  /// The message of a deal.II exception (a user error) on one line.
  std::string
  one_line_message(const dealii::ExceptionBase &exception);

  /**
   * Reading the entries of a subsection: numbers whose errors name the
   * entry, and the names the parameter files use.
   */
  namespace entries
  {
    /**
     * The number @p text of the entry @p entry (its pattern has checked the
     * format). Values beyond the range of double and denormal numbers, which
     * the patterns let through, are refused naming the entry.
     */
    double
    to_double(const std::string &text, const std::string &entry);

    /// The number of the entry @p name of the subsection @p section (the
    /// current one of @p prm).
    double
    get_double(const dealii::ParameterHandler &prm,
               const std::string              &section,
               const std::string              &name);

    /// The entry "a, b" as two numbers.
    std::array<double, 2>
    parse_pair(const dealii::ParameterHandler &prm,
               const std::string              &section,
               const std::string              &name);

    /// A number as a user would write it.
    std::string
    number(const double x);

    /// "Layer 1" or "Layer 2", the subsection of a layer (0 or 1).
    std::string
    layer_subsection(const unsigned int layer);
  } // namespace entries
} // namespace bilayer

#endif
