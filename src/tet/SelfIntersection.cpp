#include "tet/SelfIntersection.h"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "tet/Predicates.h"

namespace tetglow {
namespace {

using Tri = std::array<glm::dvec3, 3>;

int sign(double v) { return (v > 0) - (v < 0); }

// Signs that are both non-zero and equal: the two points lie strictly on one side.
bool strictlySameSide(int a, int b) { return a * b > 0; }

// No two of the signs strictly opposite: a point (or line) on the closed inner side of all three
// edges of a triangle.
bool noneOpposite(int a, int b, int c) { return a * b >= 0 && b * c >= 0 && c * a >= 0; }

// ---- Coplanar case, in the projection that drops one axis --------------------------------------

// Any axis whose projection keeps the triangle non-degenerate works. orient2d's sign is exact, so
// the largest of the three returned determinants (the normal's components) is never zero.
int dropAxis(const Tri& t) {
    int best = 0;
    double bestArea = -1;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const double area = std::abs(orient2d({t[0][u], t[0][v]}, {t[1][u], t[1][v]}, {t[2][u], t[2][v]}));
        if (area > bestArea) {
            best = axis;
            bestArea = area;
        }
    }
    return best;
}

glm::dvec2 project(const glm::dvec3& p, int axis) { return {p[(axis + 1) % 3], p[(axis + 2) % 3]}; }

bool inTriangle2d(const glm::dvec2& p, const std::array<glm::dvec2, 3>& t) {
    return noneOpposite(sign(orient2d(t[0], t[1], p)), sign(orient2d(t[1], t[2], p)), sign(orient2d(t[2], t[0], p)));
}

// Closed segments that cross or touch, unless all four points are collinear: segmentHitsTriangle2d
// needs no collinear case, since a segment overlapping an edge along its line either has an
// endpoint inside the triangle or contains that edge's endpoints and so crosses the other edges.
bool crossNonCollinear(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b) {
    const int pa = sign(orient2d(p, q, a)), pb = sign(orient2d(p, q, b));
    const int ap = sign(orient2d(a, b, p)), aq = sign(orient2d(a, b, q));
    if (pa == 0 && pb == 0 && ap == 0 && aq == 0) return false;
    return !strictlySameSide(pa, pb) && !strictlySameSide(ap, aq);
}

bool segmentHitsTriangle2d(const glm::dvec3& p, const glm::dvec3& q, const Tri& t) {
    const int axis = dropAxis(t);
    const std::array<glm::dvec2, 3> t2{project(t[0], axis), project(t[1], axis), project(t[2], axis)};
    const glm::dvec2 p2 = project(p, axis), q2 = project(q, axis);
    if (inTriangle2d(p2, t2) || inTriangle2d(q2, t2)) return true;
    for (int k = 0; k < 3; ++k)
        if (crossNonCollinear(p2, q2, t2[k], t2[(k + 1) % 3])) return true;
    return false;
}

// ---- Segment against closed triangle ------------------------------------------------------------

// sp, sq: signs of orient3d(t, p) and orient3d(t, q), which callers have at hand already.
bool segmentHitsTriangle(const glm::dvec3& p, const glm::dvec3& q, int sp, int sq, const Tri& t) {
    if (strictlySameSide(sp, sq)) return false;
    if (sp == 0 && sq == 0) return segmentHitsTriangle2d(p, q, t);
    // The segment meets the plane in one point; it lies in the triangle iff the line passes no
    // edge on the wrong side (the Pluecker signs of the line against the three edges agree).
    return noneOpposite(sign(orient3d(p, q, t[0], t[1])), sign(orient3d(p, q, t[1], t[2])),
                        sign(orient3d(p, q, t[2], t[0])));
}

int side(const Tri& t, const glm::dvec3& p) { return sign(orient3d(t[0], t[1], t[2], p)); }

// The sides of t's corners against the plane of other, and whether they are all strictly on one.
std::array<int, 3> sides(const Tri& other, const Tri& t) {
    return {side(other, t[0]), side(other, t[1]), side(other, t[2])};
}
bool strictlyOneSide(const std::array<int, 3>& s) {
    return strictlySameSide(s[0], s[1]) && strictlySameSide(s[1], s[2]);
}

// Closed triangles meet iff an edge of one meets the other: the boundary of their (convex)
// intersection lies on their edges.
bool trianglesIntersect(const Tri& a, const Tri& b) {
    const auto sa = sides(b, a);
    if (strictlyOneSide(sa)) return false;
    const auto sb = sides(a, b);
    if (strictlyOneSide(sb)) return false;
    for (int k = 0; k < 3; ++k) {
        const int l = (k + 1) % 3;
        if (segmentHitsTriangle(a[k], a[l], sa[k], sa[l], b) || segmentHitsTriangle(b[k], b[l], sb[k], sb[l], a))
            return true;
    }
    return false;
}

// Triangles a and b share exactly vertex a[0] == b[0]. They meet elsewhere iff the opposite edge
// of one meets the other: walking from the shared vertex into the intersection, the first of the
// two triangles to end does so on its opposite edge, inside the other triangle.
bool meetBeyondVertex(const Tri& a, const Tri& b) {
    return segmentHitsTriangle(a[1], a[2], side(b, a[1]), side(b, a[2]), b) ||
           segmentHitsTriangle(b[1], b[2], side(a, b[1]), side(a, b[2]), a);
}

// Triangles a and b share edge a[0]a[1] == b[0]b[1]. They meet beyond it only when coplanar and
// folded onto each other: both opposite vertices on the same side of the edge.
bool foldOver(const Tri& a, const Tri& b) {
    if (side(a, b[2]) != 0) return false;
    const int axis = dropAxis(a);
    const glm::dvec2 p = project(a[0], axis), q = project(a[1], axis);
    return sign(orient2d(p, q, project(a[2], axis))) == sign(orient2d(p, q, project(b[2], axis)));
}

// Whether triangles i and j meet other than along the corners they share. Their corners are
// reordered so that the shared ones come first, in the same order.
bool intersectBeyondShared(const TriangleMesh& mesh, uint32_t i, uint32_t j) {
    auto ia = mesh.triangles[i], ib = mesh.triangles[j];
    int shared = 0;
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            if (ia[k] == ib[l]) {
                std::swap(ia[shared], ia[k]);
                std::swap(ib[shared], ib[l]);
                ++shared;
                break;
            }
    const auto corners = [&](const std::array<uint32_t, 3>& idx) {
        return Tri{mesh.positions[idx[0]], mesh.positions[idx[1]], mesh.positions[idx[2]]};
    };
    const Tri a = corners(ia), b = corners(ib);
    switch (shared) {
        case 0: return trianglesIntersect(a, b);
        case 1: return meetBeyondVertex(a, b);
        case 2: return foldOver(a, b);
        default: return true;  // the same triangle twice
    }
}

// ---- Broad phase: a uniform grid over the triangles' bounding boxes -----------------------------

struct Box {
    glm::dvec3 lo, hi;
    bool overlaps(const Box& o) const { return glm::all(glm::lessThanEqual(glm::max(lo, o.lo), glm::min(hi, o.hi))); }
};

// Boxes are the exact min/max of the corners, and cellOf is monotone, so every pair of touching
// boxes shares the cell holding the low corner of their overlap: no padding needed.
struct Grid {
    glm::dvec3 origin, invCell;
    glm::ivec3 dims;
    std::vector<uint32_t> start, items;  // CSR: the triangles of cell c are items[start[c]..start[c+1])

