#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <bilayer/build_info.h>
#include <bilayer/layout.h>
#include <bilayer/resources.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <sys/resource.h>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Memory of the program before any mesh: libraries, MPI, threads.
    constexpr double base_memory = 150. * (1 << 20);

    /// A size in /proc/self/status (e.g. "VmSize") in bytes; 0 if unknown.
    double
    self_status(const std::string &key)
    {
      std::ifstream in("/proc/self/status");
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind(key + ":", 0) == 0)
          {
            std::istringstream value(line.substr(key.size() + 1));
            double             kib = 0;
            value >> kib;
            return kib * 1024;
          }
      return 0;
    }

    /// Bytes per degree of freedom of a subproblem with n dofs and
    /// polynomial degree k: matrix, factor (fill ~ n log n), vectors.
    double
    bytes_per_dof(const double n, const unsigned int k)
    {
      const double fill = std::log2(std::max(n, 1e3)) / std::log2(2.6e5);
      return (600. + 2600. * fill) * (1. + 0.2 * (k - 1.));
    }

    /// The number read from /proc/meminfo's line @p key [bytes].
    double
    meminfo(const std::string &key)
    {
      std::ifstream in("/proc/meminfo");
      std::string   name, unit;
      double        value;
      while (in >> name >> value)
        {
          std::getline(in, unit);
          if (name == key + ":")
            return value * 1024;
        }
      return std::numeric_limits<double>::infinity();
    }
  } // namespace


  std::string
  format_bytes(const double bytes)
  {
    std::ostringstream s;
    s << std::setprecision(3);
    if (bytes >= double(1ull << 30))
      s << bytes / double(1ull << 30) << " GiB";
    else
      s << bytes / double(1ull << 20) << " MiB";
    return s.str();
  }


  ResourceEstimate
  estimate_resources(const Scene &scene,
                     const double cells_minus,
                     const double cells_plus)
  {
    ResourceEstimate estimate;
    estimate.memory = base_memory;
    for (const Layer layer : {Layer::first, Layer::second})
      if (scene.materials.has_layer(layer))
        for (const double cells : {cells_minus, cells_plus})
          {
            const unsigned int k = scene.mesh.degree(layer);
            // Nodes of a degree-k mesh of square-ish cells (two triangles
            // per square), two components.
            const double squares =
              scene.mesh.shape == ElementShape::triangle ? cells / 2 : cells;
            const double dofs =
              2 * (k * k * squares + 2 * k * std::sqrt(squares) + 1);
            estimate.dofs += dofs;
            estimate.memory += dofs * bytes_per_dof(dofs, k);
            // Per cell, the (k+1)^2 points of its patch with coordinates,
            // displacement and five stresses, compressed about to half.
            if (scene.output.write_vtu || scene.output.write_hdf5)
              estimate.output +=
                cells * (k + 1) * (k + 1) * 10 * 8 * 0.5 *
                (scene.output.write_vtu + 0. + scene.output.write_hdf5);
          }
    return estimate;
  }


  std::array<double, 2>
  structured_cells(const Scene &scene, const unsigned int cycle)
  {
    const auto &mesh = scene.mesh;
    if (!mesh.mesh_files.empty() || !scene.geometry.gmsh_file.empty() ||
        (cycle > 0 && mesh.refinement == Refinement::adaptive))
      return {{0., 0.}};
    const auto           &g      = scene.geometry;
    const double          factor = std::ldexp(1., cycle);
    const double          width  = g.x_max - g.x_min;
    std::array<double, 2> cells;
    for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
      {
        const double n_x =
          (s == Subdomain::plus && mesh.cells_along_sigma_plus > 0 ?
             mesh.cells_along_sigma_plus :
             mesh.cells_along_sigma) *
          factor;
        const double height = s == Subdomain::minus ? g.sigma_height - g.y_min :
                                                      g.y_max - g.sigma_height;
        const double n_y    = mesh.cells_across > 0 ?
                                mesh.cells_across * factor :
                                std::max(1., std::round(n_x * (height / width)));
        // Triangles: two per quadrilateral.
        cells[static_cast<unsigned int>(s)] =
          n_x * n_y * (mesh.shape == ElementShape::triangle ? 2 : 1);
      }
    return cells;
  }


  double
  available_memory()
  {
    double        available = meminfo("MemAvailable");
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        // A limit of the address space (ulimit -v): what is left of it,
        // the base the estimates count being mapped already, less the work
        // buffers an OpenBLAS maps on its first call from each thread (its
        // BUFFER_SIZE, 32 << 22 bytes on x86-64, per thread that calls it:
        // at most one per subproblem task). OpenBLAS does not survive a
        // failed allocation of these buffers (it retries or crashes), so
        // the run must be refused before.
        const bool   openblas = blas_library().rfind("OpenBLAS", 0) == 0;
        const double buffers =
          openblas ? std::min<double>(Layout::n_subproblems,
                                      MultithreadInfo::n_threads()) *
                       double(32ul << 22) :
                     0.;
        available = std::min(available,
                             double(limit.rlim_cur) - self_status("VmSize") +
                               base_memory - buffers);
      }
    std::ifstream cgroup("/sys/fs/cgroup/memory.max");
    std::string   text;
    if (cgroup >> text && text != "max")
      {
        std::istringstream s(text);
        double             max;
        if (s >> max)
          available = std::min(available, max);
      }
    return available;
  }


  void
  check_scene_resources(const Scene &scene, const unsigned int processes)
  {
    const auto &mesh = scene.mesh;
    // Structured cells of the last cycle; with adaptive refinement only the
    // first cycle's meshes are known.
    const unsigned int last =
      mesh.refinement == Refinement::adaptive ? 0 : mesh.n_cycles - 1;
    const auto cells = structured_cells(scene, last);
    if (cells[0] + cells[1] == 0)
      return;
    const ResourceEstimate estimate =
      estimate_resources(scene, cells[0], cells[1]);
    // Processes on one node share its memory: the subproblems need the
    // same in all, plus each process's libraries.
    const double available = available_memory();
    if (estimate.memory + (processes - 1) * base_memory <= available)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << "Mesh/Cells along Sigma, Mesh/Cells "
            << "across each subdomain, Mesh/Number of cycles: cycle " << last
            << " would have " << cells[0] + cells[1] << " cells and about "
            << estimate.dofs << " dofs, needing about "
            << format_bytes(estimate.memory) << " of memory, but "
            << format_bytes(available)
            << " are available: use fewer cells or cycles (or adaptive "
               "refinement)";
    AssertThrow(false, dealii::ExcMessage(message.str()));
  }
} // namespace bilayer
