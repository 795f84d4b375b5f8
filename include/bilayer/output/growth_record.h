#ifndef bilayer_growth_record_h
#define bilayer_growth_record_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <bilayer/postprocess/boundary_forces.h>

#include <limits>
#include <ostream>
#include <string>
#include <vector>

/**
 * @file
 * What is reported about one step of a growing crack (Fracture/Crack
 * growth): growth.csv, the "growth" object of summary.json and the
 * terminal's line per step.
 */
namespace bilayer
{
  /// One tip in one growth step.
  struct GrowthTip
  {
    /// The tip's number (1, 2, ...: the crack's tips at the start, ordered
    /// by s).
    unsigned int number = 0;
    /// Whether the tip exists in this step (a tip whose piece merged with
    /// another is gone).
    bool             present = false;
    double           s       = 0;
    dealii::Point<2> point;
    double           G    = std::numeric_limits<double>::quiet_NaN();
    double           G_I  = std::numeric_limits<double>::quiet_NaN();
    double           G_II = std::numeric_limits<double>::quiet_NaN();
    /// The value of the growth criterion (1: critical; Mixed-mode law).
    double criterion = std::numeric_limits<double>::quiet_NaN();
    /// Whether the criterion holds (is_critical(): the load within the
    /// tolerance of the critical load).
    bool critical = false;
    /// The load factor at which the criterion reaches 1 for this crack,
    /// under proportional loading (NaN with a preload; infinite where
    /// nothing is released).
    double critical_load = std::numeric_limits<double>::quiet_NaN();
    /// The length of the crack piece the tip ends.
    double piece_length = 0;
    /// "grows", "arrested" (criterion below 1), "held" (not a growing
    /// tip) or "stopped: <why>" (it cannot advance further).
    std::string status;
  };

  /// One step: one solved state of the growth driver.
  struct GrowthStep
  {
    unsigned int step        = 0;
    double       load_factor = 0;
    /// "load" (a load factor of Loads/Load factor), "onset" (the exact
    /// critical load of the crack, inserted between them) or "growth"
    /// (the crack advanced at the load of the step before).
    std::string kind;
    /// Growth at a fixed load that goes on beyond this step: unstable.
    bool   unstable = false;
    double energy   = 0;
    /// The work-conjugate displacement of lambda: (F_1, w), the work of
    /// the unit proportional loads on the solution.
    double conjugate_displacement = std::numeric_limits<double>::quiet_NaN();
    /// Layer 1's displacement at Output/Displacement points.
    std::vector<dealii::Tensor<1, 2>> point_displacements;
    /// The forces and mean displacements of the boundary parts
    /// (boundary_forces()): the load-displacement curve.
    std::vector<PartForce> parts;
    /// The total length of the crack.
    double                 crack_length = 0;
    std::vector<GrowthTip> tips;
  };

  /// A run of unstable growth: growth at one load that did not stop after
  /// its first step.
  struct UnstableRun
  {
    double       load_factor = 0;
    unsigned int first_step = 0, last_step = 0;
    /// The crack length where it started and where it stopped.
    double from_length = 0, to_length = 0;
  };

  /// The head of growth.csv ('#' lines and the header): tip columns for
  /// @p n_tips tips, point columns for @p n_points points, then the force
  /// columns of the boundary parts @p parts (force_columns()).
  void
  write_growth_csv_head(std::ostream                 &out,
                        const unsigned int            n_tips,
                        const unsigned int            n_points,
                        const std::vector<PartForce> &parts);

  /// One row of growth.csv: @p step.
  void
  write_growth_csv_row(std::ostream                 &out,
                       const GrowthStep             &step,
                       const unsigned int            n_tips,
                       const unsigned int            n_points,
                       const std::vector<PartForce> &parts);

  /// growth.csv: '#' lines (what the columns mean), the header and one row
  /// per step; tip columns for @p n_tips tips (empty cells where a tip is
  /// gone), point columns for @p n_points points.
  void
  write_growth_csv(std::ostream                  &out,
                   const std::vector<GrowthStep> &steps,
                   const unsigned int             n_tips,
                   const unsigned int             n_points);

  /// The "growth" object of summary.json: the mode, the unstable runs and
  /// the steps.
  std::string
  growth_json(const std::string              &mode,
              const std::vector<GrowthStep>  &steps,
              const std::vector<UnstableRun> &unstable,
              const std::string              &stop);

  /// The unstable runs of @p steps.
  std::vector<UnstableRun>
  unstable_runs(const std::vector<GrowthStep> &steps);
} // namespace bilayer

#endif
