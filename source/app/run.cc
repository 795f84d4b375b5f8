#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <bilayer/app/check_geometry.h>
#include <bilayer/app/command_line.h>
#include <bilayer/app/run.h>
#include <bilayer/app/run_environment.h>
#include <bilayer/core/build_info.h>
#include <bilayer/drivers/resources.h>
#include <bilayer/drivers/study.h>
#include <bilayer/output/directory_anchor.h>
#include <bilayer/output/output.h>
#include <bilayer/output/output_directory.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/subproblem/distribution.h>

#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Print @p message as the one error line (on the first process).
    int
    refuse(const bool reporter, const std::string &message)
    {
      wait_if_stopping();
      if (reporter)
        std::cerr << "bilayer: error: " << unanchored(message) << std::endl;
      return ExitStatus::error;
    }


    /**
     * The command line and the scene it names, read and checked before
     * MPI_Init, which costs about a second for a job of one process:
     * refusals come at once. Under mpirun every process reads it alike and
     * the first one (@p reporter) reports. Returns the exit status where
     * nothing is to be run (--help, --version, --print-parameters, a
     * refusal).
     */
    std::optional<int>
    read_input(const int         argc,
               char            **argv,
               const bool        reporter,
               ParameterHandler &prm,
               Scene            &scene)
    {
      try
        {
          const CommandLine command = parse_command_line(argc, argv);
          if (command.action == CommandLine::Action::help)
            {
              if (reporter)
                print_usage(std::cout);
              return ExitStatus::success;
            }
          if (command.action == CommandLine::Action::version)
            {
              if (reporter)
                std::cout << "bilayer " << version() << " (git commit "
                          << git_commit() << ")\ndeal.II " << deal_ii_version()
                          << "\nBLAS " << blas_library() << std::endl;
              return ExitStatus::success;
            }
          if (command.action == CommandLine::Action::check_geometry)
            {
              check_geometry(command.geometry_file,
                             command.overrides,
                             command.allow_gmsh_commands,
                             std::cout);
              return ExitStatus::success;
            }
          if (command.action == CommandLine::Action::print_parameters &&
              command.parameter_file.empty())
            {
              Scene::declare_parameters(prm);
              if (reporter)
                prm.print_parameters(std::cout, ParameterHandler::PRM);
              return ExitStatus::success;
            }
          check_environment();
          scene = read_scene(prm,
                             command.parameter_file,
                             command.overrides,
                             command.allow_gmsh_commands);
          // Every entry as this run would use it (the file with its
          // includes, then the --set), as used_parameters.prm records it;
          // nothing is run or written.
          if (command.action == CommandLine::Action::print_parameters)
            {
              if (reporter)
                prm.print_parameters(std::cout, ParameterHandler::ShortPRM);
              return ExitStatus::success;
            }
        }
      catch (const ExceptionBase &e)
        {
          return refuse(reporter, one_line_message(e));
        }
      catch (const std::bad_alloc &)
        {
          return refuse(reporter, "out of memory while reading the parameters");
        }
      catch (const std::exception &e)
        {
          return refuse(reporter, e.what());
        }
      catch (...)
        {
          return refuse(reporter,
                        "the parameters could not be read (unknown error)");
        }
      return std::nullopt;
    }


    /// The files the run reads: the parameter file with its includes, the
    /// Gmsh scene, the mesh files of both sides.
    std::vector<std::string>
    input_files(const Scene &scene)
    {
      std::vector<std::string> inputs = scene.input_files;
      if (!scene.geometry.gmsh_file.empty())
        inputs.push_back(scene.geometry.gmsh_file);
      for (const auto &pattern : scene.mesh.mesh_files)
        for (const std::string side : {"minus", "plus"})
          {
            std::string file = pattern;
            const auto  at   = file.find("{side}");
            if (at != std::string::npos)
              file.replace(at, 6, side);
            inputs.push_back(file);
          }
      return inputs;
    }


    /**
     * The staging directory of the run (first process only) with
     * used_parameters.prm in it: every entry as used, after the versions
     * that used them. The files of all cycles must fit on the file system
     * (known in advance for structured meshes refined globally).
     */
    std::unique_ptr<StagedDirectory>
    stage_output(const Scene &scene, const ParameterHandler &prm)
    {
      auto   output = std::make_unique<StagedDirectory>(scene.output.directory,
                                                      input_files(scene));
      double files  = 0;
      for (unsigned int cycle = 0; cycle < scene.mesh.n_cycles; ++cycle)
        {
          const auto cells = structured_cells(scene, cycle);
          files += estimate_resources(scene, cells[0], cells[1]).output;
        }
      AssertThrow(files <= output->free_bytes(),
                  ExcMessage("Output/Output directory: the results of all "
                             "cycles need about " +
                             format_bytes(files) + ", but " +
                             format_bytes(output->free_bytes()) +
                             " are free on its file system: make room, "
                             "choose another directory or set Output/Write "
                             "VTU = false"));
      std::ostringstream used;
      used << "# bilayer " << version() << ", git commit " << git_commit()
           << ", deal.II " << deal_ii_version() << "\n# BLAS " << blas_library()
           << "\n";
      std::ostringstream entries;
      prm.print_parameters(entries, ParameterHandler::ShortPRM);
      used << applicable_entries(entries.str(), scene);
      write_atomically(output->staging() + "/used_parameters.prm",
                       [&](std::ostream &out) { out << used.str(); });
      return output;
    }


    /**
     * Results appear in the output directory only when the run is over: a
     * refused or failed run leaves an existing one as it was. The first
     * process prepares it (stage_output()) and tells the others whether it
     * could; on success @p problem is the staging directory, else the
     * message.
     */
    bool
    prepare_output(const Scene                      &scene,
                   const ParameterHandler           &prm,
                   const Distribution               &processes,
                   std::unique_ptr<StagedDirectory> &output,
                   std::string                      &problem)
    {
      bool ready = true;
      if (processes.is_root())
        try
          {
            output  = stage_output(scene, prm);
            problem = output->staging();
          }
        catch (const ExceptionBase &e)
          {
            output.reset();
            ready   = false;
            problem = one_line_message(e);
          }
        catch (const std::exception &e)
          {
            output.reset();
            ready   = false;
            problem = std::string("Output/Output directory: ") + e.what();
          }
      processes.broadcast(ready, problem);
      return ready;
    }


    /**
     * The staging directory as every process writes into it: anchored
     * (directory_anchor.h) to the directory the first process made, so that
     * no file of the run lands in a directory put in its place.
     */
    std::string
    anchor_staging(const Distribution                     &processes,
                   const std::unique_ptr<StagedDirectory> &output,
                   const std::string                      &staging)
    {
      bool        known = true;
      std::string id;
      if (processes.is_root())
        id = std::to_string(output->device_id()) + " " +
             std::to_string(output->inode_id());
      processes.broadcast(known, id);
      std::istringstream in(id);
      std::uintmax_t     device = 0, inode = 0;
      in >> device >> inode;
      std::string anchored, problem;
      try
        {
          anchored = anchor_directory(staging, device, inode);
        }
      catch (const ExceptionBase &e)
        {
          problem = "Output/Output directory: " + one_line_message(e);
        }
      problem = processes.first_error(problem);
      if (!problem.empty())
        throw CollectiveError(problem);
      return anchored;
    }


    /// The first line of a run: versions, processes, threads, the BLAS.
    void
    print_banner(const Distribution &processes, const unsigned int blas_threads)
    {
      const std::string variable = blas_threads_variable();
      std::cout << "bilayer " << version() << " (git commit " << git_commit()
                << "), deal.II " << deal_ii_version() << "; "
                << processes.n_processes() << " process"
                << (processes.n_processes() > 1 ? "es" : "") << " of "
                << MultithreadInfo::n_threads() << " thread"
                << (MultithreadInfo::n_threads() > 1 ? "s" : "")
                << " (the subproblems' tasks), " << blas_threads
                << " BLAS thread" << (blas_threads > 1 ? "s" : "")
                << " per call"
                << (variable.empty() ? "" : " (" + variable + ")")
                << (factorisation_loops_serial() ?
                      ", the factorisations' OpenMP loops in one thread" :
                      "")
                << "; BLAS " << blas_library() << std::endl;
    }


    /**
     * Run the study of @p scene (its output directory the staging
     * directory) and commit the results of @p output: into the directory
     * the user named (@p requested) if every cycle passed its checks, else
     * aside to DIR.failed. Returns the exit status.
     */
    int
    study_and_commit(const Scene                      &scene,
                     const Distribution               &processes,
                     std::unique_ptr<StagedDirectory> &output,
                     const std::string                &requested)
    {
      Study study(scene, std::cout, processes);
      // (On every process: the check is collective; the first verifies.)
      study.set_directory_check([&output]() {
        if (output)
          output->verify();
      });
      bool         passed = false;
      std::string  failure;
      unsigned int failed_cycle = 0;
      try
        {
          passed = scene.cohesive.active() ? study.run_cohesive() :
                   scene.fracture.growth == CrackGrowth::none ?
                                             study.run() :
                                             study.run_growth();
          if (!passed)
            {
              failed_cycle = study.records().back().cycle;
              failure      = study.records().back().failure();
            }
        }
      catch (const RunFailure &e)
        {
          failed_cycle = e.cycle;
          failure      = e.what();
        }
      catch (const std::bad_alloc &)
        {
          failed_cycle = study.records().size();
          failure =
            "out of memory (an allocation failed): use fewer cells or cycles";
        }
      if (!processes.is_root())
        return passed ? ExitStatus::success : ExitStatus::failed_checks;
      const std::string where = output->commit(passed);
      if (!passed)
        {
          std::cerr << "bilayer: "
                    << (scene.fracture.growth == CrackGrowth::none ? "cycle " :
                                                                     "step ")
                    << failed_cycle << " FAILED: " << unanchored(failure)
                    << " (its results are in " << where << ")" << std::endl;
          return ExitStatus::failed_checks;
        }
      std::cout << "bilayer: results are in " << requested << std::endl;
      return ExitStatus::success;
    }


    /**
     * The run of a scene that has been read: MPI, the threads, the
     * resources, the output directory and the study.
     */
    int
    run_scene(int               argc,
              char            **argv,
              const bool        reporter,
              ParameterHandler &prm,
              Scene            &scene)
    {
      // Under mpirun the processes share the subproblems (bilayer::
      // Distribution); without it this is a job of one process. Threads:
      // the cores of the node divided among its processes.
      start_mpi_alone_quickly();
      Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
      // PETSc, initialised with MPI, turns SIGHUP, SIGINT and SIGTERM into
      // an error report and MPI_Abort: a stopped run removes what it staged
      // and its lock, says so in one line and ends by its signal instead.
      watch_stop_signals(reporter);
      const Distribution &processes = Distribution::world();
      // The subproblems are factorised and solved as parallel tasks,
      // each calling the BLAS: a threaded BLAS gets this process's threads
      // divided among them (one each on a machine with fewer than eight
      // cores), so that the two kinds of threads do not compete for the
      // cores (docs/performance.md measures the choices;
      // BILAYER_BLAS_THREADS overrides the count, OPENBLAS_NUM_THREADS and
      // its kin do not).
      unsigned int blas_threads = 1;
      try
        {
          blas_threads = fit_blas_threads(MultithreadInfo::n_threads(),
                                          Topology(scene.geometry.n_regions(),
                                                   scene.materials.n_layers)
                                            .n_subproblems());
        }
      catch (const ExceptionBase &e)
        {
          return refuse(reporter, one_line_message(e));
        }

      // The memory each process sees may differ a little: the processes
      // decide together whether the scene fits.
      {
        std::string too_large;
        try
          {
            check_scene_resources(scene, processes.n_processes());
          }
        catch (const ExceptionBase &e)
          {
            too_large = one_line_message(e);
          }
        too_large = processes.first_error(too_large);
        if (!too_large.empty())
          return refuse(reporter, too_large);
      }

      std::unique_ptr<StagedDirectory> output;
      try
        {
          std::string staging;
          if (!prepare_output(scene, prm, processes, output, staging))
            return refuse(reporter, staging);
          // (As the user wrote it, for the last line of a successful run.)
          const std::string requested = scene.output.directory;
          scene.output.directory = anchor_staging(processes, output, staging);
          if (processes.is_root() &&
              scene.output.terminal == TerminalOutput::full)
            print_banner(processes, blas_threads);
          return study_and_commit(scene, processes, output, requested);
        }
      catch (const CollectiveError &e)
        {
          // Every process knows: the first reports, none aborts, and the
          // staging directory goes with `output`.
          return refuse(reporter, e.what());
        }
      catch (const ExceptionBase &e)
        {
          wait_if_stopping();
          std::cerr << "bilayer: error: " << unanchored(one_line_message(e))
                    << std::endl;
        }
      catch (const std::bad_alloc &)
        {
          wait_if_stopping();
          std::cerr << "bilayer: error: out of memory (an allocation failed)"
                    << std::endl;
        }
      catch (const std::exception &e)
        {
          wait_if_stopping();
          std::cerr << "bilayer: error: " << unanchored(e.what()) << std::endl;
        }
      catch (...)
        {
          wait_if_stopping();
          std::cerr << "bilayer: error: unknown error" << std::endl;
        }
      // An error on one process would leave the others waiting; the
      // staging directory goes first.
      output.reset();
      if (processes.parallel())
        MPI_Abort(processes.communicator(), 1);
      return ExitStatus::error;
    }
  } // namespace


  int
  run_program(int argc, char **argv)
  {
    open_closed_standard_streams();
    TolerantOutput standard_output;
    prepare_stop_signals();
    deal_II_exceptions::disable_abort_on_exception();
    deal_II_exceptions::suppress_stacktrace_in_exceptions();
    const bool       reporter = launch_rank() == 0;
    Scene            scene;
    ParameterHandler prm;
    if (const auto status = read_input(argc, argv, reporter, prm, scene))
      return *status;
    return run_scene(argc, argv, reporter, prm, scene);
  }
} // namespace bilayer
