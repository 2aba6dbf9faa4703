# The distributed module (src/distributed): the tile scheduler of a render shared by the ranks of
# an MPI job, written against the Communicator interface, and librtpro_mpi.so, the plugin holding
# rtpro's only calls into Open MPI. The executable does not link MPI: it loads the plugin only
# when mpirun started it, so a plain `rtpro render` neither needs nor starts MPI.
# The C API, called from C++; the deprecated MPI C++ bindings are not wanted.
set(MPI_CXX_SKIP_MPICXX ON)
find_package(MPI REQUIRED COMPONENTS CXX)

rtpro_add_module(distributed DEPENDS render job PRIVATE_DEPENDS TBB::tbb Threads::Threads ${CMAKE_DL_LIBS}
                 EXCLUDE mpi_plugin.cpp)

add_library(rtpro_mpi MODULE ${CMAKE_SOURCE_DIR}/src/distributed/mpi_plugin.cpp)
target_include_directories(rtpro_mpi PRIVATE ${CMAKE_SOURCE_DIR}/src/distributed)
target_link_libraries(rtpro_mpi PRIVATE rtpro_distributed_headers MPI::MPI_CXX)
target_compile_definitions(rtpro_mpi PRIVATE RTPRO_VERSION="${PROJECT_VERSION}")
set_target_properties(rtpro_mpi PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR} CXX_VISIBILITY_PRESET hidden)
add_dependencies(rtpro_distributed rtpro_mpi)

add_library(rtpro_distributed_headers INTERFACE)
rtpro_module_include_root(distributed distributed_root)
target_include_directories(rtpro_distributed_headers INTERFACE ${distributed_root})
