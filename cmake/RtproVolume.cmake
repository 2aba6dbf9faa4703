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
