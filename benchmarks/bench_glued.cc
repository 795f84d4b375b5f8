// The cost floor of the contact solve: one direct solve of the glued linear
// problem on the undivided domain, timed phase by phase.
//
// Both layers live on one triangulation of Omega (the meshes of Omega- and
// Omega+ that bilayer builds for the scene, merged into one: the same
// cells, Sigma an interior line), their displacements form one FESystem
// FE_Q(p)^4 = (u1, u2, v1, v2), and the layers are glued on all of Sigma by
// the constraints v = u at every dof on Sigma. The crack is closed: layer 1
// and layer 2 are continuous across Sigma. The clamped sides, the
// prescribed displacements, the moduli (ElasticLaw) and the tractions
// are those of the scene. The matrix is assembled with the constraints
// condensed (deal.II's AffineConstraints) and factorised by bilayer's
// SparseCholesky (CHOLMOD supernodal, its ordering, the BLAS the process
// loaded). This is the one linear elasticity solve that any method for the
// problem with contact has to make at least once.
//
// Minimisation principle: the glued problem minimises the energy
//   Pi(u, v) = a(w, w) / 2 - (F, w)
// over the subspace K_glued = { u, v continuous on Omega, u = v on Sigma } of
// the admissible set of the crack problem (free faces: no non-penetration;
// or with contact). Its minimum is therefore the largest of the three:
//   Pi(free faces) <= Pi(contact) <= Pi(glued),
// with equality when the crack is empty. The discrete spaces (nodal
// constraints on matching meshes) are nested in the same way.
//
// Usage: bench_glued SCENE.prm [--set Section/Entry=value ...]
//                    [--blas-threads N] [--json FILE]
// Reads the scene as bilayer does (same parameter classes, --set
// overrides), builds the last cycle's mesh (Mesh/Number of cycles, global
// refinement), prints the phases (mesh, dofs + constraints + sparsity,
// assembly, factorisation, solve, energy), the dofs, the energy and the
// peak resident memory, and writes them as JSON to FILE. Rectangle scenes
// with two layers of the same degree and matching meshes only; anything
// else is refused with one line. A benchmark: it times and prints.

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <bilayer/core/build_info.h>
#include <bilayer/geometry/geometry.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/physics/elastic_law.h>
#include <bilayer/subproblem/cholesky.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/resource.h>
#include <vector>

using namespace dealii;
using namespace bilayer;

namespace
{
  struct Options
  {
    std::string              parameter_file;
    std::vector<std::string> overrides;
    unsigned int             blas_threads = 0;
    std::string              json;
  };

  const char *const usage =
    "Usage: bench_glued SCENE.prm [--set Section/Entry=value ...] "
    "[--blas-threads N] [--json FILE]";

