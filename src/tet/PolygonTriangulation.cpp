#include "tet/PolygonTriangulation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "base/Error.h"
#include "tet/Predicates.h"

namespace tetglow {
namespace {

int sign(double x) { return (x > 0) - (x < 0); }

// Newell's normal: twice the vector area, exact for flat polygons and a fair average otherwise.
glm::dvec3 newellNormal(const std::vector<glm::dvec3>& positions, const std::vector<uint32_t>& polygon) {
    glm::dvec3 n(0);
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = positions[polygon[i]];
        const glm::dvec3& b = positions[polygon[(i + 1) % polygon.size()]];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

// The polygon in the plane of the two axes other than the normal's largest, mirrored where needed
// so that it runs counter-clockwise; dropping an axis keeps the coordinates exact. Corners at the
// position of the one before are left out (a zero-length edge bounds nothing).
struct Outline {
    std::vector<glm::dvec2> points;
    std::vector<uint32_t> vertex;  // the mesh vertex of each point
};

Outline project(const std::vector<glm::dvec3>& positions, const std::vector<uint32_t>& polygon, const glm::dvec3& n) {
    const glm::dvec3 m = glm::abs(n);
    const int axis = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    int u = (axis + 1) % 3, v = (axis + 2) % 3;  // (u, v, axis) is right-handed
    if (n[axis] < 0) std::swap(u, v);
    Outline o;
    for (uint32_t i : polygon) {
        const glm::dvec2 p(positions[i][u], positions[i][v]);
        if (o.points.empty() || p != o.points.back()) {
            o.points.push_back(p);
            o.vertex.push_back(i);
        }
    }
    while (o.points.size() > 1 && o.points.back() == o.points.front()) {
        o.points.pop_back();
        o.vertex.pop_back();
    }
    return o;
}

// Every corner turns left or goes straight on, and the outline turns once around: the fan of a
// convex polygon covers it exactly once.
bool convex(const Outline& o) {
    const size_t n = o.points.size();
    double turning = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec2 &a = o.points[(i + n - 1) % n], &b = o.points[i], &c = o.points[(i + 1) % n];
        const double turn = orient2d(a, b, c);
        const glm::dvec2 in = b - a, out = c - b;
        if (turn < 0 || (turn == 0 && glm::dot(in, out) < 0)) return false;
        turning += std::atan2(in.x * out.y - in.y * out.x, glm::dot(in, out));
    }
    return turning < 3 * M_PI;  // 2 pi for a convex polygon, 4 pi or more for a star
}

// Whether the closed segments ab and cd share a point.
bool segmentsMeet(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
    const int o1 = sign(orient2d(a, b, c)), o2 = sign(orient2d(a, b, d)), o3 = sign(orient2d(c, d, a)),
              o4 = sign(orient2d(c, d, b));
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    auto onSegment = [](const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r) {  // r collinear with pq
        return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
               r.y <= std::max(p.y, q.y);
    };
    return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) || (o3 == 0 && onSegment(c, d, a)) ||
           (o4 == 0 && onSegment(c, d, b));
}

// The first two edges (by index) of an outline that cross, touch, or fold back along each other;
// {-1, -1} for a simple outline. Edges are swept in order of their smallest x.
std::pair<long, long> selfContact(const Outline& o) {
    const size_t n = o.points.size();
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    auto lo = [&](size_t e) { return std::min(o.points[e].x, o.points[(e + 1) % n].x); };
    auto hi = [&](size_t e) { return std::max(o.points[e].x, o.points[(e + 1) % n].x); };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lo(a) < lo(b); });
    std::pair<long, long> first{-1, -1};
    for (size_t s = 0; s < n; ++s)
        for (size_t t = s + 1; t < n && lo(order[t]) <= hi(order[s]); ++t) {
            size_t i = std::min(order[s], order[t]), j = std::max(order[s], order[t]);
            const glm::dvec2 &a = o.points[i], &b = o.points[(i + 1) % n], &c = o.points[j], &d = o.points[(j + 1) % n];
            bool meet;
            if (j == i + 1)  // b == c: they meet elsewhere only by folding back
                meet = orient2d(a, b, d) == 0 && glm::dot(b - a, d - b) < 0;
            else if (i == 0 && j == n - 1)  // d == a
                meet = orient2d(c, a, b) == 0 && glm::dot(a - c, b - a) < 0;
            else
                meet = segmentsMeet(a, b, c, d);
            if (meet && (first.first < 0 || std::make_pair(long(i), long(j)) < first)) first = {long(i), long(j)};
        }
    return first;
}

