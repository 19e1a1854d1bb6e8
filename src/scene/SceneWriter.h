// SceneDesc -> a JSON scene file (docs/FORMAT.md) that loadScene reads back as the same
// SceneDesc, number for number: every mesh goes to an OBJ file beside it.
#pragma once
#include <string>
#include <vector>

#include "scene/SceneDescription.h"

namespace tetglow {

// Writes `jsonPath` and, beside it, <stem>-surface-<i>.obj, <stem>-medium-<i>.obj and
// <stem>-light-<i>.obj; returns the mesh files written. Throws InputError when a file cannot
// be written.
std::vector<std::string> writeScene(const SceneDesc& scene, const std::string& jsonPath);

}  // namespace tetglow
