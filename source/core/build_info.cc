#include <deal.II/base/config.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/revision.h>

#include <bilayer/core/build_info.h>
// Generated at build time (cmake/BilayerGitCommit.cmake): BILAYER_GIT_COMMIT.
#include <bilayer/core/git_commit.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fstream>
#include <memory>
#include <string>

#ifndef BILAYER_VERSION
#  error \
    "BILAYER_VERSION is set by CMakeLists.txt (project(bilayer VERSION ...))"
#endif

namespace bilayer
{
  namespace
  {
    /// @p path with its symbolic links resolved (itself if that fails).
    std::string
    real_path(const std::string &path)
    {
      std::unique_ptr<char, decltype(&std::free)> resolved(
        realpath(path.c_str(), nullptr), &std::free);
      return resolved ? std::string(resolved.get()) : path;
    }


    /// The file name part of @p path.
    std::string
    base_name(const std::string &path)
    {
      const auto slash = path.rfind('/');
      return slash == std::string::npos ? path : path.substr(slash + 1);
    }


    /// Whether the file name of @p path looks like a BLAS library.
    bool
    is_blas_name(const std::string &path)
    {
      const std::string name = base_name(path);
      for (const char *prefix : {"libblas",
                                 "libopenblas",
                                 "libmkl_rt",
                                 "libmkl_core",
                                 "libblis",
                                 "libflexiblas"})
        if (name.rfind(prefix, 0) == 0 && name.find(".so") != std::string::npos)
          return true;
      return false;
    }


    /**
     * The BLAS of this process: the shared object that provides dgemm_ to
     * the global scope (what CHOLMOD and deal.II call), or failing that the
     * first BLAS-like object in /proc/self/maps. Holds a handle to it
     * (RTLD_NOLOAD: never loads anything) for looking up its functions.
     */
    class LoadedBlas
    {
    public:
      LoadedBlas()
      {
        Dl_info info;
        void   *dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
        if (dgemm != nullptr && dladdr(dgemm, &info) != 0 &&
            info.dli_fname != nullptr && info.dli_fname[0] != '\0')
          loaded_as = info.dli_fname;
        else
          {
            std::ifstream maps("/proc/self/maps");
            std::string   line;
            while (loaded_as.empty() && std::getline(maps, line))
              {
                const auto slash = line.find('/');
                if (slash != std::string::npos &&
                    is_blas_name(line.substr(slash)))
                  loaded_as = line.substr(slash);
              }
          }
        if (!loaded_as.empty())
          {
            path   = real_path(loaded_as);
            handle = dlopen(loaded_as.c_str(), RTLD_LAZY | RTLD_NOLOAD);
          }
      }

      ~LoadedBlas()
      {
        if (handle != nullptr)
          dlclose(handle);
      }

      LoadedBlas(const LoadedBlas &) = delete;
      LoadedBlas &
      operator=(const LoadedBlas &) = delete;

      /// The function @p name of this BLAS (or of a library it depends
      /// on, such as OpenBLAS behind Debian's libblas.so.3), or nullptr.
      template <typename Function>
      Function *
      function(const char *name) const
      {
        if (handle == nullptr)
          return nullptr;
        return reinterpret_cast<Function *>(dlsym(handle, name));
      }

      /// The real path of the library, empty when none was found.
      std::string path;

    private:
      std::string loaded_as;
      void       *handle = nullptr;
    };
  } // namespace


  std::string
  version()
  {
    return BILAYER_VERSION;
  }


  std::string
  git_commit()
  {
    return BILAYER_GIT_COMMIT;
  }


  std::string
  deal_ii_version()
  {
    const std::string shortrev = DEAL_II_GIT_SHORTREV;
    return std::string(DEAL_II_PACKAGE_VERSION) +
           (shortrev.empty() ? "" : " (git " + shortrev + ")");
  }


  std::string
  blas_library()
  {
    const LoadedBlas blas;
    if (blas.path.empty())
      return "unknown";
    const std::string where = " (" + blas.path + ")";

    if (const auto get_config = blas.function<char *()>("openblas_get_config"))
      if (const char *config = get_config())
        {
          const std::string text = config;
          return (text.rfind("OpenBLAS", 0) == 0 ? "" : "OpenBLAS ") + text +
                 where;
        }
    if (const auto get_version =
          blas.function<void(char *, int)>("MKL_Get_Version_String"))
      {
        char text[256] = {};
        get_version(text, sizeof(text) - 1);
        return std::string(text) + where;
      }
    if (const auto get_version =
          blas.function<const char *()>("bli_info_get_version_str"))
      return std::string("BLIS ") + get_version() + where;

    const std::string name = base_name(blas.path);
    if (blas.path.find("openblas") != std::string::npos)
      return "OpenBLAS" + where;
    if (blas.path.find("mkl") != std::string::npos)
      return "Intel MKL" + where;
    if (blas.path.find("atlas") != std::string::npos)
      return "ATLAS" + where;
    if (name.rfind("libflexiblas", 0) == 0)
      return "FlexiBLAS" + where;
    if (name.rfind("libblas", 0) == 0)
      return "reference BLAS" + where;
    return "BLAS" + where;
  }


