// Scenes from Gmsh geometries: Sigma of any shape, several crack pieces,
// boundary parts by name (docs/geometry.md).
//
// Rotation invariance: Example 1 and Example 2 rotated by 30 degrees
// (parameter_files/rotated_partial_closure.geo: the rotated structured mesh
// of the same structure, 16 cells along Sigma, loads and clamps rotated
// with the body) are the same mechanical problem, so the energy must equal
// that of the built-in rectangle to solver tolerance and the opening
// profile [u].nu against arc length to 1e-8 relative (the parameter s runs
// from 0 on the rotated Sigma, from x = -1 on the rectangle), and so must
// the energy release rate at both crack tips (G is invariant under rigid
// motions: a domain integral of invariants of the fields).
//
// Patch tests: both layers clamped on the whole outer boundary to the
// uniform compression u = -e (x, y): the stress is a pressure in both
// layers, so the traction on the crack is normal and compressive for every
// normal (no shear, which the frictionless crack could not carry): the
// exact solution u = v = -e (x, y), crack closed, lies in every discrete
// space, and the weighted nodal normals (MultiplierSpace::node_normal) make
// the discrete pressure on the chords be transmitted exactly.
// On a polygonal Sigma (tests/polygonal_sigma.geo, a crack node at a
// corner) and on the circular arc (parameter_files/curved_interface.geo)
// with matching traces it must be reproduced to round-off. Refining only
// the cells of Omega- along Sigma makes the traces non-matching: on the
// polygon the two traces still lie on the same straight pieces, so round-off
// again; on the arc the new vertices lie on the circle while the coarse side
// keeps its chord, a geometric gap h^2 / (8 R): the error is of that order
// and falls by about 4 when the cells along Sigma are halved again.
//
// The three outer solvers on the curved scene (Q2 on layer 1, Q1 on layer
// 2: non-matching multiplier degrees on the arc): the active set, the
// accelerated method and the paper's Uzawa with theta = auto reach the same
// solution: energies to 1e-8 and the contact multipliers to 1e-6 of their
// largest value (at KKT tolerance 1e-10).
//
// An edge crack (parameter_files/rotated_partial_closure.geo with the left
// glued piece of Sigma made crack: the crack from the free left side, xb =
// -1, to xb = 0.5): the rotated rectangle with the crack interval (-1, 0.5),
// only the right side clamped, under Example 2's load: the same mechanical
// problem, so the same energy and G at its one tip (1e-8; no tip at the
// mouth, on the boundary), and the node at the mouth carries a contact
// multiplier (no tangential one) in both.
//
// Two cracks (parameter_files/two_cracks.prm, Example 1's load on a strip
// with crack pieces (-1.5, -0.5) and (0.5, 1.5)): every acceptance check
// passes (mu_c >= 0, no interpenetration, complementarity), the right piece
// has a contact zone (nodes with mu_c > 0) and the left piece opens; the
// mirrored load (x -> -x) gives the mirrored solution: the opening at
// s equals the mirror load's opening at L - s (1e-8 relative).

#include <deal.II/dofs/dof_tools.h>

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace bilayer;

namespace
{
  std::ostringstream quiet;

  const std::string files = std::string(SOURCE_DIR) + "/../parameter_files/";

  const std::string solver =
    "subsection Solver\n set Method = active set\n set Stopping rule = kkt\n"
    " set Tolerance = 1e-12\nend\n"
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Terminal output = checks\nend\n";

  struct Result
  {
    double              energy;
    std::vector<double> s, opening, mu_c;
    bool                accepted;
    /// The energy release rate at each crack tip, in the order of s.
    std::vector<double> G;
  };

  Result
  solve(const std::string &text)
  {
    Study              study(scene_from_string(text + solver, "scene"), quiet);
    const CycleRecord &record = study.run_cycle(0);
    Result             r{record.energy, {}, {}, {}, record.accepted(), {}};
    for (const EnergyReleaseRate &tip : record.release)
      r.G.push_back(tip.G);
    const auto &space = study.interface().space();
    r.opening         = normal_opening(study.interface(), study.solutions());
    for (unsigned int a = 0; a < space.n_nodes(Layout::across_sigma); ++a)
      {
        r.s.push_back(space.node_position(a, Layout::across_sigma));
        r.mu_c.push_back(space.on_crack(a) ?
                           space.contact_multiplier(study.multipliers(), a) :
                           0.);
      }
    return r;
  }

