#ifndef bilayer_expressions_h
#define bilayer_expressions_h

#include <deal.II/base/function_parser.h>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace bilayer
{
  /**
   * The muparser expressions of the Loads section, through deal.II's
   * FunctionParser: named constants and two-component functions of x and y.
   * muparser reports syntax errors on std::cerr before deal.II throws; here
   * that output is kept off the terminal, and the errors name the entry.
   */
  namespace expressions
  {
    /// The longest expression text read (Loads section) [characters].
    constexpr std::size_t max_length = 10000;

    /// Whether @p name is a name of letters, digits and '_' that does not
    /// start with a digit.
    bool
    is_identifier(const std::string &name);

    /**
     * The names (identifiers) that the expression @p text uses: its
     * variables, constants and functions, not the digits and exponents of
     * its numbers (1e-3).
     */
    std::set<std::string>
    names_in(const std::string &text);

    /// Variables and functions of the expressions (muparser and deal.II's
    /// additions), which a constant may not shadow.
    bool
    is_reserved_name(const std::string &name);

    /**
     * The value of the expression @p value of the @p constants into
     * @p result; false if muparser cannot evaluate it.
     */
    bool
    evaluate_constant(const std::string                   &value,
                      const std::map<std::string, double> &constants,
                      double                              &result);

    /// Build a two-component parser from "f_x; f_y" and evaluate it once so
    /// that syntax errors surface while the name of the entry @p entry is
    /// known.
    std::unique_ptr<dealii::FunctionParser<2>>
    vector_function(const std::string                   &expression,
                    const std::map<std::string, double> &constants,
                    const std::string                   &entry);

    /**
     * As vector_function(), with @p n_components components separated by
     * ';', described by @p components in the message that refuses another
     * number (e.g. "eps11; eps22; eps12").
     */
    std::unique_ptr<dealii::FunctionParser<2>>
    function(const std::string                   &expression,
             const unsigned int                   n_components,
             const std::string                   &components,
             const std::map<std::string, double> &constants,
             const std::string                   &entry);

    /**
     * A one-component function of x, y and s (the coordinate along Sigma)
     * from @p expression: a FunctionParser<3> whose third coordinate is s,
     * evaluated once so that errors name the entry @p entry.
     */
    std::unique_ptr<dealii::FunctionParser<3>>
    curve_function(const std::string                   &expression,
                   const std::map<std::string, double> &constants,
                   const std::string                   &entry);

    /// Whether every ';'-separated component of @p expression is the
    /// number 0 ("0", "0.0", "-0", "0e0", blanks around).
    bool
    is_zero(const std::string &expression);
  } // namespace expressions
} // namespace bilayer

#endif
