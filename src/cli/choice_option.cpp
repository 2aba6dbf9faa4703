#include "choice_option.h"

#include <utility>

namespace rtpro::cli {

CLI::Option* one_of(CLI::Option* option, std::vector<std::string> names) {
  // A transform, not a check: a check sees a copy, so "Embree" would pass it and then reach the
  // code as typed.
  return option->transform(CLI::IsMember(std::move(names), CLI::ignore_case));
}

}  // namespace rtpro::cli
