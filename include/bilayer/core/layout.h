#ifndef bilayer_layout_h
#define bilayer_layout_h

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The layout of the problem: two layers on two sides of Sigma give four
 * subproblems, coupled by three multiplier blocks, and the crack is a set of
 * pieces of Sigma. Every loop over subproblems or blocks, every index into a
 * per-subproblem array and every "is this point of Sigma on the crack" goes
 * through the names defined here.
 */
namespace bilayer
{
  /// The two layers: layer 1 (displacement u, cracked), layer 2 (v).
  enum class Layer
  {
    first  = 0,
    second = 1
  };

  /// The two subdomains Omega- (below Sigma) and Omega+ (above Sigma).
  enum class Subdomain
  {
    minus = 0,
    plus  = 1
  };

  /// The three multiplier blocks (docs/problem.md §3).
  enum class MultiplierBlock
  {
    /// mu_1: layer 1 across Sigma (u- against u+), contact on the crack.
    across_sigma = 0,
    /// lambda-: u- glued to v- on the Omega- side.
    glue_minus = 1,
    /// lambda+: u+ glued to v+ on the Omega+ side.
    glue_plus = 2
  };

  namespace Layout
  {
    constexpr unsigned int n_layers      = 2;
    constexpr unsigned int n_subdomains  = 2;
    constexpr unsigned int n_subproblems = n_layers * n_subdomains;
    constexpr unsigned int n_blocks      = 3;
    /// Space dimension and the components of a displacement or multiplier.
    constexpr unsigned int n_components = 2;

    /// Position of subproblem (layer, subdomain) in every per-subproblem
    /// array: u- = 0, u+ = 1, v- = 2, v+ = 3.
    constexpr unsigned int
    index(const Layer layer, const Subdomain subdomain)
    {
      return n_subdomains * static_cast<unsigned int>(layer) +
             static_cast<unsigned int>(subdomain);
    }

    constexpr Layer
    layer(const unsigned int subproblem)
    {
      return static_cast<Layer>(subproblem / n_subdomains);
    }

    constexpr Subdomain
    subdomain(const unsigned int subproblem)
    {
      return static_cast<Subdomain>(subproblem % n_subdomains);
    }

    /// The subproblem of layer 1 on the same side as @p subproblem.
    constexpr unsigned int
    first_layer_partner(const unsigned int subproblem)
    {
      return index(Layer::first, subdomain(subproblem));
    }

    constexpr unsigned int u_minus = index(Layer::first, Subdomain::minus);
    constexpr unsigned int u_plus  = index(Layer::first, Subdomain::plus);
    constexpr unsigned int v_minus = index(Layer::second, Subdomain::minus);
    constexpr unsigned int v_plus  = index(Layer::second, Subdomain::plus);

    /// All subproblem indices, for range-based loops.
    constexpr std::array<unsigned int, n_subproblems> subproblems = {
      {u_minus, u_plus, v_minus, v_plus}};

    /// "u-", "u+", "v-" or "v+".
    inline std::string
    name(const unsigned int subproblem)
    {
      return std::string(layer(subproblem) == Layer::first ? "u" : "v") +
             (subdomain(subproblem) == Subdomain::minus ? "-" : "+");
    }

    constexpr unsigned int
    index(const MultiplierBlock block)
    {
      return static_cast<unsigned int>(block);
    }

    constexpr unsigned int across_sigma = index(MultiplierBlock::across_sigma);
    constexpr unsigned int glue_minus   = index(MultiplierBlock::glue_minus);
    constexpr unsigned int glue_plus    = index(MultiplierBlock::glue_plus);

    /// All block indices, for range-based loops.
    constexpr std::array<unsigned int, n_blocks> blocks = {
      {across_sigma, glue_minus, glue_plus}};

    /// The block that glues the two layers on @p subdomain.
    constexpr unsigned int
    gluing_block(const Subdomain subdomain)
    {
      return subdomain == Subdomain::minus ? glue_minus : glue_plus;
    }