  double
  max_abs(const std::vector<double> &v)
  {
    double m = 0;
    for (const double x : v)
      m = std::max(m, std::abs(x));
    return m;
  }

  void
  rotation(const std::string &name,
           const std::string &rectangle_loads,
           const std::string &rotated_loads)
  {
    const Result plain =
      solve("subsection Mesh\n set Cells along Sigma = 16\nend\n"
            "subsection Loads\n set Constants = c = 1e-3*mu1\n"
            " subsection Layer 1\n" +
            rectangle_loads + " end\nend\n");
    const Result rotated =
      solve("subsection Geometry\n set Gmsh file = " + files +
            "rotated_partial_closure.geo\n set Clamped sides = left, right\n"
            "end\nsubsection Loads\n"
            " set Constants = c = 1e-3*mu1; cs = cos(_pi/6); sn = sin(_pi/6)\n"
            " subsection Layer 1\n" +
            rotated_loads + " end\nend\n");
    double     profile = 0, shift = 0;
    const bool same_nodes = plain.s.size() == rotated.s.size();
    for (unsigned int a = 0; same_nodes && a < plain.s.size(); ++a)
      {
        profile =
          std::max(profile, std::abs(plain.opening[a] - rotated.opening[a]));
        shift = std::max(shift, std::abs((rotated.s[a] - 1) - plain.s[a]));
      }
    std::cout << name << ", rotated by 30 degrees: accepted: "
              << (plain.accepted && rotated.accepted ? "yes" : "NO")
              << "; same nodes along Sigma: "
              << (same_nodes && shift < 1e-9 ? "yes" : "NO")
              << "; energy equal to 1e-8: "
              << (std::abs(rotated.energy - plain.energy) <=
                      1e-8 * std::abs(plain.energy) ?
                    "yes" :
                    "NO")
              << "; opening profile equal to 1e-8: "
              << (same_nodes && profile <= 1e-8 * max_abs(plain.opening) &&
                      max_abs(plain.opening) > 0 ?
                    "yes" :
                    "NO")
              << "; energy release rate at both tips equal to 1e-8: "
              << (plain.G.size() == 2 && rotated.G.size() == 2 &&
                      std::abs(rotated.G[0] - plain.G[0]) <=
                        1e-8 * max_abs(plain.G) &&
                      std::abs(rotated.G[1] - plain.G[1]) <=
                        1e-8 * max_abs(plain.G) ?
                    "yes" :
                    "NO")
              << std::endl;
  }

  /// Whether node 0 of mu_1 (the start of Sigma) carries a contact
  /// multiplier and no tangential one.
  bool
  mouth_in_contact(const Study &study)
  {
    const auto        &space = study.interface().space();
    const unsigned int mu_1 = Layout::across_sigma, a = 0;
    return space.on_crack(a) &&
           space.set().contact(mu_1, Layout::entry(a, Layout::normal)) &&
           !space.set().free(mu_1, Layout::entry(a, Layout::tangential));
  }

