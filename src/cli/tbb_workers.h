#pragma once
// TBB's worker threads started before anything else needs them.

namespace rtpro::cli {

// Has TBB load what it loads on first use (tbbmalloc, irml) and start its worker threads before
// the image layer loads in the background: while a dlopen maps and relocates libraries, glibc
// holds a lock that another dlopen and every new thread wait for, so a worker started later would
// hold the render back until OpenImageIO is loaded. Waits at most 50 ms for the workers.
void start_tbb_workers(int threads);

}  // namespace rtpro::cli
