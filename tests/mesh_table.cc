// The columns of the mesh-size table (the paper's Table 1) and the output
// contract of summary.json and table.csv.
//
// Gmsh meshes of meshes/half_square.geo: P vertices on Sigma and M on the
// outer boundary by construction; a triangulation of a simply connected
// polygon with V vertices, B of them on the boundary, has exactly
// 2 V - B - 2 triangles (Euler). Structured quadrilaterals with n cells
// along Sigma and n/2 across each half: P = n + 1, M = 4 n, n^2/2 cells and
// n^2/2 + 3n/2 + 1 vertices per half, h = 2/n.
// The contract scene has no loads: its energy and crack opening (the lines
// "energy Pi" and "largest crack opening" of Study) are exactly 0.

#include <deal.II/grid/tria.h>

#include <bilayer/drivers/study.h>
#include <bilayer/geometry/geometry.h>
#include <bilayer/output/cycle_record.h>
#include <bilayer/parameters/parameters.h>

#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  unsigned int
  boundary_vertices(const Triangulation<2> &tria)
  {
    std::set<unsigned int> vertices;
    for (const auto &face : tria.active_face_iterators())
      if (face->at_boundary())
        for (const unsigned int v : face->vertex_indices())
          vertices.insert(face->vertex_index(v));
    return vertices.size();
  }

} // namespace

int
main()
{
  for (const auto &[P, M] :
       std::vector<std::pair<unsigned int, unsigned int>>{{12, 32}, {48, 80}})
    {
      const std::string file = std::string(SOURCE_DIR) + "/../meshes/table1_P" +
                               std::to_string(P) + "_M" + std::to_string(M) +
                               "_{side}.msh";
      const Scene scene = scene_from_string(
        "subsection Mesh\n set Mesh files = " + file + "\nend\n", "gmsh");
      Geometry geometry(scene.geometry, scene.mesh);
      geometry.create_meshes(0);
      std::cout << "Gmsh P/M = " << P << "/" << M
                << ": P matches: " << yes(geometry.n_sigma_vertices() == P)
                << ", M matches: " << yes(geometry.n_outer_vertices() == M);
      const double spacing_crack = 1.0 / (P - 1 - 2 * std::round((P - 1) / 4.));
      for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
        {
          const auto stats = geometry.statistics(s);
          const auto B     = boundary_vertices(geometry.triangulation(s));
          std::cout << ", Euler " << (s == Subdomain::minus ? "-" : "+") << ": "
                    << yes(stats.cells == 2 * stats.vertices - B - 2)
                    << ", h range "
                    << yes(stats.h_min <= spacing_crack + 1e-12 &&
                           spacing_crack <= stats.h_max + 1e-12);
        }
      std::cout << std::endl;
    }

  for (const unsigned int cycle : {0u, 1u})
    {
      const Scene scene =
        scene_from_string("subsection Mesh\n set Cells along Sigma = 12\n"
                          " set Number of cycles = 2\nend\n",
                          "quads");
      Geometry geometry(scene.geometry, scene.mesh);
      geometry.create_meshes(cycle);
      const unsigned int n     = 12u << cycle;
      const auto         stats = geometry.statistics(Subdomain::minus);
      std::cout << "quadrilaterals n = " << n
                << ": P = n + 1: " << yes(geometry.n_sigma_vertices() == n + 1)
                << ", M = 4n: " << yes(geometry.n_outer_vertices() == 4 * n)
                << ", cells: " << yes(stats.cells == n * n / 2)
                << ", vertices: "
                << yes(stats.vertices == n * n / 2 + 3 * n / 2 + 1)
                << ", h = 2/n: "
                << yes(std::abs(stats.h_min - 2. / n) < 1e-12 &&
                       std::abs(stats.h_max - 2. / n) < 1e-12)
                << std::endl;
    }

  // The output contract read by scripts.
  Study study(scene_from_string(
                "subsection Mesh\n set Cells along Sigma = 4\nend\n"
                "subsection Output\n set Output directory = results\n"
                " set Write VTU = false\n set Terminal output = checks\nend\n",
                "contract"),
              std::cout);
  study.run();
  std::ifstream      json("results/summary.json");
  std::ostringstream text;
  text << json.rdbuf();
  // The keys of the file and those of every field of a cycle's record, in
  // this order.
  std::vector<std::string> keys = {"scene", "build", "cycles"};
  for (const std::string &key : CycleRecord::json_keys())
    keys.push_back(key);
  bool        all_keys = true;
  std::size_t position = 0;
  for (const std::string &key : keys)
    {
      const std::size_t found = text.str().find("\"" + key + "\":", position);
      if (found == std::string::npos)
        {
          std::cout << "missing key " << key << std::endl;
          all_keys = false;
        }
      else
        position = found;
    }
  std::cout << "summary.json has every key of the contract: " << yes(all_keys)
            << std::endl;
  // Where the tips are ("# tip k: ...", one per tip), then the header.
  std::ifstream csv("results/table.csv");
  std::string   header;
  while (std::getline(csv, header) && header.rfind("# ", 0) == 0)
    std::cout << "table.csv note: " << header << std::endl;
  std::cout << "table.csv header: " << header << std::endl;
  // The fields, the forces of the boundary parts, then G and its error bar
  // at each of the two crack tips.
  std::string keys_csv;
  for (const std::string &key : CycleRecord::csv_keys())
    keys_csv += (keys_csv.empty() ? "" : ",") + key;
  for (const std::string &key :
       force_columns(study.records().back().forces.parts))
    keys_csv += "," + key;
  keys_csv += ",G_tip1,dG_tip1,G_tip2,dG_tip2";
  if (header != keys_csv)
    std::cout << "table.csv header is not CycleRecord::csv_keys(): " << keys_csv
              << std::endl;
  // table.txt: the same notes, then the table with G and dG at each tip.
  std::ifstream table_txt("results/table.txt");
  while (std::getline(table_txt, header) && header.rfind("# ", 0) == 0)
    std::cout << "table.txt note: " << header << std::endl;
  std::cout << "table.txt has the columns G tip k, dG tip k: "
            << yes(header.find("| G tip 1 | dG tip 1 | G tip 2 | dG tip 2 |") !=
                   std::string::npos)
            << std::endl;
  // Notes (one per crack tip) start with "# ", then the header.
  std::ifstream interface_csv("results/interface-00.csv");
  unsigned int  notes = 0;
  while (std::getline(interface_csv, header) && header.rfind("# ", 0) == 0)
    ++notes;
  std::cout << "interface-00.csv notes: " << notes << std::endl;
  std::cout << "interface-00.csv header: " << header << std::endl;
}
