#include "scene/PbrtTransform.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace tetglow {

bool pbrtLookAt(const glm::dvec3& eye, const glm::dvec3& look, const glm::dvec3& up, glm::dmat4& worldToCamera) {
    const glm::dvec3 dir = glm::normalize(look - eye);
    const glm::dvec3 right = glm::cross(glm::normalize(up), dir);
    if (!(glm::length(right) > 0)) return false;
    glm::dmat4 cameraToWorld(1);  // columns: right, up, dir, eye
    cameraToWorld[0] = glm::dvec4(glm::normalize(right), 0);
    cameraToWorld[1] = glm::dvec4(glm::cross(dir, glm::normalize(right)), 0);
    cameraToWorld[2] = glm::dvec4(dir, 0);
    cameraToWorld[3] = glm::dvec4(eye, 1);
    worldToCamera = glm::inverse(cameraToWorld);
    return true;
}

bool isAffine(const glm::dmat4& m) { return m[0][3] == 0 && m[1][3] == 0 && m[2][3] == 0 && m[3][3] == 1; }

bool isSimilarity(const glm::dmat3& m) {
    // Relative to the scale, as loose as the float arithmetic pbrt-v3 itself does.
    constexpr double kTolerance = 1e-5;
    const double l0 = glm::length(m[0]), l1 = glm::length(m[1]), l2 = glm::length(m[2]);
    const double scale = std::max({l0, l1, l2});
    if (!(scale > 0)) return false;
    return std::abs(l0 - l1) <= kTolerance * scale && std::abs(l1 - l2) <= kTolerance * scale &&
           std::abs(glm::dot(m[0], m[1])) <= kTolerance * scale * scale &&
           std::abs(glm::dot(m[1], m[2])) <= kTolerance * scale * scale &&
           std::abs(glm::dot(m[0], m[2])) <= kTolerance * scale * scale;
}

}  // namespace tetglow
