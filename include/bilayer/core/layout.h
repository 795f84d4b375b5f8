#ifndef bilayer_layout_h
#define bilayer_layout_h

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The layout of the problem: N layers stacked through the thickness (the
 * paper's two, u and v, or more), each cut along Sigma into its parts on the
 * two regions Omega- and Omega+, give 2N subproblems, coupled by 2N - 1
 * multiplier blocks: layer 1 across Sigma (contact on the crack), and on each
 * region each layer k >= 2 glued to layer k - 1 along Sigma. The crack is a
 * set of pieces of Sigma. Every loop over subproblems or blocks, every index
 * into a per-subproblem array and every "is this point of Sigma on the
 * crack" goes through the names defined here. A scene with one layer keeps
 * the slots of layer 2 (absent: null subproblems, blocks without nodes).
 */
namespace bilayer
{
  /// A layer, by its position from the bottom of the stack: layer 1
  /// (displacement u, cracked), layer 2 (v), layer k (Layer(k - 1)).
  enum class Layer : unsigned int
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

  /// The first multiplier blocks (docs/problem.md §3); a stack of N layers
  /// has the blocks 0 ... 2N - 2 (Layout::coupled()).
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
    /// The fewest layers the decomposition holds slots for: a one-layer
    /// scene keeps layer 2's slots absent.
    constexpr unsigned int min_layers   = 2;
    constexpr unsigned int n_subdomains = 2;
    /// Space dimension and the components of a displacement or multiplier.
    constexpr unsigned int n_components = 2;

    /// The number of slots of the layers of a scene with @p layers layers.
    constexpr unsigned int
    n_slots(const unsigned int layers)
    {
      return layers < min_layers ? min_layers : layers;
    }

    /// The subproblems of a stack of @p layers layers (slots: at least 2).
    constexpr unsigned int
    n_subproblems(const unsigned int layers)
    {
      return n_subdomains * n_slots(layers);
    }

    /// The multiplier blocks of a stack of @p layers layers.
    constexpr unsigned int
    n_blocks(const unsigned int layers)
    {
      return 2 * n_slots(layers) - 1;
    }

    /// Position of subproblem (layer, subdomain) in every per-subproblem
    /// array: u- = 0, u+ = 1, v- = 2, v+ = 3, layer k on Omega-: 2(k - 1).
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

    /// The indices 0 ... n - 1 of a per-subproblem or per-block array of
    /// size n, for range-based loops (nothing allocated: the loops run in
    /// the outer solvers' iterations).
    class Indices
    {
    public:
      class iterator
      {
      public:
        explicit constexpr iterator(const unsigned int i)
          : i(i)
        {}
        constexpr unsigned int
        operator*() const
        {
          return i;
        }
        constexpr iterator &
        operator++()
        {
          ++i;
          return *this;
        }
        constexpr bool
        operator!=(const iterator &other) const
        {
          return i != other.i;
        }

      private:
        unsigned int i;
      };

      explicit constexpr Indices(const std::size_t n)
        : n(static_cast<unsigned int>(n))
      {}
      constexpr iterator
      begin() const
      {
        return iterator(0);
      }
      constexpr iterator
      end() const
      {
        return iterator(n);
      }

    private:
      unsigned int n;
    };

    constexpr Indices
    indices(const std::size_t n)
    {
      return Indices(n);
    }

    /// The letter of layer @p layer in names: u (layer 1), v (layer 2),
    /// w3, w4, ... (layer k >= 3).
    inline std::string
    layer_letter(const Layer layer)
    {
      const unsigned int l = static_cast<unsigned int>(layer);
      return l == 0 ? "u" : l == 1 ? "v" : "w" + std::to_string(l + 1);
    }

    /// "u_minus", "u_plus", "v_minus", ..., "w3_plus": the subproblem in
    /// the names of output fields and columns.
    inline std::string
    field_name(const unsigned int subproblem)
    {
      return layer_letter(layer(subproblem)) +
             (subdomain(subproblem) == Subdomain::minus ? "_minus" : "_plus");
    }

    /// "u-", "u+", "v-", "v+", "w3-", ...
    inline std::string
    name(const unsigned int subproblem)
    {
      return layer_letter(layer(subproblem)) +
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

    /**
     * The two subproblems that block @p b couples, (first, second): the jump
     * of block b is first - second, the multiplier acts on first with the
     * sign -1 and on second with +1. mu_1: (u-, u+); the gluing block of
     * layer k on a side: (layer k - 1, layer k) on that side, so lambda-:
     * (u-, v-), lambda+: (u+, v+).
     */
    constexpr std::pair<unsigned int, unsigned int>
    coupled(const unsigned int b)
    {
      if (b == across_sigma)
        return std::make_pair(u_minus, u_plus);
      const unsigned int upper = (b - 1) / n_subdomains + 1;
      const Subdomain    side  = static_cast<Subdomain>((b - 1) % n_subdomains);
      return std::make_pair(index(static_cast<Layer>(upper - 1), side),
                            index(static_cast<Layer>(upper), side));
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

  /// One value per subproblem, indexed by Layout::index(): sized
  /// Layout::n_subproblems(layers).
  template <typename T>
  using PerSubproblem = std::vector<T>;

  /// One value per multiplier block, indexed by Layout::index(block): sized
  /// Layout::n_blocks(layers).
  template <typename T>
  using PerBlock = std::vector<T>;

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
