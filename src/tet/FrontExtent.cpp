#include "tet/FrontExtent.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

namespace tetglow {

FrontExtent::FrontExtent(const TetMesh& mesh) {
    // The farthest any point of the medium reaches along a direction is at a vertex of its
    // convex hull: only those are scanned.
    if (mesh.surfaceVertexCount < 4 || mesh.surfaceVertexCount > 50000) return;
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Kernel::Point_3> points;
    points.reserve(mesh.surfaceVertexCount);
    for (size_t v = 0; v < mesh.surfaceVertexCount; ++v)
        points.emplace_back(mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z);
    CGAL::Surface_mesh<Kernel::Point_3> hull;
    CGAL::convex_hull_3(points.begin(), points.end(), hull);
    std::vector<glm::dvec3> corners;
    for (const auto v : hull.vertices()) {
        const auto& p = hull.point(v);
        corners.emplace_back(p.x(), p.y(), p.z());
    }
    if (double(corners.size()) * double(mesh.surface.size()) > 2e8) return;
    double size = 0;
    for (const glm::dvec3& c : corners) size = std::max(size, glm::length(c));
    // Far above the dot products' rounding (about 1e-16 of the size), here and in reentryBefore.
    const double slack = 1e-9 * size;
    bound_.resize(mesh.surface.size());
    tbb::parallel_for(size_t(0), mesh.surface.size(), [&](size_t s) {
        const auto& f = mesh.surface[s];
        const glm::dvec3 a = mesh.vertices[f[0]];
        const glm::dvec3 n = glm::cross(mesh.vertices[f[1]] - a, mesh.vertices[f[2]] - a);
        const double length = glm::length(n);
        if (!(length > 0)) {
            bound_[s] = glm::dvec4(0, 0, 0, INFINITY);  // no direction to bound along
            return;
        }
        const glm::dvec3 unit = n / length;
        double reach = -INFINITY;
        for (const glm::dvec3& c : corners) reach = std::max(reach, glm::dot(unit, c));
        bound_[s] = glm::dvec4(unit, reach + slack);
    });
}

double FrontExtent::reentryBefore(uint32_t s, const Ray& ray) const {
    if (bound_.empty()) return INFINITY;
    const glm::dvec3 n(bound_[s]);
    const double heading = glm::dot(n, ray.d);
    if (!(heading > 0)) return INFINITY;
    // The ray passes the bounding plane where dot(n, o + t d) = w.
    return (bound_[s].w - glm::dot(n, ray.o)) / heading;
}

}  // namespace tetglow
