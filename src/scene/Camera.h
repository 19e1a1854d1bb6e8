// Perspective pinhole camera; the field of view spans the shorter image axis (pbrt's convention).
#pragma once
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "base/Ray.h"
#include "scene/SceneDescription.h"

namespace tetglow {

class Camera {
public:
    explicit Camera(const CameraDesc& desc);
    int width() const { return width_; }
    int height() const { return height_; }
    const glm::dvec3& position() const { return position_; }
    // The ray through film position (x, y) in pixels from the top-left corner; unit direction.
    Ray generateRay(double x, double y) const;
    // The film position (x, y) whose ray has direction d (the inverse of generateRay; d in front
    // of the camera).
    glm::dvec2 filmPosition(const glm::dvec3& d) const;

private:
    glm::dvec3 position_, forward_, right_, up_;
    double halfWidth_, halfHeight_;  // of the image plane at distance 1
    int width_, height_;
};

}  // namespace tetglow
