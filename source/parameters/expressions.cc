#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <bilayer/parameters/expressions.h>

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace expressions
  {
    namespace
    {
      /**
       * Run @p work with std::cerr muted (muparser's reports of syntax
       * errors, which the callers' messages replace); whether it ended
       * without an exception.
       */
      bool
      quietly(const std::function<void()> &work)
      {
        std::ostringstream muparser_noise;
        std::streambuf *cerr_buffer = std::cerr.rdbuf(muparser_noise.rdbuf());
        bool            done        = true;
        try
          {
            work();
          }
        catch (...)
          {
            done = false;
          }
        std::cerr.rdbuf(cerr_buffer);
        return done;
      }
    } // namespace


    bool
    is_identifier(const std::string &name)
    {
      if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])))
        return false;
      for (const char ch : name)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'))
          return false;
      return true;
    }


    std::set<std::string>
    names_in(const std::string &text)
    {
      const auto in = [&](const std::size_t i, const char *chars) {
        return i < text.size() && text[i] != '\0' &&
               std::strchr(chars, text[i]) != nullptr;
      };
      const char *digits = "0123456789";
      const char *letters =
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ_";
      std::set<std::string> names;
      std::size_t           i = 0;
      while (i < text.size())
        if (in(i, letters))
          {
            const std::size_t begin = i;
            while (in(i, letters) || in(i, digits))
              ++i;
            names.insert(text.substr(begin, i - begin));
          }
        else if (in(i, digits) || in(i, "."))
          {
            // A number with its exponent (1e-3, 2.5E+4): no name.
            while (in(i, digits) || in(i, "."))
              ++i;
            const bool exponent =
              in(i, "eE") &&
              (in(i + 1, digits) || (in(i + 1, "+-") && in(i + 2, digits)));
            if (exponent)
              {
                i += in(i + 1, "+-") ? 2 : 1;
                while (in(i, digits))
                  ++i;
              }
          }
        else
          ++i;
      return names;
    }


    bool
    is_reserved_name(const std::string &name)
    {
      static const std::set<std::string> reserved = {
        "x",         "y",     "z",    "t",    "sin",  "cos",   "tan",   "asin",
        "acos",      "atan",  "sinh", "cosh", "tanh", "asinh", "acosh", "atanh",
        "log2",      "log10", "log",  "ln",   "exp",  "sqrt",  "sign",  "rint",
        "abs",       "min",   "max",  "sum",  "avg",  "if",    "int",   "ceil",
        "cot",       "csc",   "sec",  "pow",  "erfc", "rand",  "floor", "atan2",
        "rand_seed", "fmod",  "_pi",  "_e"};
      return reserved.count(name) > 0;
    }


    bool
    evaluate_constant(const std::string                   &value,
                      const std::map<std::string, double> &constants,
                      double                              &result)
    {
      FunctionParser<1> parser(1);
      return quietly([&]() {
        parser.initialize("t", value, constants);
        result = parser.value(Point<1>());
      });
    }


    std::unique_ptr<FunctionParser<2>>
    vector_function(const std::string                   &expression,
                    const std::map<std::string, double> &constants,
                    const std::string                   &entry)
    {
      return function(
        expression, 2, "x-component; y-component", constants, entry);
    }


    std::unique_ptr<FunctionParser<2>>
    function(const std::string                   &expression,
             const unsigned int                   n_components,
             const std::string                   &components,
             const std::map<std::string, double> &constants,
             const std::string                   &entry)
    {
      AssertThrow(expression.size() <= max_length,
                  ExcMessage(entry + ": longer than " +
                             std::to_string(max_length) + " characters"));
      const auto parts = Utilities::split_string_list(expression, ';');
      AssertThrow(parts.size() == n_components,
                  ExcMessage(
                    entry + " must have " +
                    (n_components == 1 ? std::string("one") :
                     n_components == 2 ? std::string("two") :
                     n_components == 3 ? std::string("three") :
                                         std::to_string(n_components)) +
                    (n_components == 1 ? " component, no ';' (" :
                                         " components separated by ';' (") +
                    components + "), got '" + expression + "'"));
      auto       result    = std::make_unique<FunctionParser<2>>(n_components);
      const bool evaluated = quietly([&]() {
        result->initialize("x,y", parts, constants);
        Vector<double> value(n_components);
        result->vector_value(Point<2>(0.123, 0.456), value);
      });
      AssertThrow(evaluated,
                  ExcMessage(entry + ": cannot evaluate '" + expression +
                             "' as a function of x and y (known constants: "
                             "material constants E1, nu1, mu1, lambda1, "
                             "E2, nu2, mu2, lambda2 and Loads/Constants)"));
      return result;
    }


    std::unique_ptr<FunctionParser<3>>
    curve_function(const std::string                   &expression,
                   const std::map<std::string, double> &constants,
                   const std::string                   &entry)
    {
      AssertThrow(expression.size() <= max_length,
                  ExcMessage(entry + ": longer than " +
                             std::to_string(max_length) + " characters"));
      AssertThrow(expression.find(';') == std::string::npos,
                  ExcMessage(entry + " must have one component, no ';', got '" +
                             expression + "'"));
      auto       result    = std::make_unique<FunctionParser<3>>(1);
      const bool evaluated = quietly([&]() {
        result->initialize("x,y,s", expression, constants);
        result->value(Point<3>(0.123, 0.456, 0.789));
      });
      AssertThrow(evaluated,
                  ExcMessage(entry + ": cannot evaluate '" + expression +
                             "' as a function of x, y and s"));
      return result;
    }


    bool
    is_zero(const std::string &expression)
    {
      for (const auto &part : Utilities::split_string_list(expression, ';'))
        {
          const std::string text  = Utilities::trim(part);
          char             *end   = nullptr;
          const double      value = std::strtod(text.c_str(), &end);
          if (text.empty() || end != text.c_str() + text.size() || value != 0)
            return false;
        }
      return true;
    }
  } // namespace expressions
} // namespace bilayer
