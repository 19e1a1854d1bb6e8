// The part of a ball that lies inside the medium, for density estimates near the boundary:
// photons exist only inside, so a k-NN ball that pokes out of the surface holds fewer photons
// than its volume suggests, and dividing by the whole ball darkens a rim along the surface.
// Seen from the centre, the inside part is star-shaped up to the first boundary crossing:
// V = integral over directions of min(r, t(w))^3 / 3, by a fixed spherical Fibonacci
// quadrature of rays against the boundary (Embree).
#pragma once
#include <array>

#include <glm/vec3.hpp>

#include "tet/SurfaceBVH.h"

namespace tetglow {

class ClippedBall {
public:
    static constexpr int kDirections = 32;
    explicit ClippedBall(const SurfaceBVH& boundary);
    // Volume of the ball (p, r) within reach of p without crossing the boundary (p inside).
    double inside(const glm::dvec3& p, double r) const;

private:
    const SurfaceBVH& boundary_;
    std::array<glm::dvec3, kDirections> directions_;
};

}  // namespace tetglow
