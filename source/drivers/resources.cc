#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <bilayer/core/build_info.h>
#include <bilayer/core/layout.h>
#include <bilayer/drivers/resources.h>
#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
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

    /**
     * Bytes per degree of freedom of a subproblem with n dofs and
     * polynomial degree k: matrix, Cholesky factor (fill ~ n log n in two
     * dimensions), vectors. Fitted to the peak resident memory of Example 1
     * (scripts/memory_model, docs/performance.md) from 1e4 to 6.6e6 dofs
     * of the four subproblems: 1800 to 2040 bytes per dof for Q1, 1.25
     * times that per degree above 1.
     */
    double
    bytes_per_dof(const double n, const unsigned int k)
    {
      return (1000. + 50. * std::log2(std::max(n, 1e3))) *
             (1. + 0.25 * (k - 1.));
    }

    /// The work buffer OpenBLAS maps for each thread that calls it (its
    /// BUFFER_SIZE, 32 << 22 bytes on x86-64).
    constexpr double openblas_buffer = double(32ul << 22);

    /// The value of the environment variable @p name, or "" if unset.
    std::string
    environment(const char *name)
    {
      const char *v = std::getenv(name);
      return v == nullptr ? "" : v;
    }

    /// Set by glibc's on_exit: ends the process with its exit status
    /// without the destructors of the shared libraries. Under an
    /// address-space limit an OpenBLAS thread that could not map its work
    /// buffer retries for ever, and OpenBLAS's destructor would wait for it
    /// (the process would never end).
    void
    exit_without_blas_shutdown(const int status, void *)
    {
      std::cout.flush();
      std::cerr.flush();
      std::fflush(nullptr);
      std::_Exit(status);
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
    for (const Layer layer : scene.materials.layers())
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
    const auto  &g      = scene.geometry;
    const double factor = std::ldexp(1., cycle);
    const double width  = g.x_max - g.x_min;
    // (The regions above Sigma together.)
    std::array<double, 2> cells = {{0., 0.}};
    for (unsigned int r = 0; r < g.n_regions(); ++r)
      {
        const double n_x = (r > 0 && mesh.cells_along_sigma_plus > 0 ?
                              mesh.cells_along_sigma_plus :
                              mesh.cells_along_sigma) *
                           factor;
        const auto   y      = g.region_heights(r);
        const double height = y[1] - y[0];
        const double n_uniform =
          structured_cells_across(mesh, n_x, height, width, cycle);
        // (The rows fitted to the plies, as Geometry builds them.)
        const double y0 = y[0];
        const auto   rows =
          ply_rows(scene.materials.all_ply_heights(),
                   y0,
                   y0 + height,
                   static_cast<unsigned int>(n_uniform),
                   static_cast<unsigned int>(structured_cells_across(
                     mesh, n_x / factor, height, width, 0)),
                   cycle);
        const double n_y = rows.empty() ? n_uniform : rows.size() - 1.;
        // Triangles: two per quadrilateral.
        cells[std::min(r, 1u)] +=
          n_x * n_y * (mesh.shape == ElementShape::triangle ? 2 : 1);
      }
    return cells;
  }


  MemoryAvailability
  memory_availability()
  {
    MemoryAvailability a;
    a.bytes = a.machine = meminfo("MemAvailable");
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        // A limit of the address space (ulimit -v): what is left of it,
        // the base the estimates count being mapped already, less the work
        // buffers an OpenBLAS maps on its first call from each thread (at
        // most one per subproblem task). OpenBLAS does not survive a
        // failed allocation of these buffers (its threads retry for ever),
        // so the run must be refused before, and the process must end
        // without waiting for such threads.
        a.openblas = blas_library().rfind("OpenBLAS", 0) == 0;
        if (a.openblas)
          {
            static const bool registered =
              on_exit(exit_without_blas_shutdown, nullptr) == 0;
            (void)registered;
          }
        a.address_space = double(limit.rlim_cur);
        a.mapped        = self_status("VmSize");
        a.blas_buffers  = a.openblas ?
                            std::min<double>(Topology().n_subproblems(),
                                            MultithreadInfo::n_threads()) *
                             openblas_buffer :
                            0.;
        const double left =
          a.address_space - a.mapped + base_memory - a.blas_buffers;
        if (left < a.bytes)
          a.bytes = left, a.limit = MemoryAvailability::Limit::address_space;
      }
    std::ifstream cgroup("/sys/fs/cgroup/memory.max");
    std::string   text;
    if (cgroup >> text && text != "max")
      {
        std::istringstream s(text);
        double             max;
        if (s >> max && max < a.bytes)
          a.bytes = max, a.limit = MemoryAvailability::Limit::cgroup;
      }
    return a;
  }


  double
  available_memory()
  {
    return memory_availability().bytes;
  }


  std::string
  MemoryAvailability::shortage(const std::string &entries,
                               const double       needed) const
  {
    std::ostringstream m;
    m << std::setprecision(3);
    if (limit == Limit::address_space)
      {
        const std::string blas_env = environment("OPENBLAS_NUM_THREADS"),
                          own_env  = environment("BILAYER_BLAS_THREADS");
        m << format_bytes(bytes) << " are left of the address-space limit "
          << "(ulimit -v) of " << format_bytes(address_space)
          << ": the process has mapped " << format_bytes(mapped)
          << " already (libraries and threads";
        if (openblas)
          m << "; each OpenBLAS thread maps a work buffer of "
            << format_bytes(openblas_buffer) << ", and the subproblem tasks' "
            << "calls need " << format_bytes(blas_buffers) << " more";
        m << ")";
        // The threads make the difference only where the memory they map
        // would leave room for the meshes; one BLAS thread already: the
        // libraries themselves fill the limit.
        const bool one_thread =
          blas_env == "1" && (own_env.empty() || own_env == "1");
        const bool threads_matter =
          openblas && !one_thread && needed <= bytes + mapped + blas_buffers;
        m << ": " << entries;
        if (threads_matter)
          m << ", run with fewer BLAS threads (OPENBLAS_NUM_THREADS=1"
            << (blas_env.empty() ? "" : " instead of " + blas_env)
            << ", BILAYER_BLAS_THREADS=1"
            << (own_env.empty() ? "" : " instead of " + own_env) << ")";
        m << " or raise ulimit -v";
      }
    else if (limit == Limit::cgroup)
      m << format_bytes(bytes) << " are available (the cgroup's memory.max)"
        << ": " << entries << ", or a larger memory.max";
    else
      m << format_bytes(bytes) << " are available (MemAvailable): " << entries;
    if (bytes > 0)
      m << "; Mesh/Refuse above available memory = false runs it anyway";
    return m.str();
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
    const MemoryAvailability available = memory_availability();
    if (estimate.memory + (processes - 1) * base_memory <= available.bytes)
      return;
    if (!mesh.refuse_above_memory && available.bytes > 0)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << "cycle " << last << " would have "
            << cells[0] + cells[1] << " cells and about " << estimate.dofs
            << " dofs, needing about " << format_bytes(estimate.memory)
            << " of memory, but "
            << available.shortage(
                 "use fewer cells or cycles (Mesh/Cells along Sigma, Mesh/"
                 "Cells across each subdomain, Mesh/Number of cycles) or "
                 "adaptive refinement",
                 estimate.memory);
    AssertThrow(false, dealii::ExcMessage(message.str()));
  }
} // namespace bilayer
