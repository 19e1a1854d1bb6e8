#include "tet/HoleLattice.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace tetglow {
namespace {

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

// A hole's rim, and the ball around it that its lattice fills.
struct Ball {
    glm::dvec3 centre{0}, vectorArea{0};
    double radius = 0, edgeLength = 0, spacing = 0;
    size_t edges = 0;
    bool open = false;
    std::vector<uint64_t> rim;
};

// Bisections towards the winding number's level set 1/2, and how near the rim (in lattice
// spacings) a point on it may lie.
constexpr int kBisections = 10;
constexpr double kRimClearance = 0.5;

double distanceToRim(const TriangleMesh& soup, const std::vector<uint64_t>& rim, const glm::dvec3& p) {
    double d = INFINITY;
    for (uint64_t e : rim)
        d = std::min(d, distanceToSegment(p, soup.positions[uint32_t(e >> 32)], soup.positions[uint32_t(e)]));
    return d;
}

// The lattice of spacing s in ball b, each point given to add(p).
template <class Add>
void fillBall(const Ball& b, double s, const TriangleMesh& soup, const PartWinding& winding, const glm::dvec3& offset,
              Add&& add) {
    const int n = int(std::ceil(b.radius / s)), side = 2 * n + 1;
    const auto at = [&](int i, int j, int k) { return b.centre + s * (glm::dvec3(i, j, k) + offset); };
    const auto index = [&](int i, int j, int k) { return size_t((i + n) * side + j + n) * side + k + n; };
    std::vector<double> w(size_t(side) * side * side, NAN);  // NaN: outside the ball
    for (int i = -n; i <= n; ++i)
        for (int j = -n; j <= n; ++j)
            for (int k = -n; k <= n; ++k)
                if (glm::length(at(i, j, k) - b.centre) <= b.radius)
                    w[index(i, j, k)] = winding.approximate(at(i, j, k));
    // Where the winding number crosses 1/2 between neighbours, a point on that level set
    // (by bisection) replaces both: the spanning surface then runs through these points
    // instead of stepping between lattice points on either side of it. Not beside the rim,
    // where the level set meets the surface: there such a point would make slivers whose
    // centroids fall on the wrong side of an input triangle.
    std::vector<char> nearLevel(w.size(), 0);
    for (int i = -n; i <= n; ++i)
        for (int j = -n; j <= n; ++j)
            for (int k = -n; k <= n; ++k)
                for (const glm::ivec3 step : {glm::ivec3(1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, 0, 1)}) {
                    const glm::ivec3 q = glm::ivec3(i, j, k) + step;
                    if (q.x > n || q.y > n || q.z > n) continue;
                    const size_t a = index(i, j, k), c = index(q.x, q.y, q.z);
                    if (!((w[a] - 0.5) * (w[c] - 0.5) < 0)) continue;  // also false for NaN
                    nearLevel[a] = nearLevel[c] = 1;
                    glm::dvec3 lo = at(i, j, k), hi = at(q.x, q.y, q.z);
                    const bool loInside = w[a] > 0.5;
                    for (int halving = 0; halving < kBisections; ++halving) {
                        const glm::dvec3 mid = 0.5 * (lo + hi);
                        ((winding.approximate(mid) > 0.5) == loInside ? lo : hi) = mid;
                    }
                    const glm::dvec3 level = 0.5 * (lo + hi);
                    if (distanceToRim(soup, b.rim, level) > kRimClearance * s) add(level);
                }
    for (int i = -n; i <= n; ++i)
        for (int j = -n; j <= n; ++j)
            for (int k = -n; k <= n; ++k)
                if (!std::isnan(w[index(i, j, k)]) && !nearLevel[index(i, j, k)]) add(at(i, j, k));
}

}  // namespace

std::vector<glm::dvec3> holeLattice(const TriangleMesh& soup, const EdgeMap& edges, const PartWinding& winding,
                                    const Bounds3& box, const glm::dvec3& offset) {
    static constexpr double kLatticeAcross = 16, kBallScale = 1.25, kLatticeBudget = 200000, kSmallHole = 2,
                            kCrack = 0.25;
    std::vector<uint64_t> rim;
    for (const auto& [key, users] : edges)
        if (users.size() == 1) rim.push_back(key);
    std::sort(rim.begin(), rim.end());  // the same lattice whatever the hash order
    UnionFind loops(soup.positions.size());
    for (uint64_t e : rim) loops.unite(uint32_t(e >> 32), uint32_t(e));
    std::unordered_map<uint32_t, Ball> balls;
    for (uint64_t e : rim) {
        Ball& b = balls[loops.find(uint32_t(e))];
        const glm::dvec3 p = soup.positions[uint32_t(e >> 32)], q = soup.positions[uint32_t(e)];
        b.centre += p + q;
        b.edgeLength += glm::length(q - p);
        b.edges += 1;
        b.rim.push_back(e);
    }
    for (uint64_t e : rim) {
        Ball& b = balls[loops.find(uint32_t(e))];
        const glm::dvec3 c = b.centre / double(2 * b.edges);
        const glm::dvec3 p = soup.positions[uint32_t(e >> 32)] - c, q = soup.positions[uint32_t(e)] - c;
        b.radius = std::max(b.radius, glm::length(p));
        // The rim runs as its one triangle does.
        b.vectorArea +=
            0.5 * (traverses(soup.triangles[edges.at(e)[0]], uint32_t(e >> 32), uint32_t(e)) ? glm::cross(p, q)
                                                                                             : glm::cross(q, p));
    }
    double total = 0;
    for (auto& [root, b] : balls) {
        b.centre /= double(2 * b.edges);
        b.radius *= kBallScale;
        b.edgeLength /= double(b.edges);
        b.open = b.radius >= kSmallHole * b.edgeLength &&
                 glm::length(b.vectorArea) >= kCrack * double(b.edges) * b.edgeLength * b.edgeLength;
        if (!b.open) continue;
        b.spacing = std::max(b.edgeLength, 2 * b.radius / kLatticeAcross);
        total += 4.19 * std::pow(b.radius / b.spacing, 3);  // 4 pi / 3 lattice points per unit ball
    }
    const double coarsen = std::max(1.0, std::cbrt(total / kLatticeBudget));
    std::vector<uint32_t> roots;
    for (const auto& [root, b] : balls) roots.push_back(root);
    std::sort(roots.begin(), roots.end());
    std::vector<glm::dvec3> points;
    const auto add = [&](const glm::dvec3& p) {
        const glm::dvec3 f(roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z));
        if (glm::all(glm::greaterThan(f, box.lo)) && glm::all(glm::lessThan(f, box.hi))) points.push_back(f);
    };
    for (uint32_t root : roots)
        if (const Ball& b = balls[root]; b.open) fillBall(b, b.spacing * coarsen, soup, winding, offset, add);
    return points;
}

}  // namespace tetglow
