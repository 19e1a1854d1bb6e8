// pbrt-v3's options block -> the camera, image size, output file and integrator of a SceneDesc.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/PbrtWorld.h"

namespace tetglow {

struct PbrtOptions {
    std::optional<PbrtCall> camera, film, sampler, integrator, filter;  // absent: pbrt-v3's defaults
    glm::dmat4 cameraToWorld{1};
    PbrtLocation worldBegin;  // where the defaults are reported
};

// Fills scene.camera, scene.output and scene.integrator. With pbrt-v3's "path" integrator, which
// ignores media, scene.media become the surfaces pbrt-v3 sees instead.
void applyPbrtOptions(PbrtOptions& options, SceneDesc& scene, std::vector<std::string>& warnings);

}  // namespace tetglow
