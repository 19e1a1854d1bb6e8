// The JSON scene file (docs/FORMAT.md) -> SceneDesc.
#pragma once
#include <string>

#include "scene/SceneDescription.h"

namespace tetglow {

// Reads, validates and places everything the file names: meshes are loaded (paths relative to
// the scene file's directory), transformed to world space and rounded to float; colours are
// multiplied by their "scale". Throws InputError, one line naming the file and the JSON pointer
// of the bad field, on any problem. Mesh warnings go to stderr.
SceneDesc loadScene(const std::string& path);

}  // namespace tetglow
