#include "scene/Camera.h"

#include <cmath>
#include <numbers>

namespace tetglow {

Camera::Camera(const CameraDesc& desc) : position_(desc.position), width_(desc.width), height_(desc.height) {
    forward_ = glm::normalize(desc.lookAt - desc.position);
    right_ = glm::normalize(glm::cross(forward_, desc.up));
    up_ = glm::cross(right_, forward_);
    if (desc.handedness == Handedness::Left) right_ = -right_;  // after up_, which stays the same
    const double half = std::tan(desc.fov * std::numbers::pi / 360), aspect = double(width_) / height_;
    halfWidth_ = aspect >= 1 ? half * aspect : half;
    halfHeight_ = aspect >= 1 ? half : half / aspect;
}

Ray Camera::generateRay(double x, double y) const {
    const double sx = (2 * x / width_ - 1) * halfWidth_, sy = (1 - 2 * y / height_) * halfHeight_;
    return {position_, glm::normalize(forward_ + sx * right_ + sy * up_)};
}

glm::dvec2 Camera::filmPosition(const glm::dvec3& d) const {
    const double depth = glm::dot(d, forward_);
    const double sx = glm::dot(d, right_) / depth, sy = glm::dot(d, up_) / depth;
    return {(sx / halfWidth_ + 1) * width_ / 2, (1 - sy / halfHeight_) * height_ / 2};
}

}  // namespace tetglow
