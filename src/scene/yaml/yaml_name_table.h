#pragma once
// Names of a scene file (materials, objects) resolved to their indices, with the names kept in
// the order they were written for suggestions in messages.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace rtpro {

class NameTable {
 public:
  void add(const std::string& name, std::uint32_t index) {
    if (indices_.emplace(name, index).second) names_.push_back(name);
  }
  const std::uint32_t* find(const std::string& name) const {
    const auto found = indices_.find(name);
    return found == indices_.end() ? nullptr : &found->second;
  }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::unordered_map<std::string, std::uint32_t> indices_;
  std::vector<std::string> names_;
};

}  // namespace rtpro