    glm::ivec3 cellOf(const glm::dvec3& p) const {
        glm::ivec3 c;
        for (int a = 0; a < 3; ++a)
            c[a] = static_cast<int>(std::clamp((p[a] - origin[a]) * invCell[a], 0.0, dims[a] - 1.0));
        return c;
    }
    size_t index(const glm::ivec3& c) const { return (static_cast<size_t>(c.z) * dims.y + c.y) * dims.x + c.x; }
};

template <class F>
void forCells(const Grid& grid, const Box& box, F&& f) {
    const glm::ivec3 lo = grid.cellOf(box.lo), hi = grid.cellOf(box.hi);
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) f(grid.index({x, y, z}));
}

// Per axis, cells about as long as the average triangle's box, so that long slivers do not share
// one huge cell; but no finer than sqrt(n) across, what a surface of n triangles needs, where flat
// axis-aligned triangles have no extent (DBL_MIN keeps a mesh with no extent on an axis finite).
// At most about two cells per triangle.
Grid buildGrid(const std::vector<Box>& boxes) {
    Box all{glm::dvec3(1e300), glm::dvec3(-1e300)};
    glm::dvec3 mean(0);
    for (const Box& b : boxes) {
        all = {glm::min(all.lo, b.lo), glm::max(all.hi, b.hi)};
        mean += (b.hi - b.lo) / static_cast<double>(boxes.size());
    }
    const glm::dvec3 extent = all.hi - all.lo;
    glm::dvec3 cell = glm::max(glm::max(mean, extent / std::sqrt(boxes.size())), glm::dvec3(DBL_MIN));
    const auto cellsPerAxis = [&] { return glm::max(glm::dvec3(1), glm::ceil(extent / cell)); };
    for (glm::dvec3 n = cellsPerAxis(); n.x * n.y * n.z > 2.0 * boxes.size() + 64; n = cellsPerAxis()) cell *= 1.25;

    Grid grid{all.lo, 1.0 / cell, glm::ivec3(cellsPerAxis()), {}, {}};
    grid.start.assign(static_cast<size_t>(grid.dims.x) * grid.dims.y * grid.dims.z + 1, 0);
    for (const Box& b : boxes) forCells(grid, b, [&](size_t c) { ++grid.start[c + 1]; });
    for (size_t c = 1; c < grid.start.size(); ++c) grid.start[c] += grid.start[c - 1];
    grid.items.resize(grid.start.back());
    std::vector<uint32_t> fill(grid.start.begin(), grid.start.end() - 1);
    for (uint32_t t = 0; t < boxes.size(); ++t) forCells(grid, boxes[t], [&](size_t c) { grid.items[fill[c]++] = t; });
    return grid;
}

