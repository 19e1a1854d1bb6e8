// SceneDesc -> a JSON scene file (docs/FORMAT.md) that loadScene reads back as the same
// SceneDesc, number for number: every mesh goes to an OBJ file beside it.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/SceneDescription.h"

namespace tetglow {

// Writes `jsonPath` and, beside it, <stem>-surface-<i>.obj, <stem>-medium-<i>.obj and
// <stem>-light-<i>.obj, all or none of them (writeTogether); returns the mesh files written.
// Throws InputError when a file cannot be written, or when a mesh's name is a link.
std::vector<std::string> writeScene(const SceneDesc& scene, const std::string& jsonPath);

// A scene file's JSON as writeScene lays it out (arrays of numbers on one line), in place of
// `jsonPath` at once (a temporary file renamed). Throws InputError when it cannot be written.
void writeSceneJson(const nlohmann::ordered_json& scene, const std::string& jsonPath);
// The text writeSceneJson writes.
std::string sceneJsonText(const nlohmann::ordered_json& scene);

// The "integrator" object, and a medium's "sigma_a", "sigma_s", "g", "emission" and "density",
// as writeScene writes them (keys in the order FORMAT.md lists them).
nlohmann::ordered_json integratorJson(const IntegratorDesc& d);
nlohmann::ordered_json mediumCoefficientsJson(const MediumDesc& m);

}  // namespace tetglow
