#include "rtpro/distributed/prestarted_thread.h"

#include "rtpro/core/error.h"

#include <utility>

namespace rtpro {

PrestartedThread::PrestartedThread()
    : thread_([this] {
        std::function<void()> task;
        {
          std::unique_lock lock(mutex_);
          given_.wait(lock, [this] { return released_; });
          task = std::move(task_);
        }
        if (task) task();
      }) {}

PrestartedThread::~PrestartedThread() {
  {
    const std::lock_guard lock(mutex_);
    released_ = true;
  }
  given_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void PrestartedThread::run(std::function<void()> task) {
  {
    const std::lock_guard lock(mutex_);
    if (released_) throw RuntimeError("a prestarted thread runs one task only");
    task_ = std::move(task);
    released_ = true;
  }
  given_.notify_one();
}

void PrestartedThread::join() {
  {
    const std::lock_guard lock(mutex_);
    released_ = true;
  }
  given_.notify_one();
  if (thread_.joinable()) thread_.join();
}

}  // namespace rtpro
