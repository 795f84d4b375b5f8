#include <bilayer/progress.h>

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


  double
  time_left(const std::vector<double> &seconds,
            const std::vector<double> &dofs,
            const std::vector<double> &dofs_ahead)
  {
    const std::size_t n = std::min(seconds.size(), dofs.size());
    if (n == 0 || !(seconds[n - 1] > 0) || !(dofs[n - 1] > 0))
      return -1;
    double alpha = 1.2;
    if (n >= 2 && seconds[n - 2] > 0 && dofs[n - 2] > 0 &&
        dofs[n - 1] > 1.1 * dofs[n - 2])
      alpha = std::clamp(std::log(seconds[n - 1] / seconds[n - 2]) /
                           std::log(dofs[n - 1] / dofs[n - 2]),
                         1.,
                         2.);
    double left = 0;
    for (const double N : dofs_ahead)
      left += seconds[n - 1] * std::pow(N / dofs[n - 1], alpha);
    return left;
  }
} // namespace bilayer
