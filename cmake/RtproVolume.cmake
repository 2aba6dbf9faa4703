# volume: the data of grid media (voxel grids in bricks, majorant grids and the DDA through them)
# and OpenVDB files. OpenVDB is not linked into anything that links rtpro_volume: the one source
# that calls it (src/volume/openvdb_file.cpp) is built into librtpro_vdb.so, a plugin beside the
# executable that vdb_file.cpp loads when a scene first names a .vdb file. Linked, OpenVDB costs
# every process 90 ms and 31 MB before main() (src/volume/vdb_plugin_api.h). OpenVDB's headers
# pull in Boost, TBB and Imath and take tens of seconds to compile: openvdb_file.cpp is compiled
# on its own, outside the unity batches.
#
# Debian's libopenvdb-dev ships a FindOpenVDB.cmake that insists on Boost's CMake packages; its
# headers need only Boost's header-only parts (libboost-dev), so the library is found directly.
find_path(RTPRO_OPENVDB_INCLUDE openvdb/openvdb.h REQUIRED)
find_library(RTPRO_OPENVDB_LIBRARY openvdb REQUIRED)
find_path(RTPRO_BOOST_INCLUDE boost/any.hpp)
if(NOT RTPRO_BOOST_INCLUDE)
  message(FATAL_ERROR "OpenVDB's headers need Boost's headers: install libboost-dev (scripts/install-deps.sh)")
endif()
find_package(Imath CONFIG REQUIRED)
add_library(rtpro_openvdb INTERFACE)
target_include_directories(rtpro_openvdb SYSTEM INTERFACE ${RTPRO_OPENVDB_INCLUDE} ${RTPRO_BOOST_INCLUDE})
target_link_libraries(rtpro_openvdb INTERFACE ${RTPRO_OPENVDB_LIBRARY} Imath::Imath TBB::tbb)

set(vdb_plugin_sources openvdb_file.cpp vdb_plugin.cpp)
rtpro_add_module(volume DEPENDS core EXCLUDE ${vdb_plugin_sources})
set_target_properties(rtpro_volume PROPERTIES POSITION_INDEPENDENT_CODE ON)

# The plugin holds its own copies of rtpro_volume and rtpro_core; --exclude-libs keeps them local,
# so only the entry point is exported.
set(openvdb_file ${CMAKE_SOURCE_DIR}/src/volume/openvdb_file.cpp)
add_library(rtpro_vdb MODULE ${openvdb_file} ${CMAKE_SOURCE_DIR}/src/volume/vdb_plugin.cpp)
target_include_directories(rtpro_vdb PRIVATE ${CMAKE_SOURCE_DIR}/src/volume)
target_compile_definitions(rtpro_vdb PRIVATE RTPRO_VERSION="${PROJECT_VERSION}")
target_link_libraries(rtpro_vdb PRIVATE rtpro_volume rtpro_core rtpro_openvdb)
target_link_options(rtpro_vdb PRIVATE -Wl,--exclude-libs,ALL)
# Every symbol resolved inside the plugin, except in a sanitizer build: there the sanitizer
# runtimes live in the executable that loads it.
if(NOT RTPRO_SANITIZE)
  target_link_options(rtpro_vdb PRIVATE -Wl,--no-undefined)
endif()
set_target_properties(rtpro_vdb PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR} UNITY_BUILD OFF)
# oneTBB 2021's concurrent_hash_map, which OpenVDB's trees use for their accessor registry, casts
# its bucket sentinel (address 3) to a node pointer when a tree is cleared: UBSan's alignment check
# stops every test that reads a grid there, inside library headers. That one check is off for this
# one file (third_party_notes/openvdb.md); AddressSanitizer and the other checks stay on.
if(RTPRO_SANITIZE MATCHES "undefined")
  set_property(SOURCE ${openvdb_file} APPEND PROPERTY COMPILE_OPTIONS -fno-sanitize=alignment)
endif()
# The sanitizer build reads only the tests' small grids, and at -O0 clang compiles this file in a
# third of the time it takes at -O2 under instrumentation (42 s against 115 s on one core): the
# largest single step of CI's sanitizer build. The Release build keeps -O2: users' grids are large.
if(RTPRO_SANITIZE)
  set_property(SOURCE ${openvdb_file} APPEND PROPERTY COMPILE_OPTIONS -O0)
endif()

# Programs other than rtpro (tests, fuzz targets, benchmarks) live in folders of their own and
# find the plugin beside themselves as rtpro does: a link there to the one the build makes.
function(rtpro_link_vdb_plugin_into folder)
  file(MAKE_DIRECTORY ${folder})
  file(CREATE_LINK ${CMAKE_BINARY_DIR}/librtpro_vdb.so ${folder}/librtpro_vdb.so SYMBOLIC)
endfunction()
