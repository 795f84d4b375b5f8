# Finding and checking deal.II for bilayer (included by CMakeLists.txt; the
# functions are also called by tests/cli/cmake_checks.sh through fake
# deal.II configurations).
#
#   bilayer_find_deal_ii()            find_package(deal.II) the usual way:
#                                     -DDEAL_II_DIR=, -Ddeal.II_DIR=,
#                                     DEAL_II_DIR in the environment,
#                                     CMAKE_PREFIX_PATH, the system prefixes
#   bilayer_check_deal_ii_version()   deal.II >= BILAYER_DEAL_II_MINIMUM
#   bilayer_check_deal_ii_features()  every DEAL_II_WITH_* the code uses:
#                                     one line per missing feature, then one
#                                     FATAL_ERROR
#   bilayer_check_amesos_mumps(VAR)   MUMPS in deal.II's Trilinos (Amesos):
#                                     VAR = yes, no or unknown; a WARNING
#                                     when it is absent
#
# Every message starts with "bilayer: " and is one line.

set(BILAYER_DEAL_II_MINIMUM 9.4.0)

# How to get deal.II at all (the end of several messages).
set(_bilayer_get_deal_ii
  "point -DDEAL_II_DIR=/path at a deal.II ${BILAYER_DEAL_II_MINIMUM} or newer (its installation prefix or build directory), or use Debian's: apt-get install libdeal.ii-dev, with DEAL_II_DIR unset")

# The deal.II features the code uses (grep '#include <deal.II' source
# include): DEAL_II_WITH_<FEATURE>, what needs it, how to get it.
set(BILAYER_DEAL_II_FEATURES CXX17 MPI TRILINOS METIS HDF5 MUPARSER)
set(_bilayer_why_CXX17
  "the code is C++17 (std::filesystem, std::optional, std::variant)")
set(_bilayer_how_CXX17
  "configure deal.II with a C++17 compiler (GCC >= 9, Clang >= 9) or -DCMAKE_CXX_FLAGS=-std=c++17")
set(_bilayer_why_MPI
  "the MPI processes (mpirun) and Utilities::MPI")
set(_bilayer_how_MPI
  "configure deal.II with -DDEAL_II_WITH_MPI=ON and an MPI library (Debian: libopenmpi-dev)")
set(_bilayer_why_TRILINOS
  "the subproblems shared by several processes (TrilinosWrappers matrices and vectors, Amesos direct solvers)")
set(_bilayer_how_TRILINOS
  "configure deal.II with -DDEAL_II_WITH_TRILINOS=ON -DTRILINOS_DIR=/path (Trilinos with Epetra and Amesos; Debian: libtrilinos-amesos-dev and the libtrilinos-*-dev it needs)")
set(_bilayer_why_METIS
  "the partition of a shared subproblem's mesh (GridTools::partition_triangulation with METIS)")
set(_bilayer_how_METIS
  "configure deal.II with -DDEAL_II_WITH_METIS=ON -DMETIS_DIR=/path (METIS 5; Debian: libmetis-dev)")
set(_bilayer_why_HDF5
  "Output/Write HDF5 (DataOut::write_hdf5_parallel)")
set(_bilayer_how_HDF5
  "configure deal.II with -DDEAL_II_WITH_HDF5=ON -DHDF5_DIR=/path (an MPI-parallel HDF5; Debian: libhdf5-openmpi-dev)")
set(_bilayer_why_MUPARSER
  "the functions of parameter files (FunctionParser)")
set(_bilayer_how_MUPARSER
  "configure deal.II with -DDEAL_II_WITH_MUPARSER=ON -DMUPARSER_DIR=/path (Debian: libmuparser-dev)")


macro(bilayer_find_deal_ii)
  # -Ddeal.II_DIR= names the folder of deal.IIConfig.cmake itself; CMake
  # would search elsewhere if it is wrong.
  if(deal.II_DIR AND NOT EXISTS "${deal.II_DIR}/deal.IIConfig.cmake"
      AND NOT EXISTS "${deal.II_DIR}/deal.ii-config.cmake")
    message(FATAL_ERROR
      " bilayer: no deal.II at deal.II_DIR=${deal.II_DIR} (no deal.IIConfig.cmake there; deal.II_DIR is the folder of deal.IIConfig.cmake, e.g. PREFIX/lib/cmake/deal.II): ${_bilayer_get_deal_ii}")
  endif()
  # An explicit location (-DDEAL_II_DIR= or DEAL_II_DIR in the environment)
  # is the only place searched: a wrong one is reported, not silently
  # replaced by another deal.II found elsewhere.
  set(_bilayer_hints)
  foreach(_bilayer_hint "${DEAL_II_DIR}" "$ENV{DEAL_II_DIR}")
    if(NOT "${_bilayer_hint}" STREQUAL "")
      list(APPEND _bilayer_hints "${_bilayer_hint}")
    endif()
  endforeach()
  if(_bilayer_hints)
    # A new location: forget the deal.II found before.
    if(NOT "${_bilayer_hints}" STREQUAL "${BILAYER_DEAL_II_HINTS}")
      unset(deal.II_DIR CACHE)
    endif()
    set(BILAYER_DEAL_II_HINTS "${_bilayer_hints}" CACHE INTERNAL
      "DEAL_II_DIR of the last configuration")
    find_package(deal.II QUIET HINTS ${_bilayer_hints} NO_DEFAULT_PATH)
  else()
    find_package(deal.II QUIET)
  endif()

  if(NOT deal.II_FOUND OR NOT DEFINED DEAL_II_PACKAGE_VERSION)
    if(_bilayer_hints)
      string(REPLACE ";" ", " _bilayer_hints "${_bilayer_hints}")
      message(FATAL_ERROR
        " bilayer: no deal.II at DEAL_II_DIR=${_bilayer_hints} (no deal.IIConfig.cmake there or in its lib/cmake/deal.II or share/cmake/deal.II): ${_bilayer_get_deal_ii}")
    else()
      message(FATAL_ERROR
        " bilayer: no deal.II found (searched CMAKE_PREFIX_PATH and the system prefixes): ${_bilayer_get_deal_ii}")
    endif()
  endif()
