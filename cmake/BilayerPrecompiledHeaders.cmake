# Precompiled deal.II headers (included by CMakeLists.txt).
#
# Parsing the deal.II headers is about 40 % of compiling a source of
# bilayer: the library's sources and the tests share one precompiled
# header of those most sources include. Headers only: a precompiled header
# changes no generated code. -DBILAYER_PRECOMPILED_HEADERS=OFF compiles
# without (ccache caches precompiled builds only with
# CCACHE_SLOPPINESS=pch_defines,time_macros).
#
#   bilayer_precompile_headers(TARGET)     TARGET makes the header
#   bilayer_reuse_precompiled_headers(FROM TARGETS...)  each of TARGETS
#       (same compiler flags as FROM) reuses FROM's

option(BILAYER_PRECOMPILED_HEADERS
  "precompile the deal.II headers the sources share" ON)

set(BILAYER_PRECOMPILED_HEADER_LIST
  <deal.II/base/exceptions.h>
  <deal.II/base/function_parser.h>
  <deal.II/base/parameter_handler.h>
  <deal.II/base/point.h>
  <deal.II/base/quadrature_lib.h>
  <deal.II/base/symmetric_tensor.h>
  <deal.II/base/timer.h>
  <deal.II/base/utilities.h>
  <deal.II/dofs/dof_handler.h>
  <deal.II/dofs/dof_tools.h>
  <deal.II/fe/fe_q.h>
  <deal.II/fe/fe_system.h>
  <deal.II/fe/fe_values.h>
  <deal.II/grid/grid_generator.h>
  <deal.II/grid/grid_tools.h>
  <deal.II/grid/tria.h>
  <deal.II/lac/affine_constraints.h>
  <deal.II/lac/block_vector.h>
  <deal.II/lac/dynamic_sparsity_pattern.h>
  <deal.II/lac/full_matrix.h>
  <deal.II/lac/sparse_matrix.h>
  <deal.II/lac/sparsity_pattern.h>
  <deal.II/lac/vector.h>
  <map>
  <memory>
  <string>
  <vector>)

function(bilayer_precompile_headers target)
  if(BILAYER_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE
      ${BILAYER_PRECOMPILED_HEADER_LIST})
  endif()
endfunction()

function(bilayer_reuse_precompiled_headers from)
  if(BILAYER_PRECOMPILED_HEADERS)
    foreach(_target ${ARGN})
      target_precompile_headers(${_target} REUSE_FROM ${from})
    endforeach()
  endif()
endfunction()
