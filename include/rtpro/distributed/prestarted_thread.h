#pragma once
// A thread created now to run one task later. While another thread is inside dlopen, creating a
// thread blocks (glibc allocates its TLS under the loader's lock): rank 0 of a job creates its
// render thread before it starts loading OpenImageIO in the background, so the load overlaps the
// scene's BVH build as in a single process, and neither rank 0's render nor its answers to the
// other ranks wait for it.
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace rtpro {

class PrestartedThread {
 public:
  PrestartedThread();
  // Joins; a thread never given a task is released first.
  ~PrestartedThread();
  PrestartedThread(const PrestartedThread&) = delete;
  PrestartedThread& operator=(const PrestartedThread&) = delete;

  // Runs `task` on the thread; at most once.
  void run(std::function<void()> task);
  // Waits for the task to finish (or, with none given, for the thread to end).
  void join();

 private:
  std::mutex mutex_;
  std::condition_variable given_;
  std::function<void()> task_;
  bool released_ = false;
  std::thread thread_;
};

}  // namespace rtpro
