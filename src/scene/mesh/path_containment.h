#pragma once
// Whether a file named inside a folder stays there once symbolic links are followed: how mtllib,
// MTL textures and glTF images are kept inside the folder of the file that names them.
#include <filesystem>

namespace rtpro {

// True when `path` (existing or not) resolves inside `folder` after following symbolic links, or
// when the file system cannot resolve either (a name over 255 bytes, say: left to the existence
// check that follows).
inline bool resolves_inside(const std::filesystem::path& folder, const std::filesystem::path& path) {
  std::error_code folder_error, target_error;
  const std::filesystem::path canonical_folder =
      std::filesystem::weakly_canonical(folder.empty() ? std::filesystem::path(".") : folder, folder_error);
  const std::filesystem::path target = std::filesystem::weakly_canonical(path, target_error);
  if (folder_error || target_error) return true;
  const std::filesystem::path inside = target.lexically_relative(canonical_folder);
  return !inside.empty() && *inside.begin() != "..";
}

}  // namespace rtpro