  void
  edge_crack()
  {
    const std::string rectangle =
      "subsection Geometry\n set Crack interval on Sigma = -1, 0.5\n"
      " set Clamped sides = right\nend\n"
      "subsection Mesh\n set Cells along Sigma = 16\nend\n"
      "subsection Loads\n set Constants = c = 1e-3*mu1\n"
      " subsection Layer 1\n  set Traction on bottom side = 0; -c\n"
      "  set Traction on top side = 0; c\n end\nend\n";
    // The glued piece xb in (-1, -0.5) made crack.
    std::ifstream      in(files + "rotated_partial_closure.geo");
    std::ostringstream geo;
    geo << in.rdbuf();
    std::string text = geo.str();
    for (const auto &[from, to] :
         {std::make_pair(std::string("Physical Curve(\"Sigma\") = {7, 9};"),
                         std::string("Physical Curve(\"Sigma\") = {9};")),
          std::make_pair(std::string("Physical Curve(\"crack\") = {8};"),
                         std::string("Physical Curve(\"crack\") = {7, 8};"))})
      text.replace(text.find(from), from.size(), to);
    std::ofstream("edge_crack.geo") << text;
    const std::string rotated =
      "subsection Geometry\n set Gmsh file = edge_crack.geo\n"
      " set Clamped sides = right\nend\nsubsection Loads\n"
      " set Constants = c = 1e-3*mu1; cs = cos(_pi/6); sn = sin(_pi/6)\n"
      " subsection Layer 1\n  set Traction on bottom = sn*c; -cs*c\n"
      "  set Traction on top = -sn*c; cs*c\n end\nend\n";
    Study              plain_study(scene_from_string(rectangle + solver,
                                        "edge_crack_rectangle"),
                      quiet);
    Study              rotated_study(scene_from_string(rotated + solver,
                                          "edge_crack_rotated"),
                        quiet);
    const CycleRecord &plain   = plain_study.run_cycle(0);
    const CycleRecord &turned  = rotated_study.run_cycle(0);
    const bool         one_tip = plain.release.size() == 1 &&
                         turned.release.size() == 1 &&
                         std::abs(plain.release[0].tip.point[0] - 0.5) < 1e-12;
    std::cout << "edge crack, rotated by 30 degrees: accepted: "
              << (plain.accepted() && turned.accepted() ? "yes" : "NO")
              << "; one tip (none at the mouth): " << (one_tip ? "yes" : "NO")
              << "; energy equal to 1e-8: "
              << (std::abs(turned.energy - plain.energy) <=
                      1e-8 * std::abs(plain.energy) ?
                    "yes" :
                    "NO")
              << "; G equal to 1e-8: "
              << (one_tip &&
                      std::abs(turned.release[0].G - plain.release[0].G) <=
                        1e-8 * std::abs(plain.release[0].G) ?
                    "yes" :
                    "NO")
              << "; the mouth node in contact, no tangential multiplier: "
              << (mouth_in_contact(plain_study) &&
                      mouth_in_contact(rotated_study) ?
                    "yes" :
                    "NO")
              << std::endl;
  }

  // Largest deviation of the nodal values of all four subproblems from
  // the affine field E x, relative to its largest value.
  double
  affine_error(const Study &study, const Tensor<2, 2> &E)
  {
    double error = 0, size = 0;
    for (const unsigned int s : Layout::indices(Topology().n_subproblems()))
      {
        const auto           &sub = study.subproblem(s);
        const auto           &w   = study.solutions()[s];
        std::vector<Point<2>> support(sub.n_dofs());
        DoFTools::map_dofs_to_support_points(sub.mapping(),
                                             sub.dof_handler(),
                                             support);
        std::vector<unsigned int>            component(sub.n_dofs());
        std::vector<types::global_dof_index> local(sub.fe().n_dofs_per_cell());
        for (const auto &cell : sub.dof_handler().active_cell_iterators())
          {
            cell->get_dof_indices(local);
            for (unsigned int k = 0; k < local.size(); ++k)
              component[local[k]] = sub.fe().system_to_component_index(k).first;
          }
        for (unsigned int i = 0; i < sub.n_dofs(); ++i)
          {
            const double exact = (E * support[i])[component[i]];
            error              = std::max(error, std::abs(w(i) - exact));
            size               = std::max(size, std::abs(exact));
          }
      }
    return error / size;
  }

  // Errors of the patch test on the matching mesh and after refining the
  // cells of Omega- along Sigma once and twice (non-matching traces).
  // Largest distance of the vertices on Sigma of both meshes from the
  // curve (relative to its length), over the cycles of patch().
  double drift = 0;

