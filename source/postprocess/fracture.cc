#include <bilayer/postprocess/fracture.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  double
  g_error_from_cycles(const std::vector<double> &G)
  {
    // The trailing finite values, at most four (a tip not resolved on a
    // cycle breaks the sequence).
    std::size_t n = 0;
    while (n < G.size() && n < 4 && std::isfinite(G[G.size() - 1 - n]))
      ++n;
    if (n < 2)
      return std::numeric_limits<double>::quiet_NaN();
    // The changes e[0] = G_k - G_{k-1}, e[1] = G_{k-1} - G_{k-2}, ...
    const std::size_t   k = G.size() - 1;
    std::vector<double> e;
    for (std::size_t i = 0; i + 1 < n; ++i)
      e.push_back(G[k - i] - G[k - i - 1]);
    // Two values: no contraction observed yet; twice the change (a bound
    // for geometric convergence with a ratio up to 2/3).
    if (e.size() == 1)
      return 2 * std::abs(e[0]);
    // The largest of the last changes: G of adaptive cycles moves
    // irregularly, and a small last change says little of the error.
    double dG = 0;
    for (const double change : e)
      dG = std::max(dG, std::abs(change));
    // Monotone and contracting: the remainder of the geometric sequence
    // with the observed ratio r, G - G_k = e1 (r + r^2 + ...) = e1 r /
    // (1 - r) (Aitken; larger than the changes for r > 1/2).
    const double d1 = std::abs(e[0]), d2 = std::abs(e[1]);
    if (e[0] * e[1] > 0 && d1 < d2)
      {
        const double r = d1 / d2;
        dG             = std::max(dG, d1 * r / (1 - r));
      }
    return dG;
  }


  void
  set_g_error(EnergyReleaseRate &g, const double from_cycles)
  {
    g.error = std::numeric_limits<double>::quiet_NaN();
    if (!g.tip.defined() || !g.unresolved.empty() || !std::isfinite(g.G))
      {
        g.error_estimate = "none: G not reported";
        return;
      }
    const double from_support = std::abs(g.G - g.G_half_support);
    const bool   cycles       = std::isfinite(from_cycles),
               support        = std::isfinite(from_support);
    if (cycles && support)
      {
        g.error          = std::max(from_cycles, from_support);
        g.error_estimate = "cycles and support radius";
      }
    else if (cycles)
      {
        g.error          = from_cycles;
        g.error_estimate = "cycles";
      }
    else if (support)
      {
        g.error          = from_support;
        g.error_estimate = "support radius";
      }
    else
      g.error_estimate =
        "none: first cycle of G and R/2 holds too few cells at the tip";
  }


  std::string
  tip_position(const CrackTip &tip, const bool along_x)
  {
    std::ostringstream x;
    x << std::setprecision(6);
    if (along_x)
      {
        x << "x = " << tip.point[0];
        if (tip.interface > 0)
          x << " on interface " << tip.interface + 1 << " (y = " << tip.point[1]
            << ")";
      }
    else
      x << "s = " << tip.s << ", (x, y) = (" << tip.point[0] << ", "
        << tip.point[1] << ")";
    return x.str();
  }


  std::vector<std::string>
  tip_notes(const std::vector<EnergyReleaseRate> &release, const bool along_x)
  {
    std::vector<std::string> notes;
    for (unsigned int t = 0; t < release.size(); ++t)
      {
        const CrackTip    &tip = release[t].tip;
        std::ostringstream line;
        line << std::setprecision(6) << "tip " << t + 1 << ": "
             << tip_position(tip, along_x);
        if (along_x && std::abs(tip.direction[1]) < 1e-12)
          line << ", grows towards " << (tip.direction[0] > 0 ? "+x" : "-x");
        else
          line << ", grows along (" << tip.direction[0] + 0. << ", "
               << tip.direction[1] + 0. << ")";
        notes.push_back(line.str());
      }
    return notes;
  }


  std::vector<std::string>
  release_notes(const std::vector<EnergyReleaseRate> &release,
                const bool                            along_x,
                const int                             interface)
  {
    std::vector<std::string> notes;
    for (unsigned int t = 0; t < release.size(); ++t)
      {
        const EnergyReleaseRate &g = release[t];
        if (interface >= 0 && g.tip.interface != unsigned(interface))
          continue;
        std::ostringstream line;
        line << std::setprecision(10) << "crack tip " << t + 1 << " at "
             << tip_position(g.tip, along_x) << ", growing along ("
             << g.tip.direction[0] + 0. << ", " << g.tip.direction[1] + 0.
             << "): energy release rate G = " << g.G
             << " [stress x length] (contact term " << g.contact;
        if (g.friction != 0)
          line << ", friction term " << g.friction;
        line << "), error bar dG = ";
        if (std::isfinite(g.error))
          line << std::setprecision(2) << g.error << std::setprecision(10)
               << " (estimate from the " << g.error_estimate << ")";
        else
          line << "? (estimate " << g.error_estimate << ")";
        line << ", support radius " << g.tip.support_radius;
        if (!g.unresolved.empty())
          line << " (G not resolved: " << g.unresolved << ")";
        line << "; mode split (docs/fracture.md section 7): ";
        if (std::isfinite(g.G_I))
          line << "G_I = " << g.G_I << ", G_II = " << g.G_II << ", phase angle "
               << std::setprecision(4) << g.phase_angle << std::setprecision(10)
               << " degrees, closure length " << g.mode_split_length;
        else
          line << "not defined";
        if (!g.mode_split_note.empty())
          line << " (" << g.mode_split_note << ")";
        notes.push_back(line.str());
      }
    return notes;
  }
} // namespace bilayer
