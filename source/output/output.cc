#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/numerics/data_out.h>

#include <bilayer/core/tasks.h>
#include <bilayer/output/output.h>

#include <algorithm>
#include <array>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <tuple>

namespace bilayer
{
  using namespace dealii;

  StressPostprocessor::StressPostprocessor(const PlyLaws    &laws,
                                           const VolumeLoad *volume)
    : laws(laws)
    , eigenstrain(volume != nullptr && volume->has_eigenstrain() ? volume :
                                                                   nullptr)
  {}


  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    return {"von_mises", "stress_xx", "stress_yy", "stress_zz", "stress_xy"};
  }


  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return eigenstrain != nullptr ?
             update_gradients | update_quadrature_points :
             update_gradients;
  }


  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    // The cell's law; with plies, the eigenstrain of the cell's ply at a
    // point on a ply height (a vertex) too: read at the point moved towards
    // the cell's centre by 1e-9 of its diameter.
    // (One ply: no cell needed, the inputs may come without one.)
    const bool     plies = laws.size() > 1;
    const Point<2> center =
      plies ? inputs.template get_cell<2>()->center() : Point<2>();
    const ElasticLaw &law =
      plies ? laws.law(*inputs.template get_cell<2>()) : laws.law(0);
    // The eigenstrain of the cell's ply.
    const CellLoad load =
      eigenstrain == nullptr ? CellLoad() :
      plies                  ? eigenstrain->in(*inputs.template get_cell<2>()) :
                               CellLoad{eigenstrain, 1, 1};
    for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
      {
        const Point<2> x =
          eigenstrain == nullptr ? Point<2>() :
          plies                  ? inputs.evaluation_points[q] +
                    1e-9 * (center - inputs.evaluation_points[q]) :
                  inputs.evaluation_points[q];
        const auto           &grad = inputs.solution_gradients[q];
        SymmetricTensor<2, 2> strain;
        strain[0][0] = grad[0][0];
        strain[1][1] = grad[1][1];
        strain[0][1] = 0.5 * (grad[0][1] + grad[1][0]);
        if (eigenstrain != nullptr)
          strain -= load.eigenstrain(x);
        const SymmetricTensor<2, 2> stress = law.stress(strain);
        const double                szz =
          law.out_of_plane_stress(strain) +
          (eigenstrain != nullptr ? load.eigenstress_zz(x) : 0.);
        const double sxx = stress[0][0], syy = stress[1][1], sxy = stress[0][1];
        computed_quantities[q](0) = ElasticLaw::von_mises(stress, szz);
        computed_quantities[q](1) = sxx;
        computed_quantities[q](2) = syy;
        computed_quantities[q](3) = szz;
        computed_quantities[q](4) = sxy;
      }
  }


  namespace
  {
    /// Run @p writer on @p out and close it; a failure throws
    /// @p failed("cannot write").
    template <typename Failure>
    void
    write_and_close(std::ofstream                             &out,
                    const std::function<void(std::ostream &)> &writer,
                    const Failure                             &failed)
    {
      try
        {
          writer(out);
        }
      catch (const ExceptionBase &)
        {
          // deal.II's writers check the stream themselves (ExcIO).
          out.setstate(std::ios::badbit);
        }
      out.flush();
      AssertThrow(out, failed("cannot write"));
      out.close();
      AssertThrow(out, failed("cannot write"));
    }
  } // namespace


  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &writer)
  {
    const std::string temporary = path + ".part";
    const auto        failed    = [&](const std::string &what) {
      const std::string why = errno != 0 ? std::strerror(errno) : "unknown";
      std::error_code   error;
      std::filesystem::remove(temporary, error);
      return ExcMessage(what + " '" + path + "': " + why);
    };
    {
      errno = 0;
      std::ofstream out(temporary);
      AssertThrow(out, failed("cannot create"));
      write_and_close(out, writer, failed);
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    AssertThrow(!error,
                ExcMessage("cannot rename '" + temporary + "' to '" + path +
                           "': " + error.message()));
  }


  void
  append_to(const std::string                         &path,
            const std::function<void(std::ostream &)> &writer)
  {
    std::error_code   error;
    const auto        before = std::filesystem::exists(path, error) ?
                                 std::filesystem::file_size(path, error) :
                                 std::uintmax_t(0);
    const std::size_t kept   = error ? 0 : before;
    const auto        failed = [&](const std::string &what) {
      const std::string why = errno != 0 ? std::strerror(errno) : "unknown";
      // The file as it was before this call.
      std::error_code ignored;
      if (std::filesystem::exists(path, ignored))
        std::filesystem::resize_file(path, kept, ignored);
      return ExcMessage(what + " '" + path + "': " + why);
    };
    errno = 0;
    std::ofstream out(path, std::ios::app);
    AssertThrow(out, failed("cannot open"));
    write_and_close(out, writer, failed);
  }


  namespace
  {
    /// The XDMF file of all cycles: a temporal collection of spatial
    /// collections (one grid per piece).
    void
    write_xdmf(std::ostream &out, const SolutionRecords &records)
    {
      out << "<?xml version=\"1.0\" ?>\n"
             "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
             "<Xdmf Version=\"2.0\">\n"
             "  <Domain>\n"
             "    <Grid Name=\"cycles\" GridType=\"Collection\" "
             "CollectionType=\"Temporal\">\n";
      for (const auto &[cycle, grids] : records.xdmf)
        {
          out << "      <Grid Name=\"cycle-" << cycle
              << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
              << "        <Time Value=\"" << cycle << "\"/>\n";
          for (const auto &grid : grids)
            out << grid;
          out << "      </Grid>\n";
        }
      out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
    }


    /// The VTU flags of the compression level @p compression.
    DataOutBase::VtkFlags
    vtk_flags(const Compression compression)
    {
      DataOutBase::VtkFlags flags;
      flags.compression_level = compression == Compression::none ?
                                  DataOutBase::VtkFlags::no_compression :
                                compression == Compression::best_speed ?
                                  DataOutBase::VtkFlags::best_speed :
                                compression == Compression::standard ?
                                  DataOutBase::VtkFlags::default_compression :
                                  DataOutBase::VtkFlags::best_compression;
      return flags;
    }


    /// The DataOut objects of one cycle's pieces and what they refer to.
    struct SolutionPieces
    {
      /// The pieces of @p n subproblems.
      explicit SolutionPieces(const std::size_t n)
        : stresses(n)
        , data_outs(n)
        , layers(n)
        , subdomains(n)
        , regions(n)
        , plies(n)
        , piece_of(n)
        , simplex(n, false)
        , extra_values(n)
      {}

      // Declared before the DataOut objects that subscribe to them.
      PerSubproblem<std::unique_ptr<StressPostprocessor>> stresses;
      PerSubproblem<DataOut<2>>                           data_outs;
      PerSubproblem<Vector<float>> layers, subdomains, regions, plies;
      /// Whether some subproblem has plies: then every piece has the field
      /// ply (1 where its layer has one ply), so that the pieces agree.
      bool                       any_plies = false;
      PerSubproblem<std::string> piece_of;
      PerSubproblem<bool>        simplex;
      /// The further cell data (write_solution()) and their copies by
      /// subproblem.
      const CellFields                         *extra = nullptr;
      PerSubproblem<std::vector<Vector<float>>> extra_values;
    };


    /// The names of the pieces of the present subproblems (stored in
    /// @p piece_of without the process and the extension), one VTU file per
    /// process of the subproblem's group.
    std::vector<std::string>
    name_pieces(const std::string                              &stem,
                const PerSubproblem<const ElasticSubproblem *> &subproblems,
                const Distribution                             &processes,
                PerSubproblem<std::string>                     &piece_of)
    {
      std::vector<std::string> pieces;
      for (const unsigned int s : Layout::indices(subproblems.size()))
        if (subproblems[s] != nullptr)
          {
            const ElasticSubproblem &sub = *subproblems[s];
            // (-minus, -plus of Sigma's two regions, or -r1, -r2, ...)
            piece_of[s] = stem + "-" + Layout::layer_letter(sub.layer()) +
                          (sub.regions() != Layout::n_subdomains ?
                             "-r" + std::to_string(sub.region() + 1) :
                           sub.subdomain() == Subdomain::minus ? "-minus" :
                                                                 "-plus");
            // A subproblem shared by a group of processes is written in one
            // piece per process of the group (its cells of the partition).
            const unsigned int group_size = processes.group_size(s);
            for (unsigned int k = 0; k < group_size; ++k)
              pieces.push_back(piece_of[s] +
                               (group_size > 1 ? "." + std::to_string(k) : "") +
                               ".vtu");
          }
      return pieces;
    }


    /// The fields of subproblem @p s on its DataOut: displacement, the
    /// stresses, layer and subdomain.
    void
    add_fields(const ElasticSubproblem &sub,
               const unsigned int       s,
               const Vector<double>    &solution,
               SolutionPieces          &output)
    {
      DataOut<2>                    &data_out = output.data_outs[s];
      const std::vector<std::string> names(2, "displacement");
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          2, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(solution,
                               names,
                               DataOut<2>::type_dof_data,
                               interpretation);
      output.stresses[s] =
        std::make_unique<StressPostprocessor>(sub.laws(), sub.volume_load());
      data_out.add_data_vector(solution, *output.stresses[s]);

      const unsigned int n_cells =
        sub.dof_handler().get_triangulation().n_active_cells();
      output.layers[s].reinit(n_cells);
      output.subdomains[s].reinit(n_cells);
      output.layers[s] =
        static_cast<float>(static_cast<unsigned int>(sub.layer()) + 1);
      output.subdomains[s] = sub.subdomain() == Subdomain::minus ? -1.f : 1.f;
      data_out.add_data_vector(output.layers[s],
                               "layer",
                               DataOut<2>::type_cell_data);
      data_out.add_data_vector(output.subdomains[s],
                               "subdomain",
                               DataOut<2>::type_cell_data);
      // Several interfaces: the region 1, 2, ... (subdomain: -1 below
      // Sigma, +1 above).
      if (sub.regions() != Layout::n_subdomains)
        {
          output.regions[s].reinit(n_cells);
          output.regions[s] = static_cast<float>(sub.region() + 1);
          data_out.add_data_vector(output.regions[s],
                                   "region",
                                   DataOut<2>::type_cell_data);
        }
      // Plies: the ply 1, 2, ... of each cell (Materials/Layer k/Ply j).
      if (output.any_plies)
        {
          output.plies[s].reinit(n_cells);
          for (const auto &cell : sub.dof_handler().active_cell_iterators())
            output.plies[s][cell->active_cell_index()] =
              static_cast<float>(sub.laws().ply(*cell) + 1);
          data_out.add_data_vector(output.plies[s],
                                   "ply",
                                   DataOut<2>::type_cell_data);
        }
      if (output.extra != nullptr)
        {
          const CellFields &extra = *output.extra;
          output.extra_values[s].resize(extra.names.size());
          for (unsigned int k = 0; k < extra.names.size(); ++k)
            {
              Vector<float> &values = output.extra_values[s][k];
              values.reinit(n_cells);
              values = std::numeric_limits<float>::quiet_NaN();
              if (s < extra.values[k].size() &&
                  extra.values[k][s].size() == n_cells)
                for (unsigned int c = 0; c < n_cells; ++c)
                  values[c] = static_cast<float>(extra.values[k][s][c]);
              data_out.add_data_vector(values,
                                       extra.names[k],
                                       DataOut<2>::type_cell_data);
            }
        }
    }


    /// The patches of the piece of subproblem @p s (of this process's cells
    /// where the subproblem is distributed), and with @p write_vtu its VTU
    /// file.
    void
    build_piece(const ElasticSubproblem     &sub,
                const unsigned int           s,
                const Vector<double>        &solution,
                const DataOutBase::VtkFlags &flags,
                const Distribution          &processes,
                const std::string           &directory,
                const bool                   write_vtu,
                SolutionPieces              &output)
    {
      DataOut<2> &data_out = output.data_outs[s];
      data_out.attach_dof_handler(sub.dof_handler());
      data_out.set_flags(flags);
      add_fields(sub, s, solution, output);
      std::string vtu = output.piece_of[s] + ".vtu";
      if (sub.distributed())
        {
          const DistributedSystem &system = sub.distributed_system();
          data_out.set_cell_selection(
            FilteredIterator<DataOut<2>::cell_iterator>(
              [&system](const DataOut<2>::cell_iterator &cell) {
                return cell->is_active() &&
                       system.assembles(cell->active_cell_index());
              }));
          vtu = output.piece_of[s] + "." +
                std::to_string(Utilities::MPI::this_mpi_process(
                  processes.group_communicator())) +
                ".vtu";
        }

      output.simplex[s] = !sub.dof_handler()
                             .get_triangulation()
                             .all_reference_cells_are_hyper_cube();
      data_out.build_patches(sub.mapping(),
                             output.simplex[s] ? 1 : sub.fe().degree);

      if (write_vtu)
        write_atomically(directory + "/" + vtu,
                         [&](std::ostream &out) { data_out.write_vtu(out); });
    }


    /// The HDF5 files of the owned pieces (collective in a group; the
    /// library is not used from threads): the (subproblem, XDMF grid) of the
    /// pieces whose root is this process.
    std::vector<std::pair<unsigned int, std::string>>
    write_hdf5_pieces(
      const std::string                              &directory,
      const unsigned int                              cycle,
      const PerSubproblem<const ElasticSubproblem *> &subproblems,
      const Distribution                             &processes,
      SolutionPieces                                 &output)
    {
      std::vector<std::pair<unsigned int, std::string>> grids;
      for (const unsigned int s : Layout::indices(subproblems.size()))
        if (subproblems[s] != nullptr && subproblems[s]->owned())
          {
            const ElasticSubproblem   &sub      = *subproblems[s];
            DataOut<2>                &data_out = output.data_outs[s];
            const MPI_Comm             group    = sub.distributed() ?
                                                    processes.group_communicator() :
                                                    MPI_COMM_SELF;
            DataOutBase::DataOutFilter filter(
              DataOutBase::DataOutFilterFlags(true, true));
            data_out.write_filtered_data(filter);
            const std::string h5 = output.piece_of[s] + ".h5";
            data_out.write_hdf5_parallel(filter,
                                         directory + "/" + h5 + ".part",
                                         group);
            const XDMFEntry entry =
              data_out.create_xdmf_entry(filter, h5, cycle, group);
            if (processes.process() != processes.root(s))
              continue;
            std::error_code error;
            std::filesystem::rename(directory + "/" + h5 + ".part",
                                    directory + "/" + h5,
                                    error);
            AssertThrow(!error,
                        ExcMessage("cannot write '" + directory + "/" + h5 +
                                   "': " + error.message()));
            grids.emplace_back(
              s,
              entry.get_xdmf_content(4,
                                     output.simplex[s] ?
                                       ReferenceCells::Triangle :
                                       ReferenceCells::Quadrilateral));
          }
      return grids;
    }


    /// The grids of all processes at the first process, in the order of the
    /// subproblems.
    void
    gather_grids(const Distribution                                &processes,
                 std::vector<std::pair<unsigned int, std::string>> &grids)
    {
      const auto all =
        Utilities::MPI::gather(processes.communicator(), grids, 0);
      grids.clear();
      for (const auto &from_process : all)
        grids.insert(grids.end(), from_process.begin(), from_process.end());
      std::sort(grids.begin(), grids.end());
    }


    /// solution-NN.pvtu of the pieces @p pieces and solution.pvd over the
    /// cycles written so far.
    void
    write_vtu_records(const std::string              &directory,
                      const unsigned int              cycle,
                      const std::string              &stem,
                      const std::vector<std::string> &pieces,
                      const DataOut<2>               &first,
                      SolutionRecords                &records)
    {
      write_atomically(directory + "/" + stem + ".pvtu",
                       [&](std::ostream &out) {
                         first.write_pvtu_record(out, pieces);
                       });
      records.pvd.emplace_back(records.time_of(cycle), stem + ".pvtu");
      if (!records.deferred)
        write_atomically(directory + "/solution.pvd", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, records.pvd);
        });
    }


    /// The cycle's XDMF grids in @p records, and solution.xdmf.
    void
    write_xdmf_records(
      const std::string                                       &directory,
      const unsigned int                                       cycle,
      const std::vector<std::pair<unsigned int, std::string>> &grids,
      SolutionRecords                                         &records)
    {
      std::vector<std::string> content;
      for (const auto &grid : grids)
        content.push_back(grid.second);
      records.xdmf.emplace_back(cycle, content);
      if (!records.deferred)
        write_atomically(directory + "/solution.xdmf",
                         [&](std::ostream &out) { write_xdmf(out, records); });
    }
  } // namespace


  void
  write_solution(const std::string                              &directory,
                 const unsigned int                              cycle,
                 const PerSubproblem<const ElasticSubproblem *> &subproblems,
                 const Solutions                                &solutions,
                 const OutputParameters                         &parameters,
                 SolutionRecords                                &records,
                 const CellFields                               &extra)
  {
    const Distribution &processes = subproblems[0]->processes();
    AssertThrow(!parameters.write_hdf5 || Utilities::MPI::job_supports_mpi(),
                ExcMessage("Output/Write HDF5 needs MPI to be initialised "
                           "(the bilayer program does so)"));
    std::ostringstream stem;
    stem << "solution-" << std::setw(2) << std::setfill('0') << cycle;

    SolutionPieces output(subproblems.size());
    if (!extra.names.empty())
      output.extra = &extra;
    for (const ElasticSubproblem *sub : subproblems)
      output.any_plies =
        output.any_plies || (sub != nullptr && sub->laws().size() > 1);
    const DataOutBase::VtkFlags    flags = vtk_flags(parameters.compression);
    const std::vector<std::string> pieces =
      name_pieces(stem.str(), subproblems, processes, output.piece_of);

    // The patches of the pieces, and their VTU files, as parallel tasks.
    Tasks tasks;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        tasks.add([&, s]() {
          build_piece(*subproblems[s],
                      s,
                      solutions[s],
                      flags,
                      processes,
                      directory,
                      parameters.write_vtu,
                      output);
        });
    tasks.join_all();

    /// (subproblem, XDMF grid) of the pieces written here.
    std::vector<std::pair<unsigned int, std::string>> grids;
    if (parameters.write_hdf5)
      grids =
        write_hdf5_pieces(directory, cycle, subproblems, processes, output);
    if (parameters.write_hdf5 && processes.parallel())
      gather_grids(processes, grids);
    if (!processes.is_root())
      return;
    // The first process owns u- in every layout: its fields name those of
    // all pieces.
    if (parameters.write_vtu)
      write_vtu_records(
        directory, cycle, stem.str(), pieces, output.data_outs[0], records);
    if (parameters.write_hdf5)
      write_xdmf_records(directory, cycle, grids, records);
  }


  void
  write_collections(const std::string     &directory,
                    const SolutionRecords &records)
  {
    if (!records.pvd.empty())
      write_atomically(directory + "/solution.pvd", [&](std::ostream &out) {
        DataOutBase::write_pvd_record(out, records.pvd);
      });
    if (!records.xdmf.empty())
      write_atomically(directory + "/solution.xdmf",
                       [&](std::ostream &out) { write_xdmf(out, records); });
    for (const unsigned int i : Layout::indices(records.interface_pvd.size()))
      if (!records.interface_pvd[i].empty())
        write_atomically(
          directory + "/" + interface_stem(i) + ".pvd", [&](std::ostream &out) {
            DataOutBase::write_pvd_record(out, records.interface_pvd[i]);
          });
  }
} // namespace bilayer
