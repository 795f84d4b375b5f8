#ifndef bilayer_anderson_mixing_h
#define bilayer_anderson_mixing_h

#include <deque>
#include <vector>

namespace bilayer
{
  /**
   * Anderson acceleration of a fixed-point iteration x = G(x) (Walker and
   * Ni, SIAM J. Numer. Anal. 49, 2011): from the last m + 1 pairs (x_j,
   * G(x_j)) with residuals r_j = G(x_j) - x_j, the next iterate is
   * G(x_k) - sum_j gamma_j (G(x_(j+1)) - G(x_j)), gamma minimising
   * |r_k - sum_j gamma_j (r_(j+1) - r_j)| (least squares by the normal
   * equations with a relative Tikhonov term 1e-10). Depth 0 is the plain
   * iteration. Used by the secant iteration of the cohesive driver on the
   * damage of the zone's nodes, whose plain iteration contracts slowly
   * when the process zone moves within a step (factor 0.98 seen).
   */
  class AndersonMixing
  {
  public:
    explicit AndersonMixing(const unsigned int depth)
      : depth(depth)
    {}

    /// Forget the history (a new fixed point).
    void
    clear()
    {
      xs.clear();
      gs.clear();
    }

    /// The next iterate from the iterate @p x and its image @p g = G(x).
    std::vector<double>
    next(const std::vector<double> &x, const std::vector<double> &g);

  private:
    const unsigned int              depth;
    std::deque<std::vector<double>> xs, gs;
  };
} // namespace bilayer

#endif