  std::array<double, 3>
  patch(const std::string &geo, const std::string &parts)
  {
    drift                    = 0;
    const std::string affine = "-1e-3*x; -1e-3*y";
    Study study(scene_from_string("subsection Geometry\n set Gmsh file = " +
                                    geo + "\n set Clamped sides = " + parts +
                                    "\nend\nsubsection Mesh\n set Refinement = "
                                    "adaptive\n set Number of cycles = 3\n"
                                    " set Refinement fraction = 1\nend\n"
                                    "subsection Loads\n subsection Layer 1\n"
                                    "  set Prescribed displacement = " +
                                    affine +
                                    "\n end\n subsection Layer 2\n"
                                    "  set Prescribed displacement = " +
                                    affine + "\n end\nend\n" + solver,
                                  "patch"),
                quiet);
    Tensor<2, 2> E;
    E[0][0] = -1e-3;
    E[1][1] = -1e-3;
    std::array<double, 3> errors;
    for (unsigned int cycle = 0; cycle < 3; ++cycle)
      {
        const CycleRecord &record = study.run_cycle(cycle);
        errors[cycle]     = record.accepted() ? affine_error(study, E) : 1.;
        const auto &curve = study.interface().curve();
        for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
          for (const auto &face : study.subproblem(Layer::first, sd)
                                    .dof_handler()
                                    .get_triangulation()
                                    .active_face_iterators())
            if (on_sigma(face))
              for (const unsigned int v : face->vertex_indices())
                drift =
                  std::max(drift,
                           curve.distance(face->vertex(v)) / curve.length());
        // Mark the cells along Sigma: of Omega- only after the matching
        // cycle, of both sides after that (the cells along Sigma halved,
        // the traces still non-matching).
        std::vector<Vector<float>> marks(2);
        for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
          {
            const auto &tria = study.subproblem(Layer::first, sd)
                                 .dof_handler()
                                 .get_triangulation();
            auto &m = marks[static_cast<unsigned int>(sd)];
            m.reinit(tria.n_active_cells());
            if (sd == Subdomain::minus || cycle > 0)
              for (const auto &cell : tria.active_cell_iterators())
                for (const auto &face : cell->face_iterators())
                  if (on_sigma(face))
                    m[cell->active_cell_index()] = 1;
          }
        study.set_indicators(marks);
      }
    return errors;
  }

  void
  solvers_agree()
  {
    const std::string scene =
      "subsection Geometry\n set Gmsh file = " + files +
      "curved_interface.geo\n set Clamped sides = left, right\nend\n"
      "subsection Mesh\n set Polynomial degree of layer 1 = 2\nend\n"
      "subsection Loads\n set Constants = q = 1e-3*mu1\n"
      " subsection Layer 1\n"
      "  set Traction on inner = q*x*x/sqrt(x*x + y*y); q*x*y/sqrt(x*x + y*y)\n"
      "  set Traction on outer = -q*x*x/sqrt(x*x + y*y); "
      "-q*x*y/sqrt(x*x + y*y)\n end\nend\n"
      "subsection Output\n set Output directory = results\n"
      " set Write VTU = false\n set Write interface CSV = false\n"
      " set Terminal output = checks\nend\n";
    std::vector<Result> results;
    for (const std::string method : {"active set", "accelerated", "uzawa"})
      {
        Study              study(scene_from_string(
                      scene + "subsection Solver\n set Method = " + method +
                        "\n set Stopping rule = kkt\n set Tolerance = 1e-10\n"
                                     " set Uzawa step theta = auto\n"
                                     " set Maximum iterations = 200000\nend\n",
                      "solvers"),
                    quiet);
        const CycleRecord &record = study.run_cycle(0);
        Result             r{record.energy, {}, {}, {}, record.accepted(), {}};
        for (const EnergyReleaseRate &tip : record.release)
          r.G.push_back(tip.G);
        const auto &space = study.interface().space();
        for (unsigned int a = 0; a < space.n_nodes(Layout::across_sigma); ++a)
          r.mu_c.push_back(space.on_crack(a) ?
                             space.contact_multiplier(study.multipliers(), a) :
                             0.);
        results.push_back(r);
      }
    bool energies = true, multipliers = true, accepted = true;
    for (const auto &r : results)
      {
        accepted = accepted && r.accepted;
        energies = energies && std::abs(r.energy - results[0].energy) <=
                                 1e-8 * std::abs(results[0].energy);
        for (unsigned int a = 0; a < r.mu_c.size(); ++a)
          multipliers =
            multipliers && std::abs(r.mu_c[a] - results[0].mu_c[a]) <=
                             1e-6 * max_abs(results[0].mu_c);
      }
    std::cout << "curved interface, Q2/Q1: active set, accelerated and "
                 "Uzawa (theta = auto) accepted: "
              << (accepted ? "yes" : "NO")
              << "; energies agree to 1e-8: " << (energies ? "yes" : "NO")
              << "; contact multipliers agree to 1e-6: "
              << (multipliers && max_abs(results[0].mu_c) > 0 ? "yes" : "NO")
              << std::endl;
  }

