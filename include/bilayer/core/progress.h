#ifndef bilayer_progress_h
#define bilayer_progress_h

#include <chrono>
#include <string>
#include <vector>

namespace bilayer
{
  /// A duration for people: "0.42 s", "12.3 s", "4 min 12 s", "2 h 05 min".
  std::string
  format_duration(const double seconds);

  /**
   * Elapsed time of an iteration and an estimate of the time it has left,
   * for the progress lines of long runs. The estimate assumes that the
   * stopping value falls geometrically towards its target at the rate seen
   * since the previous progress line (the first-order iterations converge
   * linearly): with value v_k at step k, v_j at the previous line j and the
   * mean time per step t, the steps left are
   * log(target / v_k) / log((v_k / v_j)^(1 / (k - j))).
   */
  class IterationClock
  {
  public:
    /// Starts the clock.
    IterationClock();

    /// Seconds since the start.
    double
    elapsed() const;

    /**
     * "elapsed 3.1 s, about 2.0 s left" at step @p k with stopping value
     * @p value and the target @p target; "elapsed 3.1 s" while no estimate
     * can be made (the first line, a value that does not fall).
     */
    std::string
    report(const unsigned int k, const double value, const double target);

  private:
    std::chrono::steady_clock::time_point start;
    unsigned int                          last_step  = 0;
    double                                last_value = 0;
  };

  /**
   * The time left of a study from its cycles so far (cycle i took
   * @p seconds[i] for @p dofs[i] unknowns) for @p n_left more cycles, and
   * the growth of the unknowns per cycle that it assumes; negative numbers
   * while it cannot be estimated. Cycle 0 carries one-off costs and is not
   * used. The unknowns of the cycles to come grow by the geometric mean of
   * the last three growth factors (global refinement: the last one); the
   * cost of a cycle grows as dofs^alpha, alpha fitted by least squares to
   * the last three cycles (from cycle 1 on), limited to [1, 1.5] (at least
   * linear; the factorisations of these 2D problems grow more slowly than
   * N^1.5), from the fitted cost of the last cycle. Under adaptive
   * refinement the growth of the first cycles is smaller than later
   * (Doerfler marking refines few cells while singularities dominate): the
   * estimate starts once five cycles are done (@p adaptive), under global
   * refinement once two are.
   */
  struct TimeLeft
  {
    double seconds = -1;
    double growth  = -1;
  };

  TimeLeft
  time_left(const std::vector<double> &seconds,
            const std::vector<double> &dofs,
            const unsigned int         n_left,
            const bool                 adaptive);
} // namespace bilayer

#endif
