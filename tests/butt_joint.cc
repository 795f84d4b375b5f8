// Regions that meet at a point (docs/laminates.md, "Regions that meet at a
// point"): parameter_files/butt_joint.prm, two plies butted on a base ply,
// three regions and three interfaces meeting at the cross-point (20, 1);
// interface 3 (the butt) joins regions 2 and 3, not two neighbours of a
// chain. At the cross-point the across blocks tie three copies of one point
// in a cycle; one of the three ends is implied by the other two and is
// left out (MultiplierSpace::drop_cross_point_ends()).
//
// 1. The same discrete problem: with the butt glued (b = 0) both plies take
//    the law of Omega+, so the three-region scene and the same cells with
//    the plies as one region Omega+ (butt = 0) are one discrete problem
//    (matching meshes: the glued interfaces tie the nodes). Every cycle's
//    energy agrees to 1e-10 and G at both tips of the delamination to 1e-8
//    (uniform Q2, three cycles). The three-region run leaves an end out at
//    the cross-point (without it the Schur complement is singular).
// 2. G at every tip of every interface against the energy: the fourth-order
//    central difference of Pi with the tip moved by -+ h, -+ 2h (h = 1/8,
//    one cell; each a .geo of its own) agrees with the domain integral to
//    1e-3 at the two tips on Sigma and at the tip of the butt crack on
//    interface 3 (uniform Q2, cells 1/8).
// 3. Two layers glued along all three interfaces: two identical layers,
//    each with half the traction, the same temperature change and the same
//    clamps, deform alike (u = v, the gluing multipliers zero), so the
//    energy is that of one layer of twice the moduli (1e-10); the gluing
//    blocks of each region meet at the cross-point too (degrees 2 and 2:
//    nodal, ends left out). With degrees 2 and 1 (mortar gluing at the
//    cross-point) every cycle is accepted and the energy falls under nested
//    refinement.
// 4. The shipped scene, adaptive Q2, with the tip of the butt crack 1/4
//    above the cross-point: every cycle accepted, the energy falls from
//    cycle to cycle, and on the last cycle the meshes do not match at the
//    cross-point. On the finer traces (the default) the blocks stay nodal
//    (a coarse trace lies in the finer one's space) and the end left out is
//    implied exactly (its jump checked); on the coarser traces the blocks
//    at the cross-point are mortar blocks, the end's basis joined to its
//    neighbour's.
// 5. A crack that reaches the cross-point (the delamination on Sigma to
//    a = 20) is refused with a one-line reason.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "quiet_output.h"
#include "scene_text.h"
#include "study_outcome.h"
#include "verdict.h"

using namespace bilayer;

namespace
{


  const std::string dir = std::string(SOURCE_DIR) + "/../parameter_files/";

  /// The shape of the scene: the delamination from c to a on Sigma, the
  /// butt crack of depth b, the plies as two regions or one.
  struct Shape
  {
    double a = 10, b = 0.75, c = 4;
    bool   butt = true;
  };

  using entries::number;

  /// parameter_files/butt_joint.prm on its .geo with the shape @p shape
  /// (written into the working directory), with @p more appended.
  std::string
  scene(const Shape &shape, const std::string &more)
  {
    std::string geo = file_text(dir + "butt_joint.geo");
    geo = replace_line(geo, "  a = 10;", "  a = " + number(shape.a) + ";");
    geo = replace_line(geo, "  b = 0.75;", "  b = " + number(shape.b) + ";");
    geo = replace_line(geo, "  c = 4;", "  c = " + number(shape.c) + ";");
    geo = replace_line(geo,
                       "  butt = 1;",
                       "  butt = " + std::string(shape.butt ? "1" : "0") + ";");
    const std::string name = "butt_joint_" + number(shape.a) + "_" +
                             number(shape.b) + "_" + number(shape.c) + "_" +
                             (shape.butt ? "1" : "0") + ".geo";
    std::ofstream(name) << geo;
    return replace_line(file_text(dir + "butt_joint.prm"),
                        "  set Gmsh file",
                        "  set Gmsh file = " + name) +
           more;
  }

  /// Uniform refinement: the Gmsh cells of size @p size, @p cycles cycles.
  std::string
  uniform(const double size, const unsigned int cycles)
  {
    return "subsection Mesh\n set Refinement = global\n"
           " set Gmsh mesh size factor = " +
           number(size) +
           "\n set Number of cycles = " + std::to_string(cycles) + "\nend\n";
  }

  /// Whether a block has an end left out at a cross-point; with @p mortar,
  /// a block with a side that is not nodal.
  bool
  cross_point_end(const Study &study, const bool mortar)
  {
    const MultiplierSpace &space = study.interface().space();
    for (unsigned int b = 0; b < space.n_blocks(); ++b)
      for (const unsigned int a : {0u, space.n_nodes(b) - 1})
        if (space.n_nodes(b) > 0 && space.cross_point_end(a, b) &&
            (!mortar || !(space.nodal(b, 0) && space.nodal(b, 1))))
          return true;
    return false;
  }