  Options
  parse_command_line(const int argc, char **argv)
  {
    Options options;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg       = argv[i];
        const bool        has_value = i + 1 < argc;
        if (arg == "--set" && has_value)
          options.overrides.emplace_back(argv[++i]);
        else if (arg == "--blas-threads" && has_value)
          options.blas_threads = std::stoul(argv[++i]);
        else if (arg == "--json" && has_value)
          options.json = argv[++i];
        else if (!arg.empty() && arg[0] != '-' &&
                 options.parameter_file.empty())
          options.parameter_file = arg;
        else
          throw std::invalid_argument("unexpected argument '" + arg + "'");
      }
    if (options.parameter_file.empty())
      throw std::invalid_argument("no parameter file");
    return options;
  }


  /// The scenes this driver handles: the rectangle, two layers of one
  /// degree, matching structured meshes, global refinement.
  void
  check_scene(const Scene &scene)
  {
    const auto refuse = [](const bool ok, const std::string &what) {
      if (!ok)
        throw std::invalid_argument(what);
    };
    refuse(scene.geometry.gmsh_file.empty() && scene.mesh.mesh_files.empty(),
           "only the rectangle scenes (Geometry/Gmsh file and Mesh/Mesh "
           "files empty)");
    refuse(scene.materials.n_layers == 2,
           "only two layers (Materials/Number of layers = 2)");
    refuse(scene.mesh.degree_first == scene.mesh.degree_second,
           "only one polynomial degree for both layers (Mesh/Polynomial "
           "degree of layer 1 = of layer 2)");
    refuse(
      scene.mesh.cells_along_sigma_plus == 0 ||
        scene.mesh.cells_along_sigma_plus == scene.mesh.cells_along_sigma,
      "only matching meshes (Mesh/Cells along Sigma on the plus side = 0)");
    refuse(scene.mesh.refinement == Refinement::global,
           "only global refinement (Mesh/Refinement = global)");
  }


  /// The prescribed displacements of both layers as one function of the
  /// four components (u1, u2, v1, v2).
  class BothLayers : public Function<2>
  {
  public:
    BothLayers(const Function<2> &first, const Function<2> &second)
      : Function<2>(4)
      , first(first)
      , second(second)
    {}

    double
    value(const Point<2> &p, const unsigned int component) const override
    {
      return component < 2 ? first.value(p, component) :
                             second.value(p, component - 2);
    }

  private:
    const Function<2> &first;
    const Function<2> &second;
  };


  double
  peak_resident_mib()
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    return memory.VmHWM / 1024.;
  }


  /// The glued problem: mesh, dofs, constraints, system, solution.
  class GluedProblem
  {
  public:
    explicit GluedProblem(const Scene &scene)
      : scene(scene)
      , law{{make_elastic_law(scene.materials.layer[0]),
             make_elastic_law(scene.materials.layer[1])}}
      , dofs(triangulation)
    {}

    /// The merged mesh of Omega, boundary ids of the rectangle's sides.
    void
    make_mesh()
    {
      Geometry geometry(scene.geometry, scene.mesh);
      geometry.create_meshes(scene.mesh.n_cycles - 1);
      GridGenerator::merge_triangulations(
        geometry.triangulation(Subdomain::minus),
        geometry.triangulation(Subdomain::plus),
        triangulation,
        1e-12 * width());
      const GeometryParameters &g = scene.geometry;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<2> c = face->center();
              face->set_boundary_id(near(c[0], g.x_min) ? BoundaryIds::left :
                                    near(c[0], g.x_max) ? BoundaryIds::right :
                                    near(c[1], g.y_min) ? BoundaryIds::bottom :
                                                          BoundaryIds::top);
            }
    }

    /// Dofs, constraints (hanging nodes, Gamma_D, v = u on Sigma),
    /// sparsity pattern, matrix and vectors.
    void
    set_up_system()
    {
      const unsigned int degree = scene.mesh.degree_first;
      if (triangulation.all_reference_cells_are_hyper_cube())
        fe = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 4);
      else
        fe = std::make_unique<FESystem<2>>(FE_SimplexP<2>(degree), 4);
      dofs.distribute_dofs(*fe);

      constraints.clear();
      DoFTools::make_hanging_node_constraints(dofs, constraints);
      const auto       first  = scene.loads.prescribed_function(Layer::first);
      const auto       second = scene.loads.prescribed_function(Layer::second);
      const BothLayers prescribed(*first, *second);
      for (unsigned int side = 0; side < scene.geometry.clamped.size(); ++side)
        if (scene.geometry.clamped[side])
          VectorTools::interpolate_boundary_values(
            mapping(), dofs, side, prescribed, constraints);

      // v = u at every dof on Sigma: on each face on Sigma, the dof of
      // component 2 + c (layer 2) equals the dof of component c (layer 1)
      // with the same base function, i.e. at the same support point.
      const unsigned int                       n = fe->n_dofs_per_cell();
      std::vector<std::array<unsigned int, 4>> by_base(
        fe->base_element(0).n_dofs_per_cell());
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto ci                = fe->system_to_component_index(i);
          by_base[ci.second][ci.first] = i;
        }
      std::vector<types::global_dof_index> local(n);
      for (const auto &cell : dofs.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (on_sigma(cell->face(f)))
            {
              cell->get_dof_indices(local);
              for (unsigned int k = 0; k < by_base.size(); ++k)
                if (fe->base_element(0).has_support_on_face(k, f))
                  for (unsigned int c = 0; c < 2; ++c)
                    {
                      const auto v = local[by_base[k][2 + c]];
                      const auto u = local[by_base[k][c]];
                      if (!constraints.is_constrained(v))
                        {
                          constraints.add_line(v);
                          constraints.add_entry(v, u, 1.);
                          ++n_glued;
                        }
                    }
            }
      constraints.close();

      DynamicSparsityPattern dsp(dofs.n_dofs());
      DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
      sparsity.copy_from(dsp);
      matrix.reinit(sparsity);
      rhs.reinit(dofs.n_dofs());
      solution.reinit(dofs.n_dofs());
    }

    /// The stiffness matrix of both layers and the traction load, with the
    /// constraints condensed.
    void
    assemble()
    {
      const auto                tractions = traction_functions();
      const unsigned int        n         = fe->n_dofs_per_cell();
      Integration               integration(mapping(), *fe);
      FEValues<2>              &fe_values      = integration.cell;
      FEFaceValues<2>          &fe_face_values = integration.face;
      std::vector<unsigned int> layer_of(n);
      for (unsigned int i = 0; i < n; ++i)
        layer_of[i] = fe->system_to_component_index(i).first / 2;
      std::vector<SymmetricTensor<2, 2>>   eps(n);
      FullMatrix<double>                   cell_matrix(n, n);
      Vector<double>                       cell_rhs(n);
      Vector<double>                       t(2);
      std::vector<types::global_dof_index> local(n);

      for (const auto &cell : dofs.active_cell_iterators())
        {
          cell_matrix = 0;
          cell_rhs    = 0;
          fe_values.reinit(cell);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < n; ++i)
                eps[i] =
                  fe_values[displacement[layer_of[i]]].symmetric_gradient(i, q);
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = i; j < n; ++j)
                  if (layer_of[i] == layer_of[j])
                    cell_matrix(i, j) +=
                      law[layer_of[i]]->bilinear_form(eps[i], eps[j]) * JxW;
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < i; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);

          for (const auto f : cell->face_indices())
            if (loaded(cell->face(f)))
              {
                const auto id = cell->face(f)->boundary_id();
                fe_face_values.reinit(cell, f);
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  for (unsigned int l = 0; l < 2; ++l)
                    {
                      tractions[l][id]->vector_value(
                        fe_face_values.quadrature_point(q), t);
                      const Tensor<1, 2> traction({t[0], t[1]});
                      for (unsigned int i = 0; i < n; ++i)
                        if (layer_of[i] == l)
                          cell_rhs(i) +=
                            fe_face_values[displacement[l]].value(i, q) *
                            traction * fe_face_values.JxW(q);
                    }
              }
          cell->get_dof_indices(local);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, local, matrix, rhs);
        }
    }

    void
    factorise()
    {
      cholesky.initialize(matrix, "the matrix of the glued problem");
    }

    void
    solve()
    {
      solution = rhs;
      cholesky.solve(solution);
      constraints.distribute(solution);
    }

    /// Pi(w) = a(w, w) / 2 - (F, w) of the solution, integrated cell by
    /// cell as the assembly does.
    double
    energy() const
    {
      const auto                         tractions = traction_functions();
      Integration                        integration(mapping(), *fe);
      FEValues<2>                       &fe_values      = integration.cell;
      FEFaceValues<2>                   &fe_face_values = integration.face;
      std::vector<SymmetricTensor<2, 2>> eps(integration.quadrature.size());
      std::vector<Tensor<1, 2>>          w(integration.face_quadrature.size());
      Vector<double>                     t(2);
      double                             pi = 0;
      for (const auto &cell : dofs.active_cell_iterators())
        {
          fe_values.reinit(cell);
          for (unsigned int l = 0; l < 2; ++l)
            {
              fe_values[displacement[l]].get_function_symmetric_gradients(
                solution, eps);
              for (const unsigned int q : fe_values.quadrature_point_indices())
                pi += 0.5 * law[l]->bilinear_form(eps[q], eps[q]) *
                      fe_values.JxW(q);
            }
          for (const auto f : cell->face_indices())
            if (loaded(cell->face(f)))
              {
                const auto id = cell->face(f)->boundary_id();
                fe_face_values.reinit(cell, f);
                for (unsigned int l = 0; l < 2; ++l)
                  {
                    fe_face_values[displacement[l]].get_function_values(
                      solution, w);
                    for (const unsigned int q :
                         fe_face_values.quadrature_point_indices())
                      {
                        tractions[l][id]->vector_value(
                          fe_face_values.quadrature_point(q), t);
                        pi -= (t[0] * w[q][0] + t[1] * w[q][1]) *
                              fe_face_values.JxW(q);
                      }
                  }
              }
        }
      return pi;
    }

    const Triangulation<2> &
    mesh() const
    {
      return triangulation;
    }
    types::global_dof_index
    n_dofs() const
    {
      return dofs.n_dofs();
    }
    unsigned int
    n_constraints() const
    {
      return constraints.n_constraints();
    }
    unsigned int
    n_glued_dofs() const
    {
      return n_glued;
    }
    std::size_t
    n_nonzeros() const
    {
      return sparsity.n_nonzero_elements();
    }

  private:
    /// The quadratures and the cell and face values of the assembly and of
    /// energy() (Gauss rules of degree + 1 points per direction).
    struct Integration
    {
      Integration(const Mapping<2> &mapping, const FiniteElement<2> &fe)
        : quadrature(
            fe.reference_cell().get_gauss_type_quadrature<2>(fe.degree + 1))
        , face_quadrature(
            ReferenceCells::Line.get_gauss_type_quadrature<1>(fe.degree + 1))
        , cell(mapping, fe, quadrature, update_gradients | update_JxW_values)
        , face(mapping,
               fe,
               face_quadrature,
               update_values | update_quadrature_points | update_JxW_values)
      {}

      const Quadrature<2> quadrature;
      const Quadrature<1> face_quadrature;
      FEValues<2>         cell;
      FEFaceValues<2>     face;
    };

    double
    width() const
    {
      return scene.geometry.x_max - scene.geometry.x_min;
    }

    bool
    near(const double a, const double b) const
    {
      return std::abs(a - b) < 1e-10 * width();
    }

    /// An interior face on Sigma (both end points at the height of Sigma).
    template <typename Face>
    bool
    on_sigma(const Face &face) const
    {
      return !face->at_boundary() &&
             near(face->vertex(0)[1], scene.geometry.sigma_height) &&
             near(face->vertex(1)[1], scene.geometry.sigma_height);
    }

    /// A face of Gamma_N: on the outer boundary, on a side not clamped.
    template <typename Face>
    bool
    loaded(const Face &face) const
    {
      return face->at_boundary() &&
             face->boundary_id() < scene.geometry.clamped.size() &&
             !scene.geometry.clamped[face->boundary_id()];
    }

    const Mapping<2> &
    mapping() const
    {
      return fe->reference_cell().get_default_linear_mapping<2>();
    }

    std::array<std::vector<std::unique_ptr<FunctionParser<2>>>, 2>
    traction_functions() const
    {
      std::array<std::vector<std::unique_ptr<FunctionParser<2>>>, 2> t;
      for (unsigned int l = 0; l < 2; ++l)
        for (unsigned int part = 0; part < scene.geometry.parts.size(); ++part)
          t[l].push_back(
            scene.loads.traction_function(static_cast<Layer>(l), part));
      return t;
    }

    const Scene                                            scene;
    const std::array<std::unique_ptr<const ElasticLaw>, 2> law;
    const std::array<FEValuesExtractors::Vector, 2>        displacement = {
             {FEValuesExtractors::Vector(0), FEValuesExtractors::Vector(2)}};
    Triangulation<2>             triangulation;
    std::unique_ptr<FESystem<2>> fe;
    DoFHandler<2>                dofs;
    AffineConstraints<double>    constraints;
    unsigned int                 n_glued = 0;
    SparsityPattern              sparsity;
    SparseMatrix<double>         matrix;
    Vector<double>               rhs;
    Vector<double>               solution;
    bilayer::SparseCholesky      cholesky;
  };


  std::string
  json_string(const std::string &s)
  {
    std::string out = "\"";
    for (const char c : s)
      if (c == '"' || c == '\\')
        out += std::string("\\") + c;
      else if (static_cast<unsigned char>(c) >= 0x20)
        out += c;
    return out + "\"";
  }
} // namespace