// The triangles' boxes and the grid over them.
struct BroadPhase {
    std::vector<Box> boxes;
    Grid grid;

    explicit BroadPhase(const TriangleMesh& mesh) : boxes(mesh.triangles.size()) {
        for (uint32_t t = 0; t < boxes.size(); ++t) {
            const glm::dvec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
            boxes[t] = {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
        }
        grid = buildGrid(boxes);
    }
    // Calls f(j) for every j > i whose box touches triangle i's, once each.
    template <class F>
    void forCandidates(uint32_t i, F&& f) const {
        forCells(grid, boxes[i], [&](size_t c) {
            for (uint32_t k = grid.start[c]; k < grid.start[c + 1]; ++k) {
                const uint32_t j = grid.items[k];
                // Each pair is visited once, in the cell that holds the low corner of its overlap.
                if (j > i && boxes[i].overlaps(boxes[j]) &&
                    grid.index(grid.cellOf(glm::max(boxes[i].lo, boxes[j].lo))) == c)
                    f(j);
            }
        });
    }
};

}  // namespace

bool segmentMeetsTriangle(const glm::dvec3& p, const glm::dvec3& q, const Tri& triangle) {
    return segmentHitsTriangle(p, q, side(triangle, p), side(triangle, q), triangle);
}

std::vector<std::pair<uint32_t, uint32_t>> findSelfIntersections(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) return {};
    const BroadPhase broad(mesh);
    std::vector<std::vector<uint32_t>> partners(mesh.triangles.size());
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, static_cast<uint32_t>(partners.size())), [&](const auto& rows) {
        for (uint32_t i = rows.begin(); i != rows.end(); ++i)
            broad.forCandidates(i, [&](uint32_t j) {
                if (intersectBeyondShared(mesh, i, j)) partners[i].push_back(j);
            });
    });
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t i = 0; i < partners.size(); ++i) {
        std::sort(partners[i].begin(), partners[i].end());
        for (uint32_t j : partners[i]) pairs.push_back({i, j});
    }
    return pairs;
}

std::optional<std::pair<uint32_t, uint32_t>> findSelfIntersection(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) return std::nullopt;
    const BroadPhase broad(mesh);
    // The lowest j > i whose triangle meets triangle i.
    const auto firstPartner = [&](uint32_t i) {
        std::optional<uint32_t> first;
        broad.forCandidates(i, [&](uint32_t j) {
            if ((!first || j < *first) && intersectBeyondShared(mesh, i, j)) first = j;
        });
        return first;
    };
    // Rows in parallel. The lowest hit so far, keyed (row, partner), spares the rows after it, and
    // every row before the final one is searched, so the answer does not depend on scheduling.
    constexpr uint64_t none = ~uint64_t{0};
    std::atomic<uint64_t> best{none};
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, static_cast<uint32_t>(mesh.triangles.size())),
                      [&](const auto& rows) {
                          for (uint32_t i = rows.begin(); i != rows.end() && i < best.load() >> 32; ++i)
                              if (const auto j = firstPartner(i)) {
                                  const uint64_t key = uint64_t{i} << 32 | *j;
                                  uint64_t seen = best.load();
                                  while (key < seen && !best.compare_exchange_weak(seen, key)) {}
                                  return;
                              }
                      });
    if (best == none) return std::nullopt;
    return std::pair{static_cast<uint32_t>(best >> 32), static_cast<uint32_t>(best)};
}

}  // namespace tetglow