  struct Run
  {
    StudyOutcome outcome;
    bool         cross_point_end = false, mortar_cross_point_end = false;
    /// The cells at the cross-point (20, 1) of the regions differ in size.
    bool unmatched_cross_point = false;
    /// What the study wrote.
    std::string log;
  };

  /// The smallest size of the cells of each region with the vertex (20, 1).
  bool
  unmatched_cross_point(const Study &study)
  {
    const Geometry     &geometry = study.state().geometry();
    std::vector<double> sizes;
    for (unsigned int r = 0; r < geometry.n_regions(); ++r)
      {
        double smallest = 1e300;
        for (const auto &cell :
             geometry.triangulation(r).active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(dealii::Point<2>(20, 1)) < 1e-9)
              smallest = std::min(smallest, cell_size(cell));
        sizes.push_back(smallest);
      }
    return *std::min_element(sizes.begin(), sizes.end()) <
           0.99 * *std::max_element(sizes.begin(), sizes.end());
  }

  Run
  run(const std::string &text)
  {
    std::ostringstream sink;
    Study study(scene_from_string(text + quiet_output(), "butt_joint"), sink);
    Run   r;
    r.outcome                = study_outcome(study, study.run());
    r.cross_point_end        = cross_point_end(study, false);
    r.mortar_cross_point_end = cross_point_end(study, true);
    r.unmatched_cross_point  = unmatched_cross_point(study);
    r.log                    = sink.str();
    return r;
  }

  bool
  falls(const std::vector<double> &energies)
  {
    bool result = energies.size() > 1;
    for (unsigned int k = 1; result && k < energies.size(); ++k)
      result = energies[k] < energies[k - 1];
    return result;
  }
} // namespace


