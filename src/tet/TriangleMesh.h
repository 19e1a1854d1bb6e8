// A closed triangle mesh: the boundary of a medium or a surface in the scene.
#pragma once
#include <array>
#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "base/Error.h"
#include "base/Ray.h"

namespace tetglow {

// x rounded to float precision. Through a volatile: GCC 12's SLP vectorizer at -O2 was seen
// to drop the rounding of (double)(float)x for some vector lanes.
inline double roundToFloat(double x) {
    volatile float f = static_cast<float>(x);
    return f;
}

struct TriangleMesh {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;

    glm::dvec3 corner(uint32_t tri, int k) const { return positions[triangles[tri][k]]; }
};

struct Bounds3 {
    glm::dvec3 lo{1e300}, hi{-1e300};
    void extend(const glm::dvec3& p);
    void extend(const Bounds3& b) {
        if (!b.empty()) {
            extend(b.lo);
            extend(b.hi);
        }
    }
    bool empty() const { return lo.x > hi.x; }
    // Closed box; false for NaN.
    bool contains(const glm::dvec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
    }
    double diagonal() const;
    // Closed boxes that share a point once one is grown by `margin`; false when either is empty.
    bool overlaps(const Bounds3& b, double margin = 0) const {
        if (empty() || b.empty()) return false;
        for (int i = 0; i < 3; ++i)
            if (lo[i] - margin > b.hi[i] || b.lo[i] - margin > hi[i]) return false;
        return true;
    }
};

// Narrows [t0, t1] to the part of the ray inside the box (slab test); false when nothing is left.
bool clip(const Bounds3& box, const Ray& ray, double& t0, double& t1);

Bounds3 bounds(const TriangleMesh& mesh);
// Signed volume by the divergence theorem (positive for outward winding).
double signedVolume(const TriangleMesh& mesh);

// Polygon (v0 ... vn-1) of the mesh's positions as triangles (tet/PolygonTriangulation.h); fewer
// than 3 vertices, or a self-crossing outline, is an InputError starting with `where` ("file:line: ").
void addPolygon(TriangleMesh& mesh, const std::vector<uint32_t>& polygon, const std::string& where);
void writeObj(const TriangleMesh& mesh, const std::string& path, const std::string& header = "");
// The same text to a stream (for a file written together with others: writeTogether).
void writeObj(const TriangleMesh& mesh, std::ostream& out, const std::string& header = "");

}  // namespace tetglow
