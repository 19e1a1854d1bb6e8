#include "scene/SphericalRectangle.h"

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
    // between them: the solid angle is their sum less 2 pi (Girard's theorem). In R each normal
    // has a zero component (the paper's closed forms: n0 = (0, z0, -y0) / |.|, n1 = (-z0, 0, x1)
    // / |.|, n2 = (0, -z0, y1) / |.|, n3 = (z0, 0, -x0) / |.|), so the angles' cosines are
    // products of corner coordinates over the normals' lengths.
    const double zz = z0_ * z0_, r0 = std::sqrt(zz + y0_ * y0_), r1 = std::sqrt(zz + x1_ * x1_),
                 r2 = std::sqrt(zz + y1_ * y1_), r3 = std::sqrt(zz + x0_ * x0_);
    auto angle = [](double cosine) { return std::acos(std::clamp(cosine, -1.0, 1.0)); };
    const double g0 = angle(y0_ * x1_ / (r0 * r1)), g1 = angle(-x1_ * y1_ / (r1 * r2)),
                 g2 = angle(y1_ * x0_ / (r2 * r3)), g3 = angle(-x0_ * y0_ / (r3 * r0));
    b0_ = -y0_ / r0;
    b1_ = y1_ / r2;
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
