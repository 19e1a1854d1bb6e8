// glTF 1.0 is told apart from 2.0 before Assimp reads a file: Assimp's glTF 1 importer composes
// node transforms in the wrong order and does not know a glTF 1 GLB at all, so glTF 1 is refused
// with one line that says how to go on.
#pragma once
#include <string>

namespace tetglow {

// Throws InputError "<path>: glTF 1.0 is not supported; re-export as glTF 2.0" when `data` is
// glTF 1.0: a GLB (`binary`) of container version 1, or JSON whose "asset" "version" is 1.x.
void refuseGltf1(const std::string& data, const std::string& path, bool binary);

}  // namespace tetglow
