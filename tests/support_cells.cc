// The support of the velocity field theta of the energy release rate must
// hold cells: theta falls from 1 to 0 on R/2 < r < R, and a support radius R
// below the size h of the cells at the tip sees the discrete solution as
// smooth there (G -> 0 as R -> 0 on a fixed mesh): R >= h is required on
// the meshes of both subdomains, at every cycle.
//
// 1. support_cells(): the cells at a tip of the 16-cell rectangle have the
//    size 2/16 (the side of the squares), on both meshes.
// 2. A given radius below the cell size (R = 0.01, cells 0.125), uniform
//    refinement: refused before anything is computed, naming the entry.
// 3. The automatic radius next to a clamped side (the crack from x = -0.999
//    with Mesh/Fit crack tips: R = 0.0005) is checked the same way: G is not
//    reported at that tip (NaN, with the reason), the run goes on (G is a
//    by-product of every scene with a crack, coarse meshes included).
// 4. Uniform refinement from cells larger than R = 0.2 (8 cells, 0.25, then
//    0.125): the first cycle reports G as not resolved (NaN, with the
//    reason), the last a finite G, and the run passes.
// 5. Adaptive refinement that ends with cells larger than R = 0.01: the run
//    fails its checks at the last cycle, naming the entry.
// 6. Mesh/Fit crack tips with a tip within half a cell of an end of Sigma
//    (x = -0.97 and its mirror 0.97, 16 cells) or of the other tip (-0.5,
//    -0.45): each tip becomes a mesh vertex and the run passes.
// 7. Adaptive refinement refines the cells at a tip whose support holds too
//    few of them, whatever the indicators say: the crack (-0.5, 0.9) on 16
//    cells (0.125) with Mesh/Fit crack tips has the automatic radius
//    R = 0.05 at the tip x = 0.9 (half its distance to the clamped side),
//    a tip in the contact zone that the indicators do not refine. Each
//    cycle halves the cells at the tip: 0.0625 > R on cycle 1, 0.03125 <= R
//    on cycle 2, so G is NaN on cycles 0 and 1 and finite from cycle 2 on,
//    and the run passes.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/postprocess/fracture.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{

  std::string
  scene(const std::string &extra)
  {
    return "subsection Loads\n set Constants = c = 1e-3*mu1\n"
           " subsection Layer 1\n"
           "  set Traction on bottom side = 0; c*x\n"
           "  set Traction on top side = 0; -c*x\n end\nend\n"
           "subsection Solver\n set Method = active set\n"
           " set Tolerance = 1e-10\nend\n"
           "subsection Output\n set Output directory = results\n"
           " set Write VTU = false\n set Write interface CSV = false\n"
           " set Terminal output = checks\nend\n" +
           extra;
  }

  /// The message of the refusal of @p text, or "" if it runs.
  std::string
  refusal(const std::string &text)
  {
    try
      {
        std::ostringstream sink;
        Study study(scene_from_string(scene(text), "support_cells"), sink);
        study.run();
      }
    catch (const ExceptionBase &e)
      {
        return one_line_message(e);
      }
    return "";
  }
} // namespace


