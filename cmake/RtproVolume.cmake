# volume: the data of grid media (voxel grids in bricks, majorant grids and the DDA through them)
# and the one source that reads OpenVDB files. OpenVDB's headers pull in Boost, TBB and Imath and
# take tens of seconds to compile: only src/volume/vdb_file.cpp includes them, compiled on its own
# (outside the unity batches), and the library links OpenVDB privately.
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

rtpro_add_module(volume DEPENDS core PRIVATE_DEPENDS rtpro_openvdb)
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/volume/vdb_file.cpp PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
# oneTBB 2021's concurrent_hash_map, which OpenVDB's trees use for their accessor registry, casts
# its bucket sentinel (address 3) to a node pointer when a tree is cleared: UBSan's alignment check
# stops every test that reads a grid there, inside library headers. That one check is off for this
# one file (third_party_notes/openvdb.md); AddressSanitizer and the other checks stay on.
if(RTPRO_SANITIZE MATCHES "undefined")
  set_property(SOURCE ${CMAKE_SOURCE_DIR}/src/volume/vdb_file.cpp APPEND PROPERTY COMPILE_OPTIONS -fno-sanitize=alignment)
endif()
# The sanitizer build reads only the tests' small grids, and at -O0 clang compiles this file in a
# third of the time it takes at -O2 under instrumentation (42 s against 115 s on one core): the
# largest single step of CI's sanitizer build. The Release build keeps -O2: users' grids are large.
if(RTPRO_SANITIZE)
  set_property(SOURCE ${CMAKE_SOURCE_DIR}/src/volume/vdb_file.cpp APPEND PROPERTY COMPILE_OPTIONS -O0)
endif()