int
main()
{
  // 1. Three regions or two: one discrete problem.
  {
    Shape three;
    three.b                = 0;
    Shape two              = three;
    two.butt               = false;
    const Run           r3 = run(scene(three, uniform(0.5, 3)));
    const Run           r2 = run(scene(two, uniform(0.5, 3)));
    const StudyOutcome &t = r3.outcome, &o = r2.outcome;
    bool same = t.accepted && o.accepted && t.energies.size() == 3 &&
                o.energies.size() == 3;
    for (unsigned int k = 0; same && k < 3; ++k)
      same = std::abs(t.energies[k] - o.energies[k]) <=
             1e-10 * std::abs(o.energies[k]);
    std::cout << "glued butt: three regions and two, both accepted, every "
                 "cycle's energy equal to 1e-10: "
              << yes(same) << std::endl;
    bool same_G = t.release.size() == 2 && o.release.size() == 2;
    for (unsigned int k = 0; same_G && k < 2; ++k)
      same_G =
        t.release[k].tip.interface == 0 &&
        t.release[k].tip.point.distance(o.release[k].tip.point) < 1e-12 &&
        std::abs(t.release[k].G - o.release[k].G) <=
          1e-8 * std::abs(o.release[k].G);
    std::cout << "glued butt: G at both tips on Sigma equal to 1e-8: "
              << yes(same_G) << std::endl;
    std::cout << "glued butt: an end left out at the cross-point (three "
                 "regions), none with two: "
              << yes(r3.cross_point_end && !r2.cross_point_end) << std::endl;
  }

  // 2. G at every tip against finite differences of the energy.
  {
    const double      h    = 0.125;
    const std::string mesh = uniform(h, 1);
    const Run         base = run(scene(Shape(), mesh));
    const auto       &g    = base.outcome.release;
    bool              tips = base.outcome.accepted && g.size() == 3 &&
                g[0].tip.interface == 0 && g[1].tip.interface == 0 &&
                g[2].tip.interface == 2 &&
                g[2].tip.point.distance(dealii::Point<2>(20, 2.25)) < 1e-12;
    std::cout << "butt joint: accepted, two tips on Sigma, one on interface "
                 "3 at (20, 2.25): "
              << yes(tips) << std::endl;
    bool       accepted = tips;
    const auto energy   = [&](const Shape &shape) {
      const Run r = run(scene(shape, mesh));
      accepted    = accepted && r.outcome.accepted;
      return r.outcome.energies.empty() ? std::nan("") :
                                            r.outcome.energies.back();
    };
    // d Pi / d(length) at each tip: the length grows with -c (tip 1), a
    // (tip 2) and b (tip 3).
    const auto difference = [&](const auto &moved) {
      return -(8 * (energy(moved(h)) - energy(moved(-h))) -
               (energy(moved(2 * h)) - energy(moved(-2 * h)))) /
             (12 * h);
    };
    const double fd[3] = {difference([](const double d) {
                            Shape s;
                            s.c -= d;
                            return s;
                          }),
                          difference([](const double d) {
                            Shape s;
                            s.a += d;
                            return s;
                          }),
                          difference([](const double d) {
                            Shape s;
                            s.b += d;
                            return s;
                          })};
    for (unsigned int t = 0; t < 3; ++t)
      std::cout << "butt joint: the fourth-order difference of Pi agrees with "
                   "G at tip "
                << t + 1 << " to 1e-3: "
                << yes(accepted && tips &&
                       std::abs(fd[t] - g[t].G) <= 1e-3 * std::abs(g[t].G))
                << std::endl;
  }

  // 3. Two layers glued along the three interfaces.
  {
    Shape glued;
    glued.b = 0;
    // Both layers: the laws of butt_joint.prm, half the traction each.
    const std::string layer =
      " set Young's modulus = 1\n set Poisson's ratio = 0.3\n"
      " set Thermal expansion = 0\n subsection Omega+\n"
      "  set Young's modulus = 3\n  set Poisson's ratio = 0.25\n"
      "  set Thermal expansion = 1e-3\n end\n";
    const std::string two_layers =
      "subsection Materials\n set Number of layers = 2\n"
      " subsection Layer 1\n" +
      layer + " end\n subsection Layer 2\n" + layer +
      " end\nend\n"
      "subsection Loads\n subsection Layer 1\n"
      "  set Traction on top = 0; x > 5 && x < 9 ? 5e-4 : 0\n end\n"
      " subsection Layer 2\n"
      "  set Traction on top = 0; x > 5 && x < 9 ? 5e-4 : 0\n end\nend\n";
    const std::string stiff = "subsection Materials\n subsection Layer 1\n"
                              "  set Young's modulus = 2\n  subsection Omega+\n"
                              "   set Young's modulus = 6\n  end\n end\nend\n";
    const std::string degrees =
      "subsection Mesh\n set Polynomial degree of layer 2 = 2\nend\n";
    const Run layered =
      run(scene(glued, uniform(0.5, 2) + two_layers + degrees));
    const Run one  = run(scene(glued, uniform(0.5, 2) + stiff));
    bool      same = layered.outcome.accepted && one.outcome.accepted &&
                layered.outcome.energies.size() == 2 &&
                one.outcome.energies.size() == 2;
    for (unsigned int k = 0; same && k < 2; ++k)
      same = std::abs(layered.outcome.energies[k] - one.outcome.energies[k]) <=
             1e-10 * std::abs(one.outcome.energies[k]);
    std::cout << "two identical layers (degrees 2, 2) glued along the three "
                 "interfaces: the energy of one layer of twice the moduli "
                 "(1e-10): "
              << yes(same) << std::endl;
    const Run mixed = run(scene(glued,
                                uniform(0.5, 3) + two_layers +
                                  "subsection Mesh\n set Polynomial degree of "
                                  "layer 2 = 1\nend\n"));
    std::cout << "two layers of degrees 2 and 1 (mortar gluing at the "
                 "cross-point): every cycle accepted, the energy falls: "
              << yes(mixed.outcome.accepted &&
                     mixed.outcome.energies.size() == 3 &&
                     falls(mixed.outcome.energies) &&
                     mixed.mortar_cross_point_end)
              << std::endl;
  }

  // 4. The shipped scene, adaptive, with the tip of the butt crack near
  // the cross-point (b = 1.75): the cells at the tip are refined on the
  // two plies, not on the base.
  {
    Shape near;
    near.b = 1.75;
    const std::string cycles =
      "subsection Mesh\n set Number of cycles = 6\nend\n";
    const Run r = run(scene(near, cycles));
    std::cout << "butt joint, adaptive Q2: every cycle accepted, the energy "
                 "falls, the meshes do not match at the cross-point on the "
                 "last cycle: "
              << yes(r.outcome.accepted && r.outcome.energies.size() == 6 &&
                     falls(r.outcome.energies) && r.cross_point_end &&
                     r.unmatched_cross_point)
              << std::endl;
    const Run m = run(scene(near,
                            cycles + "subsection Contact\n set Multiplier mesh "
                                     "= coarser trace\nend\n"));
    std::cout << "the same on the coarser traces (mortar blocks at the "
                 "cross-point): every cycle accepted, the energy falls: "
              << yes(m.outcome.accepted && m.outcome.energies.size() == 6 &&
                     falls(m.outcome.energies) && m.mortar_cross_point_end)
              << std::endl;
  }

  // 5. A crack that reaches the cross-point.
  {
    Shape reaching;
    reaching.a = 20;
    reaching.b = 0;
    std::string message;
    bool        accepted = false;
    try
      {
        const Run r = run(scene(reaching, uniform(0.5, 1)));
        accepted    = r.outcome.accepted;
        message     = r.log;
      }
    catch (const std::exception &e)
      {
        message = e.what();
      }
    std::cout << "a crack that reaches the cross-point: refused, naming the "
                 "point (20, 1): "
              << yes(!accepted &&
                     message.find("reaches (20, 1)") != std::string::npos &&
                     message.find("three regions meet") != std::string::npos)
              << std::endl;
  }
}
