// Scenes by name. See scene_lookup.hpp.
#include "program/scene_lookup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <system_error>

#include "stage2_input.hpp"

namespace gas {

namespace fs = std::filesystem;

std::vector<fs::path> scene_folders(const fs::path& program, const fs::path& build_folder,
                                    const fs::path& source_scenes,
                                    const fs::path& scenes_from_program) {
  const fs::path inside = program.lexically_relative(build_folder);
  if (!inside.empty() && *inside.begin() != "..") return {source_scenes};
  return {(program.parent_path() / scenes_from_program).lexically_normal()};
}

std::vector<fs::path> scene_folders() {
  std::error_code error;
  const fs::path program = fs::canonical("/proc/self/exe", error);
  if (error) return {GAS_INSTALLED_SCENES};
  // The build folder as the file system names it (a symbolic link resolved),
  // as /proc/self/exe does.
  fs::path build_folder = fs::weakly_canonical(GAS_BUILD_FOLDER, error);
  if (error) build_folder = GAS_BUILD_FOLDER;
  return scene_folders(program, build_folder, GAS_SOURCE_SCENES, GAS_SCENES_FROM_PROGRAM);
}

std::string find_scene(const std::string& name, const std::vector<fs::path>& folders) {
  std::error_code error;
  if (fs::exists(name, error) || fs::path(name).is_absolute()) return name;
  const std::string file_name = name.ends_with(".scene") ? name : name + ".scene";
  std::vector<std::string> looked_at;
  for (const fs::path& folder : folders) {
    const fs::path path = folder / file_name;
    if (fs::is_regular_file(path, error)) return path.string();
    looked_at.push_back(path.string());
  }
  throw SceneError(
      fmt::format("{}: no such scene file (looked in the current folder and at {})", name,
                  fmt::join(looked_at, " and ")));
}

}  // namespace gas