  void
  two_cracks()
  {
    const auto scene = [](const std::string &sign) {
      return "subsection Geometry\n set Gmsh file = " + files +
             "two_cracks.geo\n set Clamped sides = left, right\nend\n"
             "subsection Loads\n set Constants = c = 1e-3*mu1\n"
             " subsection Layer 1\n  set Traction on bottom = 0; " +
             sign + "c*x\n  set Traction on top = 0; " +
             (sign == "" ? "-" : "") + "c*x\n end\nend\n";
    };
    const Result r = solve(scene("")), m = solve(scene("-"));
    // Contact nodes (mu_c > 0) and open nodes (opening > 0) per piece.
    std::array<unsigned int, 2> closed = {{0, 0}}, open = {{0, 0}};
    const double                mid   = 0.5 * (r.s.front() + r.s.back());
    const double                scale = max_abs(r.opening);
    for (unsigned int a = 0; a < r.s.size(); ++a)
      {
        const unsigned int piece = r.s[a] < mid ? 0 : 1;
        closed[piece] += r.mu_c[a] > 0;
        open[piece] += r.opening[a] > 1e-6 * scale;
      }
    double     mirror = 0;
    const bool same   = r.s.size() == m.s.size();
    for (unsigned int a = 0; same && a < r.s.size(); ++a)
      mirror = std::max(mirror,
                        std::abs(r.opening[a] - m.opening[r.s.size() - 1 - a]) +
                          std::abs(r.mu_c[a] - m.mu_c[r.s.size() - 1 - a]) *
                            scale / std::max(max_abs(r.mu_c), 1e-300));
    std::cout << "two cracks: acceptance checks (mu_c >= 0, "
                 "non-penetration, complementarity) pass: "
              << (r.accepted && m.accepted ? "yes" : "NO")
              << "; left piece opens: " << (open[0] > 0 ? "yes" : "NO")
              << "; right piece has a contact zone: "
              << (closed[1] > 0 ? "yes" : "NO")
              << "; mirrored load gives the mirrored pieces (1e-8): "
              << (same && mirror <= 1e-8 * scale ? "yes" : "NO") << std::endl;
  }
} // namespace


int
main()
{
  rotation("Example 1",
           "  set Traction on bottom side = 0; c*x\n"
           "  set Traction on top side = 0; -c*x\n",
           "  set Traction on bottom = -sn*c*(cs*x + sn*y); "
           "cs*c*(cs*x + sn*y)\n"
           "  set Traction on top = sn*c*(cs*x + sn*y); "
           "-cs*c*(cs*x + sn*y)\n");
  rotation("Example 2",
           "  set Traction on bottom side = 0; -c\n"
           "  set Traction on top side = 0; c\n",
           "  set Traction on bottom = sn*c; -cs*c\n"
           "  set Traction on top = -sn*c; cs*c\n");

  const auto polygon = patch(std::string(SOURCE_DIR) + "/polygonal_sigma.geo",
                             "left, right, bottom, top");
  std::cout << "patch test, polygonal Sigma: matching to round-off: "
            << (polygon[0] < 1e-10 ? "yes" : "NO")
            << "; non-matching (Omega- refined along Sigma) to round-off: "
            << (polygon[1] < 1e-10 && polygon[2] < 1e-10 ? "yes" : "NO")
            << "; vertices of Sigma on the polygon after refinement: "
            << (drift < 1e-12 ? "yes" : "NO") << std::endl;
  const auto arc =
    patch(files + "curved_interface.geo", "left, right, inner, outer");
  // Chord of the coarse side: 40/8 = 5 degrees on radius 1, gap h^2/(8R)
  // with h = 0.087: about 1e-3 of the arc's cell; relative to the
  // displacement scale the error is of that order.
  std::cout << "patch test, circular Sigma: matching to round-off: "
            << (arc[0] < 1e-10 ? "yes" : "NO")
            << "; non-matching within the chord gap (< 1e-2): "
            << (arc[1] < 1e-2 ? "yes" : "NO")
            << "; falling by >= 3 when the cells along Sigma are halved: "
            << (arc[2] * 3 <= arc[1] ? "yes" : "NO")
            << "; vertices of Sigma on the circle after refinement: "
            << (drift < 1e-12 ? "yes" : "NO") << std::endl;
  solvers_agree();
  edge_crack();
  two_cracks();
}
