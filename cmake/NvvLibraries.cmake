# The project's libraries, defined once for the main build (CMakeLists.txt) and for the MeshLab
# 2025.07 build (filter_normal_voting/meshlab/v2025/CMakeLists.txt):
#   nvv_core<SUFFIX>    the algorithm on a SurfaceGraph (filter_normal_voting/core): Eigen and
#                       OpenMP only; templates remain only where a vcglib mesh meets it
#   nvv_filter<SUFFIX>  the filter as users run it (filter_normal_voting/filter): the parameter
#                       table and the run sequence; its headers write onto vcglib meshes
#   nvv_mesh_io<SUFFIX> the mesh file readers (PLY, OBJ, OFF, STL) of filter_normal_voting/io:
#                       plain C++, no vcglib, no Qt
#
#   nvv_add_libraries(SUFFIX VCGLIB <dir> [COMPILE_OPTIONS ...] [LINK_OPTIONS ...])
# A second SUFFIX builds the same sources again with other options (the AddressSanitizer twin
# the tests link while the MeshLab plugin links the plain one).
get_filename_component(NVV_SOURCE_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
find_package(Eigen3 REQUIRED NO_MODULE)  # bookworm has 3.4, sid 5
find_package(OpenMP REQUIRED)

set(NVV_CORE_SOURCES
  crease_curvature.cpp crease_thinning.cpp curvature_votes.cpp geodesic_march.cpp normal_vector_voting.cpp
  crease_network.cpp locality_order.cpp noise_estimate.cpp normal_votes.cpp params.cpp ridge_fit.cpp sharp_edges.cpp sheet_fit.cpp surface_curvature.cpp
  surface_graph.cpp)
list(TRANSFORM NVV_CORE_SOURCES PREPEND "${NVV_SOURCE_ROOT}/filter_normal_voting/core/")
set(NVV_FILTER_SOURCES filter_options.cpp run_filter.cpp)
list(TRANSFORM NVV_FILTER_SOURCES PREPEND "${NVV_SOURCE_ROOT}/filter_normal_voting/filter/")
set(NVV_MESH_IO_SOURCES mesh_reader.cpp read_ply.cpp read_obj.cpp read_off.cpp read_stl.cpp)
list(TRANSFORM NVV_MESH_IO_SOURCES PREPEND "${NVV_SOURCE_ROOT}/filter_normal_voting/io/")

function(nvv_add_libraries suffix)
  cmake_parse_arguments(A "" "VCGLIB" "COMPILE_OPTIONS;LINK_OPTIONS" ${ARGN})
  if(NOT EXISTS "${A_VCGLIB}/vcg/complex/complex.h")
    message(FATAL_ERROR "nvv_add_libraries: VCGLIB '${A_VCGLIB}' is not a vcglib source tree")
  endif()
  set(core nvv_core${suffix})
  set(filter nvv_filter${suffix})
  set(io nvv_mesh_io${suffix})
  add_library(${core} STATIC ${NVV_CORE_SOURCES})
  # Headers are included as "core/x.h", "filter/x.h", "io/x.h" (and "x.h" within the core).
  target_include_directories(${core} PUBLIC "${NVV_SOURCE_ROOT}/filter_normal_voting" "${NVV_SOURCE_ROOT}")
  target_link_libraries(${core} PUBLIC Eigen3::Eigen OpenMP::OpenMP_CXX)
  add_library(${filter} STATIC ${NVV_FILTER_SOURCES})
  target_include_directories(${filter} SYSTEM PUBLIC "${A_VCGLIB}")
  target_link_libraries(${filter} PUBLIC ${core})
  add_library(${io} STATIC ${NVV_MESH_IO_SOURCES})
  target_include_directories(${io} PUBLIC "${NVV_SOURCE_ROOT}/filter_normal_voting")
  foreach(t ${core} ${filter} ${io})
    set_target_properties(${t} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${t} PRIVATE -Wall -Wextra ${A_COMPILE_OPTIONS})
    if(A_LINK_OPTIONS)
      target_link_options(${t} INTERFACE ${A_LINK_OPTIONS})
    endif()
  endforeach()
endfunction()