bool inClosedTriangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

// Ear clipping of a simple counter-clockwise outline. A corner is an ear when it turns left and
// no other corner lies in or on its triangle; only corners that do not turn left can (a convex
// corner never becomes reflex as ears are cut), so only those are tested. An InputError starting
// with `where` when no ear is left before the end (an outline the exact tests find degenerate),
// or when the tests exceed their bound (a second or so: a hostile outline cannot hang the reader).
void clipEars(const Outline& o, std::vector<std::array<uint32_t, 3>>& triangles, const std::string& where) {
    constexpr size_t kMaxTests = size_t(1) << 28;
    size_t tests = 0;
    const size_t n = o.points.size();
    std::vector<size_t> prev(n), next(n);
    std::vector<char> removed(n, 0), reflex(n, 0);
    std::vector<size_t> reflexList;
    for (size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    auto turn = [&](size_t i) { return orient2d(o.points[prev[i]], o.points[i], o.points[next[i]]); };
    for (size_t i = 0; i < n; ++i)
        if (turn(i) <= 0) {
            reflex[i] = 1;
            reflexList.push_back(i);
        }
    auto isEar = [&](size_t i) {
        if (reflex[i]) return false;
        const size_t a = prev[i], c = next[i];
        tests += reflexList.size();
        if (tests > kMaxTests)
            throw InputError(where + "the concave polygon of " + std::to_string(n) +
                             " corners is too intricate to clip into ears within the reader's bound");
        for (size_t r : reflexList)
            if (!removed[r] && reflex[r] && r != a && r != c &&
                inClosedTriangle(o.points[r], o.points[a], o.points[i], o.points[c]))
                return false;
        return true;
    };
    size_t left = n, cur = 0, tried = 0;
    while (left > 3) {
        if (!isEar(cur)) {
            cur = next[cur];
            if (++tried > left)
                throw InputError(where + "the polygon is too degenerate to triangulate (no ear left to clip)");
            continue;
        }
        const size_t a = prev[cur], c = next[cur];
        triangles.push_back({o.vertex[a], o.vertex[cur], o.vertex[c]});
        removed[cur] = 1;
        next[a] = c;
        prev[c] = a;
        --left;
        for (size_t k : {a, c})
            if (reflex[k] && turn(k) > 0) reflex[k] = 0;
        cur = c;
        tried = 0;
    }
    if (turn(cur) > 0) triangles.push_back({o.vertex[prev[cur]], o.vertex[cur], o.vertex[next[cur]]});
}

}  // namespace

void triangulatePolygon(const std::vector<glm::dvec3>& positions, const std::vector<uint32_t>& polygon,
                        std::vector<std::array<uint32_t, 3>>& triangles, const std::string& where) {
    auto fan = [&] {
        for (size_t k = 1; k + 1 < polygon.size(); ++k) triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
    };
    if (polygon.size() == 3) return fan();
    const glm::dvec3 n = newellNormal(positions, polygon);
    // A polygon with a coordinate that is not finite is fanned for validation to name; one with
    // no area (its corners on a line) is fanned into triangles of no area, which the repair drops.
    if (!std::isfinite(n.x + n.y + n.z) || n == glm::dvec3(0)) return fan();
    const Outline o = project(positions, polygon, n);
    if (o.points.size() < 3 || convex(o)) return fan();
    if (o.points.size() > kMaxConcavePolygonCorners)
        throw InputError(where + "concave polygon of " + std::to_string(o.points.size()) + " corners (at most " +
                         std::to_string(kMaxConcavePolygonCorners) + " are triangulated)");
    const auto [i, j] = selfContact(o);
    if (i >= 0)
        throw InputError(where + "the polygon's outline crosses or touches itself (its edges " + std::to_string(i + 1) +
                         " and " + std::to_string(j + 1) + "), so it has no triangulation without overlap");
    clipEars(o, triangles, where);
}

}  // namespace tetglow