int
main()
{
  // 1.
  {
    std::ostringstream sink;
    Study              study(scene_from_string(scene("subsection Mesh\n set "
                                                     "Cells along Sigma = 16\nend\n"),
                                  "support_cells"),
                sink);
    study.run();
    const auto &tips = study.records().back().release;
    const std::array<const Triangulation<2> *, 2> meshes = {
      {&study.subproblem(Layer::first, Subdomain::minus)
          .dof_handler()
          .get_triangulation(),
       &study.subproblem(Layer::first, Subdomain::plus)
          .dof_handler()
          .get_triangulation()}};
    bool sizes = tips.size() == 2;
    for (const auto &g : tips)
      sizes =
        sizes && std::abs(support_cells(g.tip, meshes).size - 0.125) < 1e-12 &&
        std::abs(support_cells(g.tip, {{meshes[1], nullptr}}).size - 0.125) <
          1e-12;
    std::cout << "16 cells: the cells at both tips have the size 2/16 on both "
                 "meshes: "
              << yes(sizes) << std::endl;
    std::cout << "16 cells: the automatic supports (R = 0.25) hold them, G "
                 "finite at both tips: "
              << yes(tips.size() == 2 && std::isfinite(tips[0].G) &&
                     std::isfinite(tips[1].G) && tips[0].unresolved.empty())
              << std::endl;
  }
  // 2.
  {
    const std::string m =
      refusal("subsection Mesh\n set Cells along Sigma = 16\nend\n"
              "subsection Fracture\n set Support radius = 0.01\nend\n");
    std::cout << "R = 0.01 on cells of 0.125: refused, naming the entry and "
                 "the cells: "
              << yes(m.find("Fracture/Support radius = 0.01 at the crack "
                            "tip at x = -0.5 holds 0.08 cells") !=
                       std::string::npos &&
                     m.find("at least 200 Mesh/Cells along Sigma") !=
                       std::string::npos)
              << std::endl;
  }
  // 3.
  {
    std::ostringstream sink;
    Study              study(scene_from_string(
                  scene("subsection Geometry\n set Crack interval on Sigma "
                                     "= -0.999, 0.5\nend\n"
                                     "subsection Mesh\n set Cells along Sigma = 16\n"
                                     " set Fit crack tips = true\nend\n"),
                  "support_cells"),
                sink);
    const bool         accepted = study.run();
    const auto        &tips     = study.records().back().release;
    std::cout << "the automatic radius 0.0005 next to the clamped side: G "
                 "not reported there (NaN, naming the radius), the other "
                 "tip's G finite: "
              << yes(accepted && tips.size() == 2 && std::isnan(tips[0].G) &&
                     tips[0].unresolved.find(
                       "the automatic support radius R = 0.0005") !=
                       std::string::npos &&
                     tips[0].unresolved.find("x = -0.999") !=
                       std::string::npos &&
                     std::isfinite(tips[1].G) && tips[1].unresolved.empty())
              << std::endl;
  }
  // 4.
  {
    std::ostringstream sink;
    Study              study(
      scene_from_string(scene("subsection Mesh\n set Cells along Sigma = 8\n"
                                           " set Number of cycles = 2\nend\n"
                                           "subsection Fracture\n set Support radius = 0.2\n"
                                           "end\n"),
                        "support_cells"),
      sink);
    const bool  accepted = study.run();
    const auto &first    = study.records().front().release;
    const auto &last     = study.records().back().release;
    std::cout << "uniform, R = 0.2 from cells of 0.25: cycle 0 reports G "
                 "as not resolved: "
              << yes(first.size() == 2 && std::isnan(first[0].G) &&
                     first[0].unresolved.find("holds 0.8 cells") !=
                       std::string::npos)
              << std::endl
              << "uniform, R = 0.2: the last cycle (cells of 0.125) reports "
                 "finite G at both tips, the run passes: "
              << yes(accepted && last.size() == 2 && std::isfinite(last[0].G) &&
                     std::isfinite(last[1].G) && last[0].G > 0)
              << std::endl;
  }
  // 5.
  {
    std::ostringstream sink;
    Study              study(scene_from_string(
                  scene("subsection Mesh\n set Cells along Sigma = 8\n"
                                     " set Refinement = adaptive\n"
                                     " set Number of cycles = 2\nend\n"
                                     "subsection Fracture\n set Support radius = 0.01\n"
                                     "end\n"),
                  "support_cells"),
                sink);
    const bool         accepted = study.run();
    const auto         failure  = study.records().back().failure();
    std::cout << "adaptive, R = 0.01 on cells of 0.125 at the last cycle: "
                 "the run fails, naming the entry: "
              << yes(!accepted &&
                     failure.find("energy release rate resolved at every "
                                  "crack tip: NO") != std::string::npos &&
                     failure.find("Fracture/Support radius = 0.01") !=
                       std::string::npos)
              << std::endl;
  }
  // 6.
  for (const std::string crack : {"-0.97, 0.5", "-0.5, 0.97", "-0.5, -0.45"})
    {
      std::ostringstream sink;
      Study              study(scene_from_string(
                    scene("subsection Geometry\n set Crack interval on Sigma "
                                       "= " +
                          crack +
                          "\nend\n"
                                       "subsection Mesh\n set Cells along Sigma = 16\n"
                                       " set Fit crack tips = true\nend\n"
                                       "subsection Fracture\n set Energy release rate = "
                                       "false\nend\n"),
                    "support_cells"),
                  sink);
      std::cout << "Fit crack tips, crack " << crack
                << ": meshed (the tips are vertices) and the run passes: "
                << yes(study.run()) << std::endl;
    }
  // 7.
  {
    std::ostringstream sink;
    Study              study(scene_from_string(
                  scene("subsection Geometry\n set Crack interval on Sigma "
                                     "= -0.5, 0.9\nend\n"
                                     "subsection Mesh\n set Cells along Sigma = 16\n"
                                     " set Fit crack tips = true\n"
                                     " set Refinement = adaptive\n"
                                     " set Number of cycles = 4\nend\n"),
                  "support_cells"),
                sink);
    const bool         accepted = study.run();
    const auto        &records  = study.records();
    bool               pattern  = records.size() == 4;
    for (unsigned int c = 0; pattern && c < records.size(); ++c)
      pattern = records[c].release.size() == 2 &&
                std::isfinite(records[c].release[0].G) &&
                std::isnan(records[c].release[1].G) == (c < 2);
    std::cout << "adaptive, the automatic R = 0.05 at x = 0.9 on cells of "
                 "0.125: the cells at the tip are refined, G not resolved "
                 "on cycles 0 and 1, finite from cycle 2 on, the run "
                 "passes: "
              << yes(accepted && pattern) << std::endl;
  }
}
