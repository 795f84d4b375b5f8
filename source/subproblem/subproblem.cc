#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/core/similarity_breaker.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <set>

namespace bilayer
{

  namespace
  {
    /// The stiffness matrix of subproblem @p name as a refusal names it:
    /// where it is not positive definite, the law of the layer (@p entries)
    /// is singular or nearly so, or nothing holds the subproblem.
    std::string
    stiffness_matrix_named(const std::string &name, const std::string &entries)
    {
      return "the stiffness matrix of subproblem " + name + " (" + entries +
             ": a law that is singular or nearly so, or a side not held by "
             "Geometry/Clamped sides)";
    }
  } // namespace

  using namespace dealii;

  ElasticSubproblem::ElasticSubproblem(
    const Layer                       layer,
    const Subdomain                   subdomain,
    const Triangulation<2>           &triangulation,
    const unsigned int                degree,
    const std::vector<LayerMaterial> &materials,
    const PlyDivision                &plies,
    const Distribution               &distribution,
    const unsigned int                n_regions)
    : layer_(layer)
    , subdomain_(subdomain)
    , n_regions(n_regions)
    , laws_(materials, plies)
    , moduli_entries_(
        materials[0].law == MaterialLaw::orthotropic ? "E_1, E_2, E_3, G_12" :
        materials[0].law == MaterialLaw::anisotropic ? "Stiffness" :
                                                       "Young's modulus")
    , distribution(distribution)
    , dofs(triangulation)
  {
    if (materials.size() > 1)
      moduli_entries_ += " of each ply";
    if (triangulation.all_reference_cells_are_hyper_cube())
      fe_system = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 2);
    else
      fe_system = std::make_unique<FESystem<2>>(FE_SimplexP<2>(degree), 2);
    // Curved manifolds (circular boundaries or Sigma of a Gmsh scene): an
    // isoparametric mapping for elements of degree >= 2.
    bool curved = false;
    for (const types::manifold_id id : triangulation.get_manifold_ids())
      curved = curved || id != numbers::flat_manifold_id;
    if (curved && degree >= 2 &&
        triangulation.all_reference_cells_are_hyper_cube())
      curved_mapping = std::make_unique<MappingQ<2>>(degree);
  }


  const Mapping<2> &
  ElasticSubproblem::mapping() const
  {
    if (curved_mapping)
      return *curved_mapping;
    return fe_system->reference_cell().get_default_linear_mapping<2>();
  }


  std::string
  ElasticSubproblem::name() const
  {
    return Topology(n_regions).name(index());
  }


  namespace
  {
    /// False where the environment says BILAYER_ELEMENT_REUSE=off: every
    /// element matrix computed (for benchmarks: scripts/bench_fine_mesh
    /// --study setup).
    bool
    reuse_element_matrices()
    {
      static const bool on = [] {
        const char *value = std::getenv("BILAYER_ELEMENT_REUSE");
        return value == nullptr || std::string(value) != "off";
      }();
      return on;
    }


    /**
     * The element matrix and the load of one cell: the tractions on its
     * faces on Gamma_N and, with a VolumeLoad, the volume terms
     * f . z + sigma(eps*) : eps(z); with @p split also the proportional
     * part (tractions, f . z) and the preload (sigma(eps*) : eps(z)) apart.
     */
    class CellSystem
    {
    public:
      CellSystem(const FiniteElement<2>                 &fe,
                 const Mapping<2>                       &mapping,
                 const PlyLaws                          &laws,
                 const std::vector<bool>                &clamped,
                 const std::vector<const Function<2> *> &traction,
                 const VolumeLoad                       *volume,
                 const bool                              split = false)
        : fe(fe)
        , clamped(clamped)
        , traction(traction)
        , laws(laws)
        , volume(volume)
        , split(split)
        , fe_values(
            mapping,
            fe,
            fe.reference_cell().get_gauss_type_quadrature<2>(fe.degree + 1),
            update_gradients | update_JxW_values |
              (volume != nullptr ? update_values | update_quadrature_points :
                                   update_default))
        , fe_face_values(
            mapping,
            fe,
            ReferenceCells::Line.get_gauss_type_quadrature<1>(fe.degree + 1),
            update_values | update_quadrature_points | update_JxW_values)
        , fresh(fe.reference_cell())
        , eps(fe.n_dofs_per_cell())
        , t(2)
        , cell_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
        , cell_rhs(fe.n_dofs_per_cell())
        , cell_unit(fe.n_dofs_per_cell())
        , cell_preload(fe.n_dofs_per_cell())
        , local_dofs(fe.n_dofs_per_cell())
        , reuse(volume == nullptr &&
                &mapping ==
                  &fe.reference_cell().get_default_linear_mapping<2>() &&
                reuse_element_matrices())
      {
        if (!reuse)
          return;
        // The reference gradients of the linear mapping's shape functions
        // (one per vertex) and of the element's, at the quadrature points.
        const Quadrature<2> quadrature =
          fe.reference_cell().get_gauss_type_quadrature<2>(fe.degree + 1);
        const std::unique_ptr<FiniteElement<2>> geometry =
          fe.reference_cell().is_hyper_cube() ?
            std::unique_ptr<FiniteElement<2>>(new FE_Q<2>(1)) :
            std::unique_ptr<FiniteElement<2>>(new FE_SimplexP<2>(1));
        weights = quadrature.get_weights();
        for (const Point<2> &xi : quadrature.get_points())
          {
            std::vector<Tensor<1, 2>> g(geometry->n_dofs_per_cell()),
              phi(fe.n_dofs_per_cell());
            for (unsigned int k = 0; k < g.size(); ++k)
              g[k] = geometry->shape_grad(k, xi);
            for (unsigned int i = 0; i < phi.size(); ++i)
              phi[i] = fe.shape_grad(i, xi);
            vertex_gradients.push_back(g);
            shape_gradients.push_back(phi);
          }
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          components.push_back(fe.system_to_component_index(i).first);
      }

      /// Compute cell_matrix, cell_rhs and local_dofs of @p cell.
      void
      compute(const DoFHandler<2>::active_cell_iterator &cell)
      {
        cell_rhs     = 0;
        cell_unit    = 0;
        cell_preload = 0;
        if (reuse)
          {
            // The element matrix of a linear mapping is a function of the
            // law and the vertices' positions relative to the first one:
            // computed once per distinct shape.
            std::vector<std::int64_t> key = shape_of(cell);
            auto [entry, fresh_shape] =
              shapes.try_emplace(std::move(key), FullMatrix<double>());
            if (fresh_shape)
              {
                compute_stiffness_of_shape(laws.law(*cell), entry->first);
                entry->second = cell_matrix;
              }
            else
              cell_matrix = entry->second;
          }
        else
          compute_volume_terms(cell);
        compute_face_terms(cell);
        cell->get_dof_indices(local_dofs);
      }

      /// The number of distinct element matrices computed so far (with
      /// reuse) or 0 (without).
      std::size_t
      n_shapes() const
      {
        return shapes.size();
      }

    private:
      /**
       * The law of @p cell, an exponent e and its vertices relative to the
       * first one in units of 2^(e - 42), 2^e the power of two at or above
       * its first edge: cells equal up to a translation, and to 2^-42 of
       * their size (the round-off of coordinates made by subdivision or
       * read from a file), have one key.
       */
      std::vector<std::int64_t>
      shape_of(const DoFHandler<2>::active_cell_iterator &cell) const
      {
        const Point<2>     origin = cell->vertex(0);
        const std::int64_t exponent =
          std::ceil(std::log2((cell->vertex(1) - origin).norm()));
        const double              unit = std::exp2(exponent - 42);
        std::vector<std::int64_t> key{
          reinterpret_cast<std::intptr_t>(&laws.law(*cell)), exponent};
        for (unsigned int v = 1; v < cell->n_vertices(); ++v)
          for (unsigned int d = 0; d < 2; ++d)
            key.push_back(
              std::llround((cell->vertex(v)[d] - origin[d]) / unit));
        return key;
      }

      /**
       * The element matrix of the shape @p key of a cell of @p law (no
       * volume load, linear mapping): the vertices relative to the first
       * one as the key rounds them (exact multiples of a power of two), the
       * Jacobian J = sum_k (v_k - v_0) (grad N_k)^T of the mapping's shape
       * functions N_k. Every cell of one key gets these bits, whatever its
       * position and the last bits of its coordinates.
       */
      void
      compute_stiffness_of_shape(const ElasticLaw                &law,
                                 const std::vector<std::int64_t> &key)
      {
        const unsigned int n    = fe.n_dofs_per_cell();
        const double       unit = std::exp2(key[1] - 42);
        cell_matrix             = 0;
        for (unsigned int q = 0; q < weights.size(); ++q)
          {
            Tensor<2, 2> jacobian;
            for (unsigned int k = 1; k < vertex_gradients[q].size(); ++k)
              jacobian += outer_product(Tensor<1, 2>({key[2 * k] * unit,
                                                      key[2 * k + 1] * unit}),
                                        vertex_gradients[q][k]);
            const double       det               = determinant(jacobian);
            const Tensor<2, 2> inverse_transpose = transpose(invert(jacobian));
            for (unsigned int i = 0; i < n; ++i)
              {
                Tensor<2, 2> grad;
                grad[components[i]] = inverse_transpose * shape_gradients[q][i];
                eps[i]              = symmetrize(grad);
              }
            law.add_stiffness(eps, std::abs(det) * weights[q], cell_matrix);
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < i; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);
      }

      void
      compute_volume_terms(const DoFHandler<2>::active_cell_iterator &cell)
      {
        const unsigned int n = fe.n_dofs_per_cell();
        cell_matrix          = 0;
        fresh.apply(fe_values);
        fe_values.reinit(cell);
        const ElasticLaw &law = laws.law(*cell);
        const CellLoad    load =
          volume != nullptr ? volume->in(*cell) : CellLoad();
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            for (unsigned int i = 0; i < n; ++i)
              eps[i] = fe_values[displacement].symmetric_gradient(i, q);
            const double JxW = fe_values.JxW(q);
            law.add_stiffness(eps, JxW, cell_matrix);
            if (volume != nullptr)
              {
                const Point<2>             &x = fe_values.quadrature_point(q);
                const Tensor<1, 2>          f = load.body_force(x);
                const SymmetricTensor<2, 2> s = law.stress(load.eigenstrain(x));
                for (unsigned int i = 0; i < n; ++i)
                  cell_rhs(i) +=
                    (fe_values[displacement].value(i, q) * f + s * eps[i]) *
                    JxW;
                if (split)
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      cell_unit(i) +=
                        fe_values[displacement].value(i, q) * f * JxW;
                      cell_preload(i) += s * eps[i] * JxW;
                    }
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < i; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);
      }

      void
      compute_face_terms(const DoFHandler<2>::active_cell_iterator &cell)
      {
        const unsigned int n = fe.n_dofs_per_cell();
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() < clamped.size() &&
              !clamped[cell->face(f)->boundary_id()])
            {
              const Function<2> &load = *traction[cell->face(f)->boundary_id()];
              fe_face_values.reinit(cell, f);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                {
                  load.vector_value(fe_face_values.quadrature_point(q), t);
                  const Tensor<1, 2> traction_q({t[0], t[1]});
                  for (unsigned int i = 0; i < n; ++i)
                    cell_rhs(i) += fe_face_values[displacement].value(i, q) *
                                   traction_q * fe_face_values.JxW(q);
                  if (split)
                    for (unsigned int i = 0; i < n; ++i)
                      cell_unit(i) += fe_face_values[displacement].value(i, q) *
                                      traction_q * fe_face_values.JxW(q);
                }
            }
      }

      const FiniteElement<2>                 &fe;
      const std::vector<bool>                 clamped;
      const std::vector<const Function<2> *> &traction;
      const PlyLaws                          &laws;
      const VolumeLoad *const                 volume;
      const bool                              split;
      FEValues<2>                             fe_values;
      FEFaceValues<2>                         fe_face_values;
      const SimilarityBreaker                 fresh;
      const FEValuesExtractors::Vector        displacement{0};
      std::vector<SymmetricTensor<2, 2>>      eps;
      Vector<double>                          t;

    public:
      FullMatrix<double> cell_matrix;
      Vector<double>     cell_rhs;
      /// With split: cell_rhs apart into the proportional part (tractions,
      /// body force) and the preload (the eigenstrain terms).
      Vector<double>                       cell_unit, cell_preload;
      std::vector<types::global_dof_index> local_dofs;

    private:
      const bool                                              reuse;
      std::map<std::vector<std::int64_t>, FullMatrix<double>> shapes;
      /// With reuse: the quadrature weights, and at each point the
      /// reference gradients of the mapping's shape functions and of the
      /// element's (each with its component).
      std::vector<double>                    weights;
      std::vector<std::vector<Tensor<1, 2>>> vertex_gradients, shape_gradients;
      std::vector<unsigned int>              components;
    };
  } // namespace


  void
  ElasticSubproblem::setup(const std::vector<bool>                &clamped,
                           const Function<2>                      &prescribed,
                           const std::vector<const Function<2> *> &traction,
                           const std::string &shared_solver_type,
                           const bool         condense_on_sigma,
                           const VolumeLoad  *volume)
  {
    shared_solver = shared_solver_type;
    shared.reset();
    volume_             = volume;
    eigenstrain_energy_ = 0;
    Timer timer;
    dofs.distribute_dofs(*fe_system);

    make_constraints(clamped, prescribed);
    start_load_parts(volume);
    const IndexSet on_sigma =
      DoFTools::extract_boundary_dofs(dofs,
                                      ComponentMask(),
                                      BoundaryIds::interfaces());
    trace_dofs_.assign(on_sigma.begin(), on_sigma.end());
    extents.reinit(dofs);
    if (!owned())
      {
        assembly_seconds = timer.wall_time();
        return;
      }
    if (distribution.group_size(index()) > 1)
      shared = std::make_unique<DistributedSystem>(
        dofs, constraints, distribution.group_communicator(), shared_solver);
    else
      {
        DynamicSparsityPattern dsp(dofs.n_dofs());
        DoFTools::make_sparsity_pattern(dofs, dsp, constraints, true);
        sparsity.copy_from(dsp);
        system_matrix.reinit(sparsity);
        stiffness.reinit(sparsity);
        system_rhs.reinit(dofs.n_dofs());
        load_vector.reinit(dofs.n_dofs());
      }
    // (The load at load factor 1: a ScaledVolumeLoad's unit load.)
    assemble(clamped, traction, volume ? &volume->unit_load() : nullptr);
    keep_load_at_one();
    if (volume != nullptr && volume->has_eigenstrain())
      eigenstrain_energy_ = eigenstrain_energy();
    assembly_seconds = timer.wall_time();

    timer.restart();
    if (shared)
      shared->finish_assembly();
    else
      {
        // Moduli and cell sizes whose products leave the range of double
        // (E = 1e308, coordinates of 1e+-300) show here, not as a
        // divergence of the outer solver.
        const std::string layer_entry =
          "Materials/Layer " +
          std::to_string(static_cast<unsigned int>(layer()) + 1) + "/" +
          moduli_entries_;
        // Row sums, not only entries: the factorisation adds them up.
        AssertThrow(std::isfinite(system_matrix.linfty_norm()),
                    ExcMessage(
                      "the stiffness matrix of subproblem " + name() +
                      " has entries that are not finite: " + layer_entry +
                      " and the cell sizes (Geometry) leave the "
                      "range of double; state them in other units"));
        AssertThrow(std::isfinite(system_rhs.linfty_norm()) &&
                      std::isfinite(system_rhs.l1_norm()),
                    ExcMessage("the load vector of subproblem " + name() +
                               " has entries that are not finite: the "
                               "tractions or prescribed displacements "
                               "(Loads) and the side lengths (Geometry) "
                               "leave the range of double; state them in "
                               "other units"));
        const std::string what = stiffness_matrix_named(name(), layer_entry);
        const std::vector<unsigned int> last =
          condense_on_sigma ? schur_dofs() : std::vector<unsigned int>();
        if (last.empty())
          factorisation.initialize(system_matrix, what);
        else
          {
            AssertThrow(factorisation.try_initialize(system_matrix, last),
                        ExcMessage("the Cholesky factorisation of " + what +
                                   " failed: it is not positive definite"));
            if (condensed())
              {
                // Where each Sigma dof sits in the Schur complement.
                const std::vector<unsigned int> &order =
                  factorisation.schur_complement()->indices();
                std::vector<int> position(n_dofs(), -1);
                for (unsigned int a = 0; a < order.size(); ++a)
                  position[order[a]] = a;
                sigma_positions.clear();
                constrained_sigma_dofs.clear();
                for (const auto i : trace_dofs_)
                  if (!homogeneous_constraints.is_constrained(i))
                    sigma_positions.emplace_back(i, position[i]);
                  else
                    {
                      ConstrainedSigmaDof dof{i, {}};
                      for (const auto &[j, weight] :
                           *homogeneous_constraints.get_constraint_entries(i))
                        dof.entries.emplace_back(position[j], weight);
                      constrained_sigma_dofs.push_back(std::move(dof));
                    }
                solve(Vector<double>(), particular);
              }
          }
      }
    make_anchor_modes();
    factorisation_seconds = timer.wall_time();
    ++factorisations;
  }


  void
  ElasticSubproblem::make_constraints(const std::vector<bool> &clamped,
                                      const Function<2>       &prescribed)
  {
    constraints.clear();
    homogeneous_constraints.clear();
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    DoFTools::make_hanging_node_constraints(dofs, homogeneous_constraints);
    choose_anchors(clamped);
    const Functions::ZeroFunction<2> zero(2);
    for (unsigned int side = 0; side < clamped.size(); ++side)
      if (clamped[side])
        {
          VectorTools::interpolate_boundary_values(
            mapping(), dofs, side, prescribed, constraints);
          VectorTools::interpolate_boundary_values(
            mapping(), dofs, side, zero, homogeneous_constraints);
        }
    constraints.close();
    homogeneous_constraints.close();
  }


  std::vector<unsigned int>
  ElasticSubproblem::schur_dofs() const
  {
    std::vector<unsigned int> last;
    std::vector<bool>         on_sigma(n_dofs(), false);
    for (const auto i : trace_dofs_)
      if (!homogeneous_constraints.is_constrained(i))
        {
          last.push_back(i);
          on_sigma[i] = true;
        }
    for (const auto i : trace_dofs_)
      if (homogeneous_constraints.is_constrained(i))
        for (const auto &entry :
             *homogeneous_constraints.get_constraint_entries(i))
          if (!on_sigma[entry.first])
            return {};
    return last;
  }


  void
  ElasticSubproblem::assemble(const std::vector<bool>                &clamped,
                              const std::vector<const Function<2> *> &traction,
                              const VolumeLoad                       *volume)
  {
    const bool split = shared == nullptr && has_preload_;
    CellSystem system(
      *fe_system, mapping(), laws_, clamped, traction, volume, split);
    for (const auto &cell : dofs.active_cell_iterators())
      if (shared == nullptr)
        {
          system.compute(cell);
          constraints.distribute_local_to_global(system.cell_matrix,
                                                 system.cell_rhs,
                                                 system.local_dofs,
                                                 system_matrix,
                                                 system_rhs);
          stiffness.add(system.local_dofs, system.cell_matrix);
          load_vector.add(system.local_dofs, system.cell_rhs);
          if (split)
            {
              // The proportional part with the prescribed displacement's
              // terms, the preload with none.
              constraints.distribute_local_to_global(system.cell_unit,
                                                     system.local_dofs,
                                                     unit_rhs,
                                                     system.cell_matrix);
              homogeneous_constraints.distribute_local_to_global(
                system.cell_preload, system.local_dofs, preload_rhs);
              unit_load.add(system.local_dofs, system.cell_unit);
              preload_load.add(system.local_dofs, system.cell_preload);
            }
        }
      else if (shared->assembles(cell->active_cell_index()))
        {
          // The cells of this process's part of a shared subproblem.
          system.compute(cell);
          constraints.distribute_local_to_global(system.cell_matrix,
                                                 system.cell_rhs,
                                                 system.local_dofs,
                                                 shared->matrix,
                                                 shared->rhs);
          shared->stiffness.add(system.local_dofs, system.cell_matrix);
          shared->load.add(system.local_dofs, system.cell_rhs);
        }
  }


  std::unique_ptr<DistributedSystem>
  ElasticSubproblem::factorise_in_group(
    const AffineConstraints<double> &other_constraints) const
  {
    Assert(shared != nullptr, ExcInternalError());
    auto system =
      std::make_unique<DistributedSystem>(dofs,
                                          other_constraints,
                                          distribution.group_communicator(),
                                          shared_solver,
                                          shared.get());
    // No boundary part: no tractions.
    const std::vector<bool>                no_loads;
    const std::vector<const Function<2> *> none;
    CellSystem                             system_of_cell(
      *fe_system, mapping(), laws_, no_loads, none, nullptr);
    for (const auto &cell : dofs.active_cell_iterators())
      if (system->assembles(cell->active_cell_index()))
        {
          system_of_cell.compute(cell);
          other_constraints.distribute_local_to_global(
            system_of_cell.cell_matrix,
            system_of_cell.local_dofs,
            system->matrix);
        }
    system->finish_assembly();
    return system;
  }
} // namespace bilayer
