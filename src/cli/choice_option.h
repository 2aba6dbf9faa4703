#pragma once
// Options whose value is a keyword (--backend embree, --integrator path, --progress json, ...):
// one rule for all of them, so `--backend Embree` and `--aov Albedo` are read as a user means them.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rtpro::cli {

// Makes `option` take one of `names`, in any case; the value handed on is the name as spelt in
// `names` (so the code reading it compares against lowercase only). Others are a usage error
// listing the names, which also become the option's type name ("TEXT:{native,embree}") that help
// and shell completion show.
CLI::Option* one_of(CLI::Option* option, std::vector<std::string> names);

}  // namespace rtpro::cli
