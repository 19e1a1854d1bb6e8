// A short hash of everything in a scene that changes its image, so that parts of a render
// (render/PartialRender.h) from different scenes or settings are never merged.
#pragma once
#include <string>

#include "scene/SceneDescription.h"

namespace tetglow {

// 16 hex digits: FNV-1a over the scene as writeScene writes it (JSON and meshes, number for
// number), without its file name and output path. InputError if the temporary copy cannot be written.
std::string sceneFingerprint(const SceneDesc& scene);

}  // namespace tetglow
