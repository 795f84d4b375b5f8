#include <bilayer/core/progress.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bilayer
{
  std::string
  format_duration(const double seconds)
  {
    char text[64];
    if (!(seconds >= 0) || !std::isfinite(seconds))
      return "unknown";
    if (seconds < 10)
      std::snprintf(text, sizeof(text), "%.2g s", seconds);
    else if (seconds < 60)
      std::snprintf(text, sizeof(text), "%.0f s", seconds);
    else if (seconds < 3600)
      {
        const long s = std::lround(seconds);
        std::snprintf(text, sizeof(text), "%ld min %02ld s", s / 60, s % 60);
      }
    else
      {
        const long m = std::lround(seconds / 60);
        std::snprintf(text, sizeof(text), "%ld h %02ld min", m / 60, m % 60);
      }
    return text;
  }


  IterationClock::IterationClock()
    : start(std::chrono::steady_clock::now())
  {}


  double
  IterationClock::elapsed() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }


  std::string
  IterationClock::report(const unsigned int k,
                         const double       value,
                         const double       target)
  {
    const double seconds = elapsed();
    std::string  text    = "elapsed " + format_duration(seconds);
    if (last_step > 0 && k > last_step && value > 0 && last_value > 0 &&
        value < last_value && target > 0)
      {
        const double rate =
          std::log(value / last_value) / double(k - last_step); // < 0
        const double steps_left =
          value <= target ? 0. : std::log(target / value) / rate;
        text +=
          ", about " + format_duration(steps_left * seconds / k) + " left";
      }
    last_step  = k;
    last_value = value;
    return text;
  }


  TimeLeft
  time_left(const std::vector<double> &seconds,
            const std::vector<double> &dofs,
            const unsigned int         n_left,
            const bool                 adaptive)
  {
    TimeLeft          left;
    const std::size_t n = std::min(seconds.size(), dofs.size());
    if (n < (adaptive ? 5u : 2u) || n_left == 0)
      return left;
    for (std::size_t i = 1; i < n; ++i)
      if (!(seconds[i] > 0) || !(dofs[i] > 0) || !(dofs[i - 1] > 0))
        return left;
    // Growth of the unknowns: the last growth factors.
    const std::size_t n_growth   = adaptive ? 3 : 1;
    double            log_growth = 0;
    for (std::size_t i = n - n_growth; i < n; ++i)
      log_growth += std::log(dofs[i] / dofs[i - 1]);
    const double growth = std::max(1., std::exp(log_growth / n_growth));
    // Cost exponent: least squares of log seconds against log dofs over the
    // last three cycles from cycle 1 on.
    const std::size_t first = std::max<std::size_t>(1, n >= 3 ? n - 3 : 1);
    double            mx = 0, my = 0;
    for (std::size_t i = first; i < n; ++i)
      mx += std::log(dofs[i]), my += std::log(seconds[i]);
    const double m = n - first;
    mx /= m, my /= m;
    double sxx = 0, sxy = 0;
    for (std::size_t i = first; i < n; ++i)
      {
        const double x = std::log(dofs[i]) - mx;
        sxx += x * x;
        sxy += x * (std::log(seconds[i]) - my);
      }
    double alpha = 1.2, last = seconds[n - 1];
    if (m >= 2 && sxx > 1e-3)
      {
        alpha = std::clamp(sxy / sxx, 1., 1.5);
        last  = std::exp(my + alpha * (std::log(dofs[n - 1]) - mx));
      }
    double total = 0, ratio = 1;
    for (unsigned int k = 0; k < n_left; ++k)
      {
        ratio *= growth;
        total += last * std::pow(ratio, alpha);
      }
    left.seconds = total;
    left.growth  = growth;
    return left;
  }
} // namespace bilayer
