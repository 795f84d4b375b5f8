#ifndef bilayer_parameter_overrides_h
#define bilayer_parameter_overrides_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace bilayer
{
  /**
   * Apply the command line's --set assignments "Section/Subsection/
   * Entry=value" to @p prm (declared and read), in order; blanks around the
   * names and the value do not count. A malformed assignment, an entry that
   * is not declared or a value its pattern refuses throws a one-line
   * message with the closest names or choices (suggestions.h).
   */
  void
  apply_overrides(dealii::ParameterHandler       &prm,
                  const std::vector<std::string> &overrides);

  /**
   * The value that the last of @p overrides assigns to the entry @p path
   * ({"Section", "Entry"}), untrimmed, or @p value where none does; for the
   * entries read before the others are declared.
   */
  std::string
  overridden_value(const std::vector<std::string> &overrides,
                   const std::vector<std::string> &path,
                   const std::string              &value);
} // namespace bilayer

#endif
