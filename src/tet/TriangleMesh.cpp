#include "tet/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include <glm/geometric.hpp>

#include "base/OutputFile.h"
#include "tet/PolygonTriangulation.h"

namespace tetglow {

void Bounds3::extend(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

double Bounds3::diagonal() const { return glm::length(hi - lo); }

bool clip(const Bounds3& box, const Ray& ray, double& t0, double& t1) {
    for (int k = 0; k < 3; ++k) {
        const double inv = 1 / ray.d[k];
        double a = (box.lo[k] - ray.o[k]) * inv, b = (box.hi[k] - ray.o[k]) * inv;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);  // NaN (0 * inf) leaves the bound as it was
    }
    return t0 < t1;
}

Bounds3 bounds(const TriangleMesh& mesh) {
    Bounds3 b;
    for (const auto& p : mesh.positions) b.extend(p);
    return b;
}

double signedVolume(const TriangleMesh& mesh) {
    // Relative to the first vertex, so that large offsets do not cost precision.
    if (mesh.positions.empty()) return 0;
    const glm::dvec3 o = mesh.positions[0];
    double v = 0;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        v += glm::dot(mesh.corner(t, 0) - o, glm::cross(mesh.corner(t, 1) - o, mesh.corner(t, 2) - o));
    return v / 6.0;
}

void addPolygon(TriangleMesh& mesh, const std::vector<uint32_t>& poly, const std::string& where) {
    if (poly.size() < 3) throw InputError(where + "face with " + std::to_string(poly.size()) + " vertices");
    triangulatePolygon(mesh.positions, poly, mesh.triangles, where);
}

void writeObj(const TriangleMesh& mesh, std::ostream& out, const std::string& header) {
    if (!header.empty()) out << header;
    out.precision(9);  // enough to round-trip float positions exactly (validation snaps to float)
    for (const auto& p : mesh.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void writeObj(const TriangleMesh& mesh, const std::string& path, const std::string& header) {
    writeStream(path, [&](std::ostream& out) { writeObj(mesh, out, header); });
}

}  // namespace tetglow