int
main(int argc, char **argv)
{
  deal_II_exceptions::disable_abort_on_exception();
  deal_II_exceptions::suppress_stacktrace_in_exceptions();
  Options options;
  Scene   scene;
  try
    {
      options = parse_command_line(argc, argv);
      ParameterHandler prm;
      scene = read_scene(prm, options.parameter_file, options.overrides);
      check_scene(scene);
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "bench_glued: error: " << one_line_message(e) << std::endl;
      return 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "bench_glued: error: " << e.what() << "\n"
                << usage << std::endl;
      return 1;
    }

  try
    {
      const unsigned int blas_threads =
        bilayer::set_blas_threads(options.blas_threads);
      Timer                                       total;
      Timer                                       timer;
      std::vector<std::pair<std::string, double>> seconds;
      const auto phase = [&](const std::string &name) {
        seconds.emplace_back(name, timer.wall_time());
        timer.restart();
      };

      GluedProblem problem(scene);
      problem.make_mesh();
      phase("mesh");
      problem.set_up_system();
      phase("dofs");
      problem.assemble();
      phase("assembly");
      problem.factorise();
      phase("factorisation");
      problem.solve();
      phase("solve");
      const double pi = problem.energy();
      phase("energy");
      seconds.emplace_back("total", total.wall_time());

      struct rusage usage_self;
      getrusage(RUSAGE_SELF, &usage_self);
      const double memory = peak_resident_mib();

      std::cout << "bench_glued: " << scene.name << ", "
                << problem.mesh().n_active_cells() << " cells, "
                << problem.n_dofs() << " dofs (" << problem.n_glued_dofs()
                << " glued v = u on Sigma, " << problem.n_constraints()
                << " constrained in all), " << problem.n_nonzeros()
                << " matrix entries, " << blas_threads << " BLAS thread(s) of "
                << bilayer::blas_library() << "\n";
      for (const auto &[name, s] : seconds)
        std::cout << "  " << std::left << std::setw(14) << name << std::fixed
                  << std::setprecision(3) << s << " s\n";
      std::cout << std::defaultfloat << std::setprecision(17)
                << "  energy Pi     " << pi << "\n"
                << std::setprecision(4) << "  peak memory   " << memory
                << " MiB" << std::endl;

      if (!options.json.empty())
        {
          std::ofstream out(options.json);
          out << std::setprecision(17)
              << "{\"scene\": " << json_string(scene.name)
              << ", \"cells\": " << problem.mesh().n_active_cells()
              << ", \"dofs\": " << problem.n_dofs()
              << ", \"glued_dofs\": " << problem.n_glued_dofs()
              << ", \"constraints\": " << problem.n_constraints()
              << ", \"matrix_entries\": " << problem.n_nonzeros()
              << ", \"blas_threads\": " << blas_threads
              << ", \"blas\": " << json_string(bilayer::blas_library())
              << ", \"energy\": " << pi << ", \"wall_seconds\": {";
          for (unsigned int i = 0; i < seconds.size(); ++i)
            out << (i ? ", " : "") << json_string(seconds[i].first) << ": "
                << seconds[i].second;
          out << "}, \"memory_mib\": " << memory
              << ", \"ru_maxrss_mib\": " << usage_self.ru_maxrss / 1024.
              << "}\n";
          if (!out)
            throw std::runtime_error("cannot write " + options.json);
        }
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "bench_glued: error: " << one_line_message(e) << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "bench_glued: error: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}
