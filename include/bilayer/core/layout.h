#ifndef bilayer_layout_h
#define bilayer_layout_h

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * The layout of the problem (Topology): R regions of the plane (Omega- and
 * Omega+, or more, stacked from the bottom) separated by R - 1 interfaces
 * (Sigma, ...), and N layers stacked through the thickness (the paper's two,
 * u and v, or more) on two regions; a subproblem per layer and region,
 * coupled by multiplier blocks across the interfaces (contact on their
 * cracks) and between the layers along Sigma. A crack is a set of pieces of
 * its interface. Every loop over subproblems or blocks, every index into a
 * per-subproblem array and every "is this point of the interface on the
 * crack" goes through the names defined here. A two-region scene with one
 * layer keeps the slots of layer 2 (absent: null subproblems, blocks
 * without nodes).
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

  /// The first multiplier blocks of a two-region scene (docs/problem.md
  /// §3); a stack of N layers has the blocks 0 ... 2N - 2
  /// (Topology::coupling()).
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

    /// Position of subproblem (layer, subdomain) of a two-region scene in
    /// every per-subproblem array: u- = 0, u+ = 1, v- = 2, v+ = 3, layer k
    /// on Omega-: 2(k - 1) (Topology::index(); with more regions only layer
    /// 1 exists, and region r's index is r for both).
    constexpr unsigned int
    index(const Layer layer, const Subdomain subdomain)
    {
      return n_subdomains * static_cast<unsigned int>(layer) +
             static_cast<unsigned int>(subdomain);
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

    constexpr unsigned int
    index(const MultiplierBlock block)
    {
      return static_cast<unsigned int>(block);
    }

    constexpr unsigned int across_sigma = index(MultiplierBlock::across_sigma);
    constexpr unsigned int glue_minus   = index(MultiplierBlock::glue_minus);
    constexpr unsigned int glue_plus    = index(MultiplierBlock::glue_plus);

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

  /**
   * One coupling of two subproblems by a multiplier block: across an
   * interface (layer 1 of the region below it against layer 1 of the region
   * above it: glue, and on the interface's crack contact and friction), or
   * the gluing of layer k to layer k - 1 on one region along one of the
   * interfaces on its boundary. The jump of the block is first - second;
   * the multiplier acts on first with the sign -1 and on second with +1.
   */
  struct Coupling
  {
    enum class Kind
    {
      across,
      glue
    };
    Kind kind = Kind::across;
    /// The interface that carries the block's nodes (Sigma: 0): the one
    /// it couples across, or the one along which it glues the layers.
    unsigned int interface = 0;
    /// Across an interface: the first of its regions; gluing: the region whose
    /// layers it glues.
    unsigned int region = 0;
    unsigned int first = 0, second = 0;
  };

  /**
   * The decomposition as data: R regions of the plane and the interfaces
   * between them, each joining two regions (interface i: the regions
   * regions_of(i), the lower number first; by default a chain stacked from
   * the bottom, interface i between regions i and i + 1, Sigma = interface
   * 0 between region 0 = Omega- and region 1 = Omega+), and N layers
   * through the thickness. Subproblem (layer l, region r) has the index
   * R l + r; the multiplier blocks are first the blocks across the
   * interfaces (block i across interface i), then the gluing blocks of each
   * layer k >= 2: two per interface, one for each region it joins, in the
   * order (interface 0, its first region), (interface 0, its second
   * region), (interface 1, its first region), ... (pair j: interface j / 2,
   * side j % 2; block I + (k - 2) 2 I + j with I interfaces). The layers
   * are glued along every interface (the paper's gluing along Sigma, on
   * each curve that cuts the cross-section). A two-region scene keeps at
   * least two layer slots (a one-layer scene's layer 2 absent: null
   * subproblems, blocks without nodes), so u- = 0, u+ = 1, v- = 2, v+ = 3
   * as Layout::index() numbers them.
   */
  class Topology
  {
  public:
    explicit Topology(const unsigned int regions = 2,
                      const unsigned int layers  = 2)
      : Topology(regions, layers, chain(regions))
    {}

    /// The regions @p regions joined by the interfaces @p between (the two
    /// regions of each, the lower number first).
    Topology(const unsigned int                       regions,
             const unsigned int                       layers,
             std::vector<std::array<unsigned int, 2>> between)
      : regions(regions)
      , slots(regions == Layout::n_subdomains ? Layout::n_slots(layers) :
                                                layers)
      , between(std::move(between))
    {}

    /// The interfaces of a chain of @p regions regions stacked from the
    /// bottom: interface i between regions i and i + 1.
    static std::vector<std::array<unsigned int, 2>>
    chain(const unsigned int regions)
    {
      std::vector<std::array<unsigned int, 2>> pairs;
      for (unsigned int i = 0; i + 1 < regions; ++i)
        pairs.push_back({{i, i + 1}});
      return pairs;
    }

    unsigned int
    n_regions() const
    {
      return regions;
    }
    unsigned int
    n_interfaces() const
    {
      return between.size();
    }
    /// The two regions that interface @p i joins, the lower number first
    /// (side 0 and side 1 of the interface).
    const std::array<unsigned int, 2> &
    regions_of(const unsigned int i) const
    {
      return between[i];
    }
    /// Whether region @p r lies on one side of interface @p i.
    bool
    joins(const unsigned int i, const unsigned int r) const
    {
      return between[i][0] == r || between[i][1] == r;
    }
    /// The side whose material (Materials/Layer k/Omega- or Omega+) region
    /// @p r takes: Omega- below Sigma, Omega+ for every region above it.
    static Subdomain
    material_side(const unsigned int r)
    {
      return r == 0 ? Subdomain::minus : Subdomain::plus;
    }
    /// The layer slots (at least two with two regions).
    unsigned int
    n_slots() const
    {
      return slots;
    }
    unsigned int
    n_subproblems() const
    {
      return regions * slots;
    }
    /// The gluing blocks of one layer k >= 2: one per region and
    /// interface on its boundary.
    unsigned int
    n_glue_blocks() const
    {
      return 2 * n_interfaces();
    }
    unsigned int
    n_blocks() const
    {
      return n_interfaces() + n_glue_blocks() * (slots - 1);
    }
    /// The block that glues layer @p layer (>= 2) to the layer below it on
    /// region @p r along interface @p i (on the boundary of r).
    unsigned int
    glue_block(const Layer        layer,
               const unsigned int r,
               const unsigned int i) const
    {
      return n_interfaces() +
             n_glue_blocks() * (static_cast<unsigned int>(layer) - 1) + 2 * i +
             side(i, r);
    }
    unsigned int
    index(const Layer layer, const unsigned int region) const
    {
      return regions * static_cast<unsigned int>(layer) + region;
    }
    Layer
    layer(const unsigned int subproblem) const
    {
      return static_cast<Layer>(subproblem / regions);
    }
    unsigned int
    region(const unsigned int subproblem) const
    {
      return subproblem % regions;
    }
    /// The coupling of block @p b.
    Coupling
    coupling(const unsigned int b) const
    {
      Coupling c;
      if (b < n_interfaces())
        {
          c.kind      = Coupling::Kind::across;
          c.interface = b;
          c.region    = between[b][0];
          c.first     = index(Layer::first, between[b][0]);
          c.second    = index(Layer::first, between[b][1]);
          return c;
        }
      const unsigned int g     = b - n_interfaces();
      const unsigned int upper = g / n_glue_blocks() + 1;
      const unsigned int j     = g % n_glue_blocks();
      c.kind                   = Coupling::Kind::glue;
      c.interface              = j / 2;
      c.region                 = between[j / 2][j % 2];
      c.first                  = index(static_cast<Layer>(upper - 1), c.region);
      c.second                 = index(static_cast<Layer>(upper), c.region);
      return c;
    }
    /// Whether block @p b couples across an interface.
    bool
    across(const unsigned int b) const
    {
      return b < n_interfaces();
    }
    /// The side of interface @p i that region @p r lies on: 0 for the
    /// first of its regions (Omega- of Sigma), 1 for the second.
    unsigned int
    side(const unsigned int i, const unsigned int r) const
    {
      return r == between[i][0] ? 0 : 1;
    }
    /// "u_minus", "u_plus", "v_minus", ..., "w3_plus" (two regions), or
    /// "u_1", "u_2", ... (layer 1 of the regions 1, 2, ...): the subproblem
    /// in the names of output fields and columns.
    std::string
    field_name(const unsigned int subproblem) const
    {
      const std::string letter = Layout::layer_letter(layer(subproblem));
      if (regions != Layout::n_subdomains)
        return letter + "_" + std::to_string(region(subproblem) + 1);
      return letter + (region(subproblem) == 0 ? "_minus" : "_plus");
    }
    /// "u-", "u+", "v-", "v+", "w3-", ... or "u(1)", "u(2)", ...
    std::string
    name(const unsigned int subproblem) const
    {
      const std::string letter = Layout::layer_letter(layer(subproblem));
      if (regions != Layout::n_subdomains)
        return letter + "(" + std::to_string(region(subproblem) + 1) + ")";
      return letter + (region(subproblem) == 0 ? "-" : "+");
    }

  private:
    unsigned int                             regions;
    unsigned int                             slots;
    std::vector<std::array<unsigned int, 2>> between;
  };

  /// One value per subproblem, indexed by Topology::index(): sized
  /// Topology::n_subproblems().
  template <typename T>
  using PerSubproblem = std::vector<T>;

  /// One value per multiplier block: sized Topology::n_blocks().
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
