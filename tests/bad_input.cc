// Bad input gives one clear line naming the parameter and the allowed
// range (bilayer prints it as "bilayer: error: ..." and exits with 1).

#include <bilayer/geometry/geometry.h>
#include <bilayer/parameters/parameters.h>

#include <iostream>

using namespace dealii;
using namespace bilayer;

int
main()
{
  deal_II_exceptions::disable_abort_on_exception();
  deal_II_exceptions::suppress_stacktrace_in_exceptions();
  const std::vector<std::string> inputs = {
    "subsection Materials\n subsection Layer 2\n"
    "  set Young's modulus = 0\n end\nend\n",
    "subsection Materials\n subsection Layer 1\n"
    "  set Poisson's ratio = 0.5\n end\nend\n",
    "subsection Geometry\n set Height of Sigma = 1.5\nend\n",
    "subsection Geometry\n set Crack interval on Sigma = 0.5, -0.5\nend\n",
    "subsection Geometry\n set Clamped sides = left\n"
    " set Crack interval on Sigma = -1, 0.5\nend\n",
    "subsection Solver\n set Uzawa step theta = 0\nend\n",
    "subsection Solver\n set Uzawa step theta = fast\nend\n",
    "subsection Solver\n set Tolerance = 0\nend\n",
    "subsection Contact\n set Multiplier bound p = 0\nend\n",
    "subsection Loads\n set Constants = c = 1e-3*mu7\nend\n",
    "subsection Loads\n set Constants = 3c = 1\nend\n",
    "subsection Loads\n subsection Layer 1\n"
    "  set Traction on top side = 0; c*x\n end\nend\n",
    "subsection Loads\n subsection Layer 2\n"
    "  set Traction on top side = 1\n end\nend\n",
    "subsection Loads\n subsection Layer 1\n"
    "  set Traction on left side = 0; 1\n end\nend\n",
    "subsection Mesh\n set Element shape = triangles\n"
    " set Polynomial degree of layer 2 = 3\nend\n",
    "subsection Mesh\n set Cells along Sigma = 6\nend\n"};
  for (const auto &text : inputs)
    try
      {
        const Scene scene = scene_from_string(text, "bad");
        Geometry    geometry(scene.geometry, scene.mesh);
        geometry.create_meshes(0);
        std::cout << "accepted (wrong)" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::cout << one_line_message(e) << std::endl;
      }
}
