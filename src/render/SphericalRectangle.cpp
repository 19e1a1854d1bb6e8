#include "render/SphericalRectangle.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace tetglow {

SphericalRectangle::SphericalRectangle(const glm::dvec3& o, const glm::dvec3& corner, const glm::dvec3& ex,
                                       const glm::dvec3& ey)
    : o_(o) {
    const double exl = glm::length(ex), eyl = glm::length(ey);
    x_ = ex / exl;
    y_ = ey / eyl;
    z_ = glm::cross(x_, y_);
    const glm::dvec3 d = corner - o;
    z0_ = glm::dot(d, z_);
    if (z0_ > 0) {
        z_ = -z_;
        z0_ = -z0_;
    }
    x0_ = glm::dot(d, x_);
    y0_ = glm::dot(d, y_);
    x1_ = x0_ + exl;
    y1_ = y0_ + eyl;
    // The normals of the four great circles through o and the edges, and the internal angles
    // between them: the solid angle is their sum less 2 pi (Girard's theorem).
    const glm::dvec3 v00(x0_, y0_, z0_), v01(x0_, y1_, z0_), v10(x1_, y0_, z0_), v11(x1_, y1_, z0_);
    const glm::dvec3 n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11));
    const glm::dvec3 n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
    auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
        return std::acos(std::clamp(-glm::dot(a, b), -1.0, 1.0));
    };
    const double g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    b0_ = n0.z;
    b1_ = n2.z;
    k_ = 2 * std::numbers::pi - g2 - g3;
    solidAngle_ = g0 + g1 - k_;
}

glm::dvec3 SphericalRectangle::sample(const glm::dvec2& u) const {
    // u.x sweeps the solid angle left of the plane x = xu; invert for xu.
    const double au = u.x * solidAngle_ + k_;
    const double fu = (std::cos(au) * b0_ - b1_) / std::sin(au);
    const double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + b0_ * b0_), -1.0, 1.0);
    const double xu = std::clamp(-(cu * z0_) / std::sqrt(std::max(1e-300, 1 - cu * cu)), x0_, x1_);
    // Along that line, u.y is uniform in the sine of the elevation.
    const double d = std::sqrt(xu * xu + z0_ * z0_);
    const double h0 = y0_ / std::sqrt(d * d + y0_ * y0_), h1 = y1_ / std::sqrt(d * d + y1_ * y1_);
    const double hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1 - 1e-12 ? std::clamp(hv * d / std::sqrt(1 - hv2), y0_, y1_) : y1_;
    return o_ + xu * x_ + yv * y_ + z0_ * z_;
}

}  // namespace tetglow
