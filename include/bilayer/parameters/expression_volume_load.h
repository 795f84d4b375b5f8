#ifndef bilayer_expression_volume_load_h
#define bilayer_expression_volume_load_h

#include <deal.II/base/function_parser.h>

#include <bilayer/physics/volume_load.h>

#include <map>
#include <memory>
#include <string>

namespace bilayer
{
  /**
   * The VolumeLoad of a layer's entries Loads/Layer k/Body force ("f_x;
   * f_y") and Loads/Layer k/Eigenstrain ("eps11; eps22; eps12", the tensor
   * components in the x-y frame), muparser expressions of x, y and the load
   * constants (expressions.h). An expression that is "0" in every component
   * is not evaluated (has_body_force(), has_eigenstrain() false).
   *
   * Every value is checked where it is evaluated: one that is not finite
   * throws "Loads/Layer k/Body force is not finite at (x, y) = (...)" (or
   * Eigenstrain), which the program reports as its one error line. The
   * gradients are VolumeLoad's fourth-order central differences with the
   * step 1e-3 of @p length_scale (the size of the domain). Thread-safe:
   * deal.II's FunctionParser keeps one muparser per thread.
   */
  class ExpressionVolumeLoad : public VolumeLoad
  {
  public:
    /**
     * @p body_force and @p eigenstrain: the texts of the entries; @p entry
     * the subsection ("Loads/Layer 1") that the messages name.
     */
    ExpressionVolumeLoad(const std::string                   &body_force,
                         const std::string                   &eigenstrain,
                         const std::map<std::string, double> &constants,
                         const std::string                   &entry,
                         const double                         length_scale);

    dealii::Tensor<1, 2>
    body_force(const dealii::Point<2> &p) const override;

    dealii::SymmetricTensor<2, 2>
    eigenstrain(const dealii::Point<2> &p) const override;

    bool
    has_body_force() const override
    {
      return force != nullptr;
    }

    bool
    has_eigenstrain() const override
    {
      return strain != nullptr;
    }

    double
    length_scale() const override
    {
      return length;
    }

  private:
    std::unique_ptr<dealii::FunctionParser<2>> force, strain;
    const std::string                          force_entry, strain_entry;
    const double                               length;

    /// The values of @p function at @p p into @p values, each checked.
    void
    evaluate(const dealii::FunctionParser<2> &function,
             const std::string               &entry,
             const dealii::Point<2>          &p,
             double                          *values) const;
  };
} // namespace bilayer

#endif
