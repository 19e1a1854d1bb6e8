// pbrt-v3's "trianglemesh" and "plymesh" shapes placed in world space, each triangle wound so
// that cross(p1 - p0, p2 - p0) is the normal pbrt-v3 gives it: the side an area light emits to
// and a MediumInterface calls "outside".
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/PbrtParams.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

struct PbrtMesh {
    TriangleMesh mesh;             // world space, every coordinate a float
    bool hasNormals = false;       // "N" (or the PLY file's nx, ny, nz) was given
    bool swapsHandedness = false;  // the transform mirrors
};

// `type`: the Shape's type; `objectToWorld`: the CTM; files relative to `searchDir`.
PbrtMesh readPbrtMesh(const std::string& type, PbrtParams& params, const PbrtLocation& where,
                      const glm::dmat4& objectToWorld, bool reverseOrientation, const std::filesystem::path& searchDir,
                      std::vector<std::string>& warnings);

}  // namespace tetglow
