# Which BLAS and LAPACK the factorisations use (included by CMakeLists.txt).
#
#   bilayer_runtime_blas(LIBRARY VAR)  the BLAS/LAPACK libraries that the
#       dynamic loader gives LIBRARY (ldd; without ldd, the libblas.so.3 and
#       liblapack.so.3 beside LIBRARY), their real paths (Debian's
#       libblas.so.3 is an alternatives link), each "PATH (KIND)": VAR is a
#       list of those strings, empty when none could be found
#   bilayer_blas_kind(PATH VAR)        OpenBLAS, MKL, BLIS, ATLAS, reference
#                                      BLAS/LAPACK, or unknown
#   bilayer_report_blas(CHOLMOD_LIBRARY)  the summary lines; a WARNING when
#       CHOLMOD gets the reference BLAS

function(bilayer_blas_kind path result_var)
  get_filename_component(_name "${path}" NAME)
  if(path MATCHES "openblas")
    set(_kind OpenBLAS)
  elseif(path MATCHES "mkl")
    set(_kind "Intel MKL")
  elseif(path MATCHES "blis")
    set(_kind BLIS)
  elseif(path MATCHES "atlas")
    set(_kind ATLAS)
  elseif(path MATCHES "/blas/libblas\\.")
    set(_kind "reference BLAS")
  elseif(path MATCHES "/lapack/liblapack\\.")
    set(_kind "reference LAPACK")
  else()
    set(_kind unknown)
  endif()
  set(${result_var} "${_kind}" PARENT_SCOPE)
endfunction()


function(bilayer_runtime_blas library result_var)
  set(_paths)
  find_program(BILAYER_LDD ldd)
  mark_as_advanced(BILAYER_LDD)
  if(BILAYER_LDD AND EXISTS "${library}")
    execute_process(COMMAND ${BILAYER_LDD} ${library}
      OUTPUT_VARIABLE _ldd RESULT_VARIABLE _rc ERROR_QUIET)
    if(_rc EQUAL 0)
      string(REGEX MATCHALL "[^\n]+" _lines "${_ldd}")
      foreach(_line ${_lines})
        if(_line MATCHES "^[ \t]*(lib(open)?blas|liblapack|libmkl_rt|libmkl_core|libblis)[^ ]* => ([^ ]+) ")
          list(APPEND _paths "${CMAKE_MATCH_3}")
        endif()
      endforeach()
    endif()
  endif()
  if(NOT _paths AND EXISTS "${library}")
    get_filename_component(_dir "${library}" DIRECTORY)
    foreach(_soname libblas.so.3 liblapack.so.3)
      if(EXISTS "${_dir}/${_soname}")
        list(APPEND _paths "${_dir}/${_soname}")
      endif()
    endforeach()
  endif()
  # libopenblas behind Debian's libblas.so.3/liblapack.so.3 is the same
  # library: named only when nothing else is.
  set(_others ${_paths})
  list(FILTER _others EXCLUDE REGEX "/libopenblas[^/]*$")
  if(_others)
    set(_paths ${_others})
  endif()
  set(_result)
  foreach(_path ${_paths})
    get_filename_component(_real "${_path}" REALPATH)
    bilayer_blas_kind("${_real}" _kind)
    list(APPEND _result "${_real} (${_kind})")
  endforeach()
  list(REMOVE_DUPLICATES _result)
  set(${result_var} "${_result}" PARENT_SCOPE)
endfunction()


function(bilayer_report_blas cholmod_library)
  # CHOLMOD's BLAS: the first BLAS the loader gives libcholmod (its own
  # libblas.so.3; a libopenblas behind it is the same BLAS).
  bilayer_runtime_blas("${cholmod_library}" _cholmod)
  set(_blas "")
  foreach(_entry ${_cholmod})
    if(_blas STREQUAL "" AND NOT _entry MATCHES "lapack")
      set(_blas "${_entry}")
    endif()
  endforeach()
  if(_blas STREQUAL "")
    message(STATUS "bilayer: BLAS used by CHOLMOD: unknown (no libblas found for ${cholmod_library})")
  else()
    message(STATUS "bilayer: BLAS used by CHOLMOD: ${_blas}")
    if(_blas MATCHES "\\(reference BLAS\\)$")
      string(REGEX REPLACE " \\(reference BLAS\\)$" "" _path "${_blas}")
      message(WARNING
        " bilayer: CHOLMOD gets the reference BLAS (${_path}): the Cholesky factorisations of the subproblems take about twice as long as with OpenBLAS on one thread (more with several threads); on Debian: apt-get install libopenblas0-pthread (libblas.so.3 then points at OpenBLAS through update-alternatives, no rebuild needed)")
    elseif(_blas MATCHES "\\(unknown\\)$")
      message(STATUS "bilayer: (a BLAS not recognised; with the reference BLAS the factorisations take about twice as long as with OpenBLAS, MKL or BLIS)")
    endif()
  endif()

  # deal.II's LAPACK (its LAPACKFullMatrix and the Trilinos/MUMPS solvers
  # behind it): what the configuration names, and what the loader gives
  # the deal.II library.
  set(_configured)
  foreach(_lib ${DEAL_II_LIBRARIES_RELEASE} ${DEAL_II_LIBRARIES})
    get_filename_component(_name "${_lib}" NAME)
    if(_name MATCHES "^lib(open)?blas|^liblapack|^libmkl|^libblis"
        AND NOT _name MATCHES "scalapack")
      list(APPEND _configured "${_name}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES _configured)
  set(_deal_ii_library "")
  foreach(_lib ${DEAL_II_LIBRARIES_RELEASE} ${DEAL_II_LIBRARIES})
    get_filename_component(_name "${_lib}" NAME)
    if(_deal_ii_library STREQUAL "" AND _name MATCHES "^libdeal[._]ii")
      set(_deal_ii_library "${_lib}")
    endif()
  endforeach()
  set(_loaded)
  if(_deal_ii_library)
    bilayer_runtime_blas("${_deal_ii_library}" _loaded)
  endif()
  if(NOT DEAL_II_WITH_LAPACK)
    set(_lapack "deal.II without LAPACK (DEAL_II_WITH_LAPACK=OFF)")
  else()
    set(_lapack "DEAL_II_WITH_LAPACK=ON")
    if(DEAL_II_LAPACK_WITH_MKL)
      string(APPEND _lapack ", MKL")
    endif()
  endif()
  string(REPLACE ";" ", " _configured "${_configured}")
  string(REPLACE ";" ", " _loaded "${_loaded}")
  if(_configured STREQUAL "")
    set(_configured "none named")
  endif()
  if(_loaded STREQUAL "")
    set(_loaded "unknown")
  endif()
  message(STATUS "bilayer: LAPACK/BLAS of deal.II (${_lapack}, links ${_configured}): ${_loaded}")
endfunction()
