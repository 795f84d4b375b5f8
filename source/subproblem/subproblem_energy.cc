#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/core/similarity_breaker.h>
#include <bilayer/subproblem/subproblem.h>

/**
 * @file
 * The energies and works of a subproblem's displacement: a(w, w), Pi(w),
 * the load's and the preload's work, and the energy of the eigenstrain.
 */

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// x . y summed in index order: the same bits for any number of
    /// threads (deal.II's parallel reductions group the sum by thread).
    double
    ordered_dot(const Vector<double> &x, const Vector<double> &y)
    {
      double sum = 0;
      for (unsigned int i = 0; i < x.size(); ++i)
        sum += x(i) * y(i);
      return sum;
    }
  } // namespace


  void
  ElasticSubproblem::multiply_stiffness(Vector<double>       &y,
                                        const Vector<double> &x) const
  {
    if (shared)
      shared->vmult_stiffness(y, x);
    else
      stiffness.vmult(y, x);
  }


  double
  ElasticSubproblem::energy_norm_squared(const Vector<double> &w) const
  {
    if (shared)
      return shared->energy_norm_squared(w);
    Vector<double> aw(w.size());
    stiffness.vmult(aw, w); // row by row: independent of the threads
    return ordered_dot(aw, w);
  }


  double
  ElasticSubproblem::eigenstrain_energy() const
  {
    FEValues<2> fe_values(
      mapping(),
      *fe_system,
      fe_system->reference_cell().get_gauss_type_quadrature<2>(
        fe_system->degree + 1),
      update_quadrature_points | update_JxW_values);
    const SimilarityBreaker fresh(fe_system->reference_cell());
    double                  sum = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        fresh.apply(fe_values);
        fe_values.reinit(cell);
        const CellLoad load = volume_->in(*cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          sum += laws_.law(*cell).energy_density(
                   load.eigenstrain(fe_values.quadrature_point(q))) *
                 fe_values.JxW(q);
      }
    return sum;
  }


  double
  ElasticSubproblem::energy(const Vector<double> &w) const
  {
    const double energy =
      0.5 * energy_norm_squared(w) -
      (shared ? shared->load_product(w) : ordered_dot(load_vector, w));
    // (Without an eigenstrain exactly the sum above, bit for bit.)
    // (The eigenstrain energy of setup() is quadratic in the preload.)
    return eigenstrain_energy_ == 0 ?
             energy :
           preload_factor_ == 1 ?
             energy + eigenstrain_energy_ :
             energy + preload_factor_ * preload_factor_ * eigenstrain_energy_;
  }


  double
  ElasticSubproblem::load_work(const Vector<double> &w) const
  {
    if (shared)
      {
        AssertThrow(!has_preload_,
                    ExcMessage("load_work: subproblem " + name() +
                               " is shared by a group of processes and has "
                               "a preload; its unit load is not kept"));
        return shared->load_product(w);
      }
    return ordered_dot(unit_load, w);
  }


  double
  ElasticSubproblem::preload_work(const Vector<double> &w) const
  {
    if (!has_preload_)
      return 0;
    AssertThrow(!shared && preload_load.size() == w.size(),
                ExcMessage("preload_work: subproblem " + name() +
                           " is shared by a group of processes; its preload "
                           "is not kept"));
    return ordered_dot(preload_load, w);
  }
} // namespace bilayer