endmacro()


function(bilayer_check_deal_ii_version)
  if(DEAL_II_PACKAGE_VERSION VERSION_LESS BILAYER_DEAL_II_MINIMUM)
    message(FATAL_ERROR
      " bilayer: found deal.II ${DEAL_II_PACKAGE_VERSION} at ${DEAL_II_PATH}, bilayer needs ${BILAYER_DEAL_II_MINIMUM} or newer: point -DDEAL_II_DIR=/path at a newer one (its installation prefix or build directory), or use Debian's (Debian 12: 9.4.1): apt-get install libdeal.ii-dev, with DEAL_II_DIR unset")
  endif()
endfunction()


function(bilayer_check_deal_ii_features)
  set(_missing)
  # deal.II 9.5 and newer require C++17 and may not set DEAL_II_WITH_CXX17.
  if(NOT DEFINED DEAL_II_WITH_CXX17
      AND DEAL_II_PACKAGE_VERSION VERSION_GREATER_EQUAL 9.5)
    set(DEAL_II_WITH_CXX17 ON)
  endif()
  foreach(_feature ${BILAYER_DEAL_II_FEATURES})
    if(NOT DEAL_II_WITH_${_feature})
      list(APPEND _missing ${_feature})
      message("bilayer: deal.II lacks DEAL_II_WITH_${_feature} (OFF), "
        "needed for ${_bilayer_why_${_feature}}: ${_bilayer_how_${_feature}}")
    endif()
  endforeach()
  if(_missing)
    list(LENGTH _missing _n)
    string(REPLACE ";" ", " _missing "${_missing}")
    message(FATAL_ERROR
      " bilayer: the deal.II ${DEAL_II_PACKAGE_VERSION} at ${DEAL_II_PATH} lacks ${_n} feature(s) that bilayer needs (each named above): ${_missing}; rebuild it with them, or ${_bilayer_get_deal_ii}")
  endif()

  # Only some tests need UMFPACK: a warning.
  if(NOT DEAL_II_WITH_UMFPACK)
    message(WARNING
      " bilayer: deal.II lacks DEAL_II_WITH_UMFPACK: the tests contact_reference, glued_direct and prm_references (SparseDirectUMFPACK) will fail; the program itself does not need it (configure deal.II with -DDEAL_II_WITH_UMFPACK=ON, Debian: libsuitesparse-dev)")
  endif()
endfunction()


# MUMPS in the Trilinos of deal.II, which the default
# "Solver/Shared subproblem solver = mumps" (Amesos_Mumps) needs when a
# subproblem is shared by a group of processes (more than 4 processes).
# Amesos_config.h (HAVE_AMESOS_MUMPS) says it; failing that, deal.II's
# DEAL_II_TRILINOS_WITH_MUMPS.
function(bilayer_check_amesos_mumps result_var)
  set(_result unknown)
  set(_where "")
  foreach(_dir ${DEAL_II_INCLUDE_DIRS} ${DEAL_II_TRILINOS_INCLUDE_DIRS})
    foreach(_file "${_dir}/Amesos_config.h" "${_dir}/trilinos/Amesos_config.h")
      if(_result STREQUAL "unknown" AND EXISTS "${_file}")
        file(STRINGS "${_file}" _define REGEX "^#[ \t]*define[ \t]+HAVE_AMESOS_MUMPS")
        if(_define)
          set(_result yes)
        else()
          set(_result no)
        endif()
        set(_where " (${_file})")
      endif()
    endforeach()
  endforeach()
  if(_result STREQUAL "unknown" AND DEFINED DEAL_II_TRILINOS_WITH_MUMPS)
    if(DEAL_II_TRILINOS_WITH_MUMPS)
      set(_result yes)
    else()
      set(_result no)
    endif()
    set(_where " (DEAL_II_TRILINOS_WITH_MUMPS)")
  endif()
  if(_result STREQUAL "no")
    message(WARNING
      " bilayer: deal.II's Trilinos has no MUMPS (Amesos_Mumps)${_where}: runs with more than 4 MPI processes and 'Solver/Shared subproblem solver = mumps' (the default) will stop with an error; set 'Shared subproblem solver = klu' for them, or use a Trilinos built with MUMPS (-DTPL_ENABLE_MUMPS=ON; Debian's libtrilinos-amesos-dev has it)")
  elseif(_result STREQUAL "unknown")
    message(STATUS
      "bilayer: could not tell whether deal.II's Trilinos has MUMPS (no Amesos_config.h in DEAL_II_INCLUDE_DIRS); without it, 'Solver/Shared subproblem solver = mumps' with more than 4 MPI processes stops with an error (klu works)")
  endif()
  set(${result_var} ${_result} PARENT_SCOPE)
endfunction()