  unsigned int
  set_blas_threads(const unsigned int n)
  {
    const LoadedBlas blas;

    // OpenBLAS
    const auto openblas_set =
      blas.function<void(int)>("openblas_set_num_threads");
    const auto openblas_get = blas.function<int()>("openblas_get_num_threads");
    if (openblas_set != nullptr && openblas_get != nullptr)
      {
        if (n > 0)
          openblas_set(static_cast<int>(n));
        return static_cast<unsigned int>(std::max(openblas_get(), 1));
      }

    // Intel MKL
    const auto mkl_set = blas.function<void(int)>("MKL_Set_Num_Threads");
    const auto mkl_get = blas.function<int()>("MKL_Get_Max_Threads");
    if (mkl_set != nullptr && mkl_get != nullptr)
      {
        if (n > 0)
          mkl_set(static_cast<int>(n));
        return static_cast<unsigned int>(std::max(mkl_get(), 1));
      }

    // BLIS (dim_t: a 64-bit integer in its usual builds)
    const auto blis_set =
      blas.function<void(std::int64_t)>("bli_thread_set_num_threads");
    const auto blis_get =
      blas.function<std::int64_t()>("bli_thread_get_num_threads");
    if (blis_set != nullptr && blis_get != nullptr)
      {
        if (n > 0)
          blis_set(n);
        const std::int64_t threads = blis_get();
        return threads >= 1 && threads < (1 << 20) ?
                 static_cast<unsigned int>(threads) :
                 1;
      }

    // The reference BLAS and unknown ones: one thread.
    return 1;
  }


  unsigned int
  blas_threads()
  {
    return set_blas_threads(0);
  }


  std::string
  blas_threads_variable()
  {
    const char *value = std::getenv("BILAYER_BLAS_THREADS");
    return value != nullptr && *value != '\0' ? "BILAYER_BLAS_THREADS" : "";
  }


  unsigned int
  fit_blas_threads(const unsigned int threads, const unsigned int tasks)
  {
    unsigned int n = std::max(1u, threads / std::max(1u, tasks));
    if (!blas_threads_variable().empty())
      {
        const char *value = std::getenv("BILAYER_BLAS_THREADS");
        char       *end   = nullptr;
        const long  asked = std::strtol(value, &end, 10);
        AssertThrow(*end == '\0' && asked >= 1 && asked <= 1024,
                    dealii::ExcMessage(
                      std::string("BILAYER_BLAS_THREADS must be a whole "
                                  "number from 1 to 1024, got '") +
                      value + "'"));
        n = static_cast<unsigned int>(asked);
      }
    const unsigned int in_effect = set_blas_threads(n);
    fit_factorisation_loops(in_effect);
    return in_effect;
  }


  namespace
  {
    /// OpenMP's omp_get_max_active_levels where an OpenMP library is
    /// loaded (CHOLMOD's libgomp), else nullptr.
    int (*openmp_get_levels())()
    {
      return reinterpret_cast<int (*)()>(
        dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
    }
  } // namespace


  void
  fit_factorisation_loops(const unsigned int blas_threads_per_call)
  {
    // OpenMP's max-active-levels is one setting of the process (libgomp
    // keeps it globally): 0 makes every parallel region a team of one.
    const auto get = openmp_get_levels();
    const auto set = reinterpret_cast<void (*)(int)>(
      dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
    if (get == nullptr || set == nullptr)
      return;
    static const int library_default = get();
    const char      *choice          = std::getenv("BILAYER_OPENMP_LOOPS");
    const bool       library =
      choice != nullptr && std::strcmp(choice, "library") == 0;
    set(blas_threads_per_call <= 1 && !library ? 0 : library_default);
  }


  bool
  factorisation_loops_serial()
  {
    const auto get = openmp_get_levels();
    return get != nullptr && get() == 0;
  }
} // namespace bilayer
