#include "rtpro/job/job_identity.h"

#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "rtpro/scene/scene_inputs.h"

#include <xxhash.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rtpro {

namespace {

std::string hex64(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

bool is_one_line(std::string_view text) { return text.find('\n') == std::string_view::npos; }

}  // namespace

void JobIdentity::set(std::string key, std::string value) {
  if (key.empty() || !is_one_line(key) || key.find(": ") != std::string::npos || !is_one_line(value))
    throw std::logic_error("job identity key '" + key + "' or its value is not one line");
  for (auto& entry : entries_)
    if (entry.first == key) {
      entry.second = std::move(value);
      return;
    }
  entries_.emplace_back(std::move(key), std::move(value));
}

std::string JobIdentity::text() const {
  std::string out;
  for (const auto& [key, value] : entries_) out += key + ": " + value + "\n";
  return out;
}

JobIdentity JobIdentity::parse(std::string_view text, std::string_view source) {
  JobIdentity identity;
  std::size_t line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t end = text.find('\n');
    if (end == std::string_view::npos)
      throw InputError(std::string(source) + ": job description line " + std::to_string(line_number) +
                       " is not terminated");
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(end + 1);
    const std::size_t colon = line.find(": ");
    if (colon == std::string_view::npos || colon == 0)
      throw InputError(std::string(source) + ": job description line " + std::to_string(line_number) +
                       " is not 'key: value'");
    identity.entries_.emplace_back(std::string(line.substr(0, colon)), std::string(line.substr(colon + 2)));
  }
  return identity;
}

std::vector<std::string> JobIdentity::differences(const JobIdentity& other, std::string_view other_name) const {
  const auto find = [](const JobIdentity& in, const std::string& key) -> const std::string* {
    for (const auto& entry : in.entries_)
      if (entry.first == key) return &entry.second;
    return nullptr;
  };
  // Keys and values come from a journal or another rank: printed escaped.
  const auto shown = [](const std::string& text) { return printable_text(text); };
  std::vector<std::string> out;
  for (const auto& [key, value] : entries_) {
    const std::string* theirs = find(other, key);
    if (!theirs) out.push_back(shown(key) + ": " + shown(value) + " here, absent in " + std::string(other_name));
    else if (*theirs != value)
      out.push_back(shown(key) + ": " + shown(value) + " here, " + shown(*theirs) + " in " + std::string(other_name));
  }
  for (const auto& [key, value] : other.entries_)
    if (!find(*this, key))
      out.push_back(shown(key) + ": absent here, " + shown(value) + " in " + std::string(other_name));
  return out;
}

std::string text_digest(std::string_view text) { return hex64(XXH3_64bits(text.data(), text.size())); }

std::string file_digest(const std::filesystem::path& file) {
  const int descriptor = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) throw InputError(file.string() + ": cannot read it to identify the job: " + std::strerror(errno));
  XXH3_state_t* state = XXH3_createState();
  XXH3_64bits_reset(state);
  std::vector<char> chunk(1 << 20);
  while (true) {
    const ssize_t got = ::read(descriptor, chunk.data(), chunk.size());
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int error = errno;
      ::close(descriptor);
      XXH3_freeState(state);
      throw InputError(file.string() + ": cannot read it to identify the job: " + std::strerror(error));
    }
    if (got == 0) break;
    XXH3_64bits_update(state, chunk.data(), static_cast<std::size_t>(got));
  }
  ::close(descriptor);
  const std::uint64_t digest = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  return hex64(digest);
}

JobIdentity scene_identity(const SceneDescription& description, const SceneBuildReport& report,
                           const RenderScene& scene) {
  JobIdentity identity;
  identity.set("rtpro", RTPRO_VERSION);
  for (const SceneInput& input : scene_inputs(description, report, scene))
    identity.set(input.kind + " " + input.file.string(), file_digest(input.file));
  return identity;
}

}  // namespace rtpro
