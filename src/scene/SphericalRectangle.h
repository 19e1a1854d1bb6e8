// A rectangle as seen from a point: its solid angle, and points on it uniform in that solid
// angle (Urena, Cruz and Wang 2013, "An area-preserving parametrization for spherical
// rectangles"). Area sampling's pdf grows as distance^2 / cos; this one is 1 / solidAngle.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tetglow {

class SphericalRectangle {
public:
    // The rectangle corner + a ex + b ey (a, b in [0, 1]; ex and ey orthogonal) seen from o.
    SphericalRectangle(const glm::dvec3& o, const glm::dvec3& corner, const glm::dvec3& ex, const glm::dvec3& ey);
    double solidAngle() const { return solidAngle_; }
    // A point on the rectangle; the direction to it has the solid-angle pdf 1 / solidAngle().
    glm::dvec3 sample(const glm::dvec2& u) const;

private:
    glm::dvec3 o_, x_, y_, z_;  // the paper's reference system R, z pointing away from the rectangle
    double x0_, y0_, x1_, y1_, z0_;
    double b0_, b1_, k_, solidAngle_;
};

}  // namespace tetglow
