// glTF 2.0 scenes (.gltf with its buffers, or .glb) -> SceneDesc: the camera, KHR_lights_punctual
// lights, and every mesh of the scene as a diffuse or index-matched surface, an area light or a
// medium by its material (KHR_materials_transmission, _ior, _volume, _emissive_strength, and the
// "tetglow" object of a material's extras). docs/FORMAT.md, "glTF 2.0 scenes", has the mapping.
#pragma once
#include <string>

#include "scene/SceneDescription.h"

namespace tetglow {

// A .gltf or .glb name, or content that is a GLB container or a JSON object with an "asset".
bool looksLikeGltf(const std::string& path, const std::string& data);

// The scene of the glTF file `data` read from `path`. `camera`: the name of the camera node to
// look through; "" for the first camera node of the scene. Throws InputError, one line naming the
// file and the JSON pointer of the problem; warnings go to stderr.
SceneDesc loadGltfScene(const std::string& path, std::string data, const std::string& camera);

}  // namespace tetglow
