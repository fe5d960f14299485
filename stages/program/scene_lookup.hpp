// Scenes by name: `gas crowd` or `gas crowd.scene` from any folder.
//
// Not one of the article's stages: the article's stage 2 sets the initial
// values and does not say how; this program reads a scene file, and finds a
// scene named on the command line that is not a file among the teaching scenes:
// those installed beside the program (share/gas-on-the-display, found from the
// program's own location, so that a `--prefix` install and a relocated package
// both work), or, for a program run from its build folder, the source tree's
// data/.
// Lesson: lessons/2-input.md; the reference: README.md ("The program").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gas {

// The folders where a scene name is looked for, for the program at `program`
// (an absolute path): the source tree's scenes `source_scenes` if the program
// lies inside the build folder `build_folder`, else `scenes_from_program`
// taken from the program's folder (e.g. "../share/gas-on-the-display").
std::vector<std::filesystem::path> scene_folders(
    const std::filesystem::path& program, const std::filesystem::path& build_folder,
    const std::filesystem::path& source_scenes,
    const std::filesystem::path& scenes_from_program);

// The folders of this program, as its build configured them (CMakeLists.txt);
// the program's location is /proc/self/exe, and where that cannot be read,
// the installation prefix it was configured with.
std::vector<std::filesystem::path> scene_folders();

// The scene file the command line's SCENE means: `name` itself if it exists
// (a directory too: stage 2 refuses it clearly) or is absolute, else the
// first folder's `name`.scene (`name` if it ends in ".scene") that is a
// file. Throws SceneError naming every place it looked when none holds it.
std::string find_scene(const std::string& name,
                       const std::vector<std::filesystem::path>& folders);

}  // namespace gas
