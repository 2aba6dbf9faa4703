#pragma once
// The check every backend puts in front of its traversal: untraceable rays (NaN, huge, negative
// tnear) never reach it — Debian's Embree would abort the process on them — and are counted.
#include "rtpro/core/ray.h"

#include <atomic>
#include <cstdint>

namespace rtpro {

class RayGate {
 public:
  bool admit(const Ray& ray) const {
    if (is_traceable(ray)) return true;
    rejected_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  std::uint64_t rejected() const { return rejected_.load(std::memory_order_relaxed); }

 private:
  mutable std::atomic<std::uint64_t> rejected_{0};
};

}  // namespace rtpro