    /**
     * The two subproblems that block @p b couples, (first, second): the jump
     * of block b is first - second, the multiplier acts on first with the
     * sign -1 and on second with +1. mu_1: (u-, u+); lambda-: (u-, v-);
     * lambda+: (u+, v+).
     */
    constexpr std::pair<unsigned int, unsigned int>
    coupled(const unsigned int b)
    {
      return b == across_sigma ? std::make_pair(u_minus, u_plus) :
             b == glue_minus   ? std::make_pair(u_minus, v_minus) :
                                 std::make_pair(u_plus, v_plus);
    }

    /// Entry of component @p c of node @p a in a multiplier block.
    constexpr unsigned int
    entry(const unsigned int a, const unsigned int c)
    {
      return n_components * a + c;
    }

    /// Components of a vector on Sigma at a multiplier node, in the node's
    /// frame (tangent, normal) of MultiplierSpace::node_frame().
    constexpr unsigned int tangential = 0;
    constexpr unsigned int normal     = 1;
  } // namespace Layout

  /// One value per subproblem, indexed by Layout::index().
  template <typename T>
  using PerSubproblem = std::array<T, Layout::n_subproblems>;

  /// One value per multiplier block, indexed by Layout::index(block).
  template <typename T>
  using PerBlock = std::array<T, Layout::n_blocks>;

  /**
   * The crack gamma_c as a set of open pieces of Sigma, each an interval of
   * the coordinate along Sigma. The crack tips belong to Sigma \ gamma_c
   * (glued). A piece may reach an end of Sigma on the outer boundary (an
   * edge crack, once the ends are known: set_sigma_ends()); that end is its
   * mouth, no tip, and lies on the crack. contains() is the one test of "is
   * this point on the crack".
   */
  class CrackSet
  {
  public:
    struct Piece
    {
      double start, end;
    };

    CrackSet() = default;

    /// The pieces, and a tolerance for comparing coordinates (points within
    /// @p tolerance of a tip are tips).
    CrackSet(std::vector<Piece> pieces, const double tolerance)
      : pieces_(std::move(pieces))
      , tolerance(tolerance)
    {}

    /// The coordinates of the two ends of Sigma (InterfaceCurve::set_crack):
    /// a piece end there is a mouth (mouth()).
    void
    set_sigma_ends(const double begin, const double end)
    {
      sigma_ends       = {{begin, end}};
      sigma_ends_known = true;
    }

    /**
     * Whether the coordinate @p s along Sigma is the mouth of an edge
     * crack: an end of Sigma (on the outer boundary) that a piece reaches.
     * It lies on the crack and is no tip.
     */
    bool
    mouth(const double s) const
    {
      if (!sigma_ends_known || pieces_.empty())
        return false;
      const auto near = [this](const double a, const double b) {
        return std::abs(a - b) <= tolerance;
      };
      return (near(s, sigma_ends[0]) &&
              near(pieces_.front().start, sigma_ends[0])) ||
             (near(s, sigma_ends[1]) &&
              near(pieces_.back().end, sigma_ends[1]));
    }

    /// Whether the coordinate @p s along Sigma lies on the crack: inside a
    /// crack piece (tips excluded) or at the mouth of an edge crack.
    bool
    contains(const double s) const
    {
      for (const auto &piece : pieces_)
        if (s > piece.start + tolerance && s < piece.end - tolerance)
          return true;
      return mouth(s);
    }

    bool
    empty() const
    {
      return pieces_.empty();
    }

    const std::vector<Piece> &
    pieces() const
    {
      return pieces_;
    }

  private:
    std::vector<Piece>    pieces_;
    double                tolerance = 0;
    std::array<double, 2> sigma_ends{{0., 0.}};
    bool                  sigma_ends_known = false;
  };
} // namespace bilayer

#endif
