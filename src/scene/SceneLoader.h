// Scene files (docs/FORMAT.md) -> SceneDesc.
#pragma once
#include <string>

#include "scene/JsonReader.h"
#include "scene/SceneDescription.h"

namespace tetglow {

inline constexpr size_t kMaxLabelBytes = 64;  // a medium's "name", in UTF-8

// Reads, validates and places everything the file names: meshes are loaded (paths relative to
// the scene file's directory), transformed to world space and rounded to float; colours are
// multiplied by their "scale". Throws InputError, one line naming the file and the JSON pointer
// of the bad field, on any problem. Mesh warnings go to stderr.
// A file whose name ends in .pbrt, or whose first token is a pbrt-v3 directive, is read as a
// pbrt-v3 scene (scene/PbrtParser.h); a .gltf or .glb file, or a GLB or a JSON object with an
// "asset" and no "camera", as a glTF 2.0 scene (scene/GltfScene.h), looking through the camera
// node named `camera` ("" the first); a camera named for another format is an error.
SceneDesc loadScene(const std::string& path, const std::string& camera = "");
// A JSON scene as `path` would hold it (its files relative to path's folder), read as loadScene
// reads one: a scene checked before it is written.
SceneDesc loadJsonScene(const nlohmann::json& doc, const std::string& path);
// The same from a JSON scene's `text` (`path` named in messages): a scene about to be saved
// there is checked with it.
SceneDesc loadJsonSceneText(const std::string& text, const std::string& path);

// The parts of a scene file the preview re-tunes, with the loader's own checks and errors.
// A camera's "position", "look_at", "up" and "fov" (up and fov, when absent, keep c's).
void readCameraView(JsonObject& o, CameraDesc& c);
// A light's "scale", its emitted quantity (emissionKey(l.type), times the scale) and "on".
void readLightEmission(JsonObject& o, LightDesc& l);
// An "integrator" object (absent keys keep their defaults).
IntegratorDesc readIntegrator(JsonObject& o);
// A medium's "scale", "sigma_a", "sigma_s", "g", "emission" and "density": the keys present
// replace m's values (sigma_a and sigma_s times "scale", 1 when absent).
void readMediumCoefficients(JsonObject& o, MediumDesc& m);

// A medium's name as a page or a report may show it: 1 to kMaxLabelBytes bytes of one line.
bool validLabel(const std::string& label);

// Something gives off light: a light with non-zero intensity, irradiance or radiance, or an
// emissive medium.
bool emitsLight(const SceneDesc& scene);

}  // namespace tetglow
