// pbrt-v3's transform formulas (core/transform.cpp) and the checks tetglow needs on them.
#pragma once
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace tetglow {

// pbrt-v3's LookAt: the world-to-camera transform of a LEFT-handed camera frame (x along
// cross(up, look - eye), y the up direction made orthogonal, z towards `look`). Returns false
// when `up` is zero or parallel to the view direction.
bool pbrtLookAt(const glm::dvec3& eye, const glm::dvec3& look, const glm::dvec3& up, glm::dmat4& worldToCamera);

// The last row is (0, 0, 0, 1): no perspective division.
bool isAffine(const glm::dmat4& m);
// A rotation times a uniform scale, perhaps mirrored: angles are kept.
bool isSimilarity(const glm::dmat3& m);

}  // namespace tetglow
