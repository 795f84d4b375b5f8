#ifndef bilayer_suggestions_h
#define bilayer_suggestions_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

/**
 * "Did you mean" for names and values of a parameter file that
 * ParameterHandler does not know: the declared entries, subsections or
 * choices a few letters away, or the README's table of what bilayer models.
 */
namespace bilayer
{
  /**
   * "; did you mean ...?" naming the declared paths closest to @p name
   * (compared as a whole path when @p name contains '/', else by their
   * last part) when they differ from it by a few letters (at most a third
   * of its length, at least 2, at most 4), else the pointer to the README's
   * table of what bilayer models (also for a name about physics that
   * bilayer does not model, however close to a real entry).
   */
  std::string
  did_you_mean(const dealii::ParameterHandler &prm,
               const std::string              &name,
               const bool                      subsection);

  /**
   * "; did you mean 'VALUE'?" for a value that a Selection pattern refuses:
   * @p message holds the value between @p before and @p after and the
   * pattern "[Selection a|b|c ]"; the choices closest to the value (at most a
   * third of its length apart, at least 2; case and blanks, '-' and '_'
   * not counted), else "".
   */
  std::string
  closest_choice(const std::string &message,
                 const std::string &before,
                 const std::string &after);

  /**
   * The one-line message of @p e, an error of ParameterHandler reading a
   * file, with did_you_mean() for a name it does not know.
   */
  std::string
  with_suggestion(const dealii::ParameterHandler &prm,
                  const dealii::ExceptionBase    &e);
} // namespace bilayer

#endif
