#include "light_sample.h"

#include <variant>

namespace rtpro {

int light_samples_per_axis(const Light& light) {
  return std::visit([](const auto& l) { return samples_per_axis(l); }, light);
}

float hit_light(const Light& light, const Ray& ray, float t_max) {
  return std::visit([&](const auto& l) { return hit_light_of_kind(l, ray, t_max); }, light);
}

Color light_emission(const Light& light) {
  return std::visit([](const auto& l) { return emission_of_kind(l); }, light);
}

}  // namespace rtpro
