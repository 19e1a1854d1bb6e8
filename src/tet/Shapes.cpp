#include "tet/Shapes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <glm/geometric.hpp>

namespace tetglow {

TriangleMesh box(const glm::dvec3& lo, const glm::dvec3& hi) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) m.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    // Outward winding, two triangles per face.
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

TriangleMesh icosphere(int subdivisions, double radius, const glm::dvec3& centre) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    TriangleMesh m;
    m.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& p : m.positions) p = glm::normalize(p);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
            return mid[key] = uint32_t(m.positions.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> next;
        for (const auto& f : m.triangles) {
            const uint32_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
            next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
        }
        m.triangles = std::move(next);
    }
    for (auto& p : m.positions) p = centre + p * radius;
    return m;
}

TriangleMesh merge(const TriangleMesh& a, const TriangleMesh& b) {
    TriangleMesh m = a;
    const auto offset = uint32_t(a.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (auto t : b.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return m;
}

TriangleMesh quad(const glm::dvec3& corner, const glm::dvec3& edge0, const glm::dvec3& edge1) {
    TriangleMesh m;
    m.positions = {corner, corner + edge0, corner + edge0 + edge1, corner + edge1};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

TriangleMesh disk(const glm::dvec3& centre, const glm::dvec3& normal, double radius, int sides) {
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 a = glm::normalize(glm::cross(n, std::abs(n.x) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 b = glm::cross(n, a);
    TriangleMesh m;
    m.positions.push_back(centre);
    for (int i = 0; i < sides; ++i) {
        const double phi = 2 * std::numbers::pi * i / sides;
        m.positions.push_back(centre + radius * (std::cos(phi) * a + std::sin(phi) * b));
        m.triangles.push_back({0, uint32_t(1 + i), uint32_t(1 + (i + 1) % sides)});
    }
    return m;
}

}  // namespace tetglow
