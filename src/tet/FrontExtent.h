// How far a closed surface reaches in front of each of its triangles: a ray that leaves the
// medium through a triangle, heading out, can meet the medium again only that far in front of
// the triangle's plane. Where nothing lies in front (a face of the convex hull), it cannot.
#pragma once
#include <vector>

#include <glm/vec4.hpp>

#include "base/Ray.h"
#include "tet/TetMesh.h"

namespace tetglow {

class FrontExtent {
public:
    FrontExtent() = default;  // no bound
    // Empty (no bound: every ray may re-enter anywhere) where the surface is too large to be
    // worth the start-up: more than 50,000 vertices (CGAL's hull of 50,000 points, half of them
    // on it, took 0.3 s; of 200,000, 1.6 s) or 2e8 pairs of a triangle and a hull vertex.
    explicit FrontExtent(const TetMesh& mesh);
    // The t beyond which the ray meets no part of the medium, having passed the plane that bounds
    // it in front of surface triangle s (whatever the ray's origin); INFINITY where no bound is
    // known or the ray does not head out of that plane.
    double reentryBefore(uint32_t s, const Ray& ray) const;

private:
    // Per surface triangle, the plane beyond which nothing of the medium lies: its unit outward
    // normal n (xyz) and w, rounded up, with dot(n, p) <= w for every point p of the medium; empty: none.
    std::vector<glm::dvec4> bound_;
};

}  // namespace tetglow
