#include "tet/TetTraversal.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "tet/Predicates.h"

namespace tetglow {

TetTraversal::TetTraversal(TetMesh mesh) : mesh_(std::move(mesh)), bvh_(mesh_.vertices, mesh_.surface) {
    // Start grid: about two tets per cell; each cell keeps the tet whose centroid is nearest its
    // centre, and empty cells inherit from a neighbour (breadth-first), so every cell has one.
    for (const auto& v : mesh_.vertices) bounds_.extend(v);
    const Bounds3& b = bounds_;
    const glm::dvec3 size = glm::max(b.hi - b.lo, glm::dvec3(1e-30));
    const double cell = std::cbrt(size.x * size.y * size.z * 2.0 / double(mesh_.tets.size()));
    gridRes_ = glm::clamp(glm::ivec3(glm::ceil(size / cell)), glm::ivec3(1), glm::ivec3(256));
    gridLo_ = b.lo;
    gridScale_ = glm::dvec3(gridRes_) / size;
    grid_.assign(size_t(gridRes_.x) * gridRes_.y * gridRes_.z, UINT32_MAX);
    std::vector<double> best(grid_.size(), INFINITY);
    auto index = [&](glm::ivec3 c) { return (size_t(c.z) * gridRes_.y + c.y) * gridRes_.x + c.x; };
    auto cellOf = [&](const glm::dvec3& p) {
        return glm::clamp(glm::ivec3(glm::floor((p - gridLo_) * gridScale_)), glm::ivec3(0), gridRes_ - 1);
    };
    for (uint32_t t = 0; t < mesh_.tets.size(); ++t) {
        const glm::dvec3 c = mesh_.centroid(t);
        const glm::ivec3 cell3 = cellOf(c);
        const glm::dvec3 centre = gridLo_ + (glm::dvec3(cell3) + 0.5) / gridScale_;
        const double d = glm::distance(c, centre);
        const size_t i = index(cell3);
        if (d < best[i]) {
            best[i] = d;
            grid_[i] = t;
        }
    }
    std::deque<glm::ivec3> queue;
    for (int z = 0; z < gridRes_.z; ++z)
        for (int y = 0; y < gridRes_.y; ++y)
            for (int x = 0; x < gridRes_.x; ++x)
                if (grid_[index({x, y, z})] != UINT32_MAX) queue.push_back({x, y, z});
    while (!queue.empty()) {
        const glm::ivec3 c = queue.front();
        queue.pop_front();
        for (int axis = 0; axis < 3; ++axis)
            for (int dir : {-1, 1}) {
                glm::ivec3 n = c;
                n[axis] += dir;
                if (n[axis] < 0 || n[axis] >= gridRes_[axis] || grid_[index(n)] != UINT32_MAX) continue;
                grid_[index(n)] = grid_[index(c)];
                queue.push_back(n);
            }
    }
}

uint32_t TetTraversal::gridTet(const glm::dvec3& p) const {
    const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((p - gridLo_) * gridScale_)), glm::ivec3(0), gridRes_ - 1);
    return grid_[(size_t(c.z) * gridRes_.y + c.y) * gridRes_.x + c.x];
}

int64_t TetTraversal::locate(const glm::dvec3& p, int64_t hint) const {
    // Outside the box (or not a number) is outside, without the walk to the surface and the
    // Embree ray behind it: photons from lights far outside ask this once each.
    if (!bounds_.contains(p)) return -1;
    uint32_t t = hint >= 0 ? uint32_t(hint) : gridTet(p);
    return visibilityWalk(p, t) ? int64_t(t) : lineLocate(t, p);
}

bool TetTraversal::visibilityWalk(const glm::dvec3& p, uint32_t& t) const {
    // Step across a face p lies strictly beyond. The first face tested rotates with the step
    // count, which keeps the walk from cycling in degenerate configurations.
    int came = -1;
    for (size_t step = 0; step <= mesh_.tets.size(); ++step) {
        int beyond = -1;
        for (int k = 0; k < 4 && beyond < 0; ++k) {
            const int j = int(k + step) & 3;
            if (j == came) continue;
            if (beyondFace(t, j, p)) beyond = j;
        }
        if (beyond < 0) return true;
        const int32_t adj = mesh_.adjacency[t][beyond];
        if (TetMesh::isBoundary(adj)) {  // into the next region, or p is outside, or beyond a concavity
            const uint32_t f = mesh_.across(TetMesh::surfaceTriangle(adj), 4 * t + uint32_t(beyond));
            if (f == UINT32_MAX) return false;
            t = f >> 2;
            came = int(f & 3);
            continue;
        }
        t = TetMesh::neighbourTet(adj);
        came = TetMesh::neighbourFace(adj);
    }
    return false;
}

bool TetTraversal::beyondFace(uint32_t t, int j, const glm::dvec3& p) const {
    const auto& v = mesh_.tets[t];
    const int* f = kInwardFace[j];
    return orient3d(mesh_.vertices[v[f[0]]], mesh_.vertices[v[f[1]]], mesh_.vertices[v[f[2]]], p) > 0;
}

bool TetTraversal::contains(uint32_t t, const glm::dvec3& p) const {
    for (int j = 0; j < 4; ++j)
        if (beyondFace(t, j, p)) return false;
    return true;
}

int64_t TetTraversal::lineLocate(uint32_t from, const glm::dvec3& p) const {
    // Walk the segment from a point surely inside (the centroid) to p, re-entering through
    // concavities; p is inside exactly when the medium's segments reach t = 1.
    const glm::dvec3 c = mesh_.centroid(from);
    const Ray ray{c, p - c};
    int64_t found = -1;
    traverse(
        ray, 0.0, 1.0,
        [&](const WalkSegment& s) {
            if (s.tOut >= 1.0) found = s.tet;
            return true;
        },
        from);
    return found;
}

std::vector<TetWalk> TetTraversal::entriesAlong(const Ray& ray, double tnear, double tfar) const {
    std::vector<TetWalk> entries;
    for (const SurfaceHit& c : bvh_.candidates(ray, tnear, tfar)) TetWalk::entriesNear(mesh_, ray, c.triangle, entries);
    // Around neighbouring candidates, and from a candidate Embree reports twice, the same entry is
    // found twice, with the same t: ordered by (t, triangle), the copies are adjacent.
    std::sort(entries.begin(), entries.end(), [](const TetWalk& a, const TetWalk& b) {
        return a.exitT() < b.exitT() || (a.exitT() == b.exitT() && a.entryTriangle() < b.entryTriangle());
    });
    entries.erase(
        std::unique(entries.begin(), entries.end(),
                    [](const TetWalk& a, const TetWalk& b) { return a.entryTriangle() == b.entryTriangle(); }),
        entries.end());
    return entries;
}

std::optional<TetWalk> TetTraversal::firstEntry(const Ray& ray, double tnear, double tfar) const {
    // The first by (t, triangle), as entriesAlong orders them; the search ends past it.
    std::optional<TetWalk> first;
    std::vector<TetWalk> near;
    bvh_.visitCandidates(ray, tnear, tfar, [&](const SurfaceHit& c) {
        near.clear();
        TetWalk::entriesNear(mesh_, ray, c.triangle, near);
        for (const TetWalk& w : near)
            if (w.exitT() >= tnear && w.exitT() <= tfar &&
                (!first || w.exitT() < first->exitT() ||
                 (w.exitT() == first->exitT() && w.entryTriangle() < first->entryTriangle())))
                first = w;
        return first ? first->exitT() : INFINITY;
    });
    return first;
}

namespace {

uint64_t splitmix64(uint64_t& state) {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace

bool insideByParity(const SurfaceBVH& bvh, const glm::dvec3& p, int rays) {
    uint64_t state = 0;
    for (int k = 0; k < 3; ++k) {
        uint64_t bits;
        std::memcpy(&bits, &p[k], sizeof bits);
        state ^= bits + 0x9e3779b97f4a7c15ull + (state << 6) + (state >> 2);
    }
    int votes = 0;
    for (int r = 0; r < rays; ++r) {
        const double z = 2.0 * double(splitmix64(state) >> 11) * 0x1.0p-53 - 1.0;
        const double phi = 2.0 * M_PI * double(splitmix64(state) >> 11) * 0x1.0p-53;
        const double s = std::sqrt(std::max(0.0, 1 - z * z));
        votes += bvh.crossings(Ray{p, {s * std::cos(phi), s * std::sin(phi), z}}) & 1;
    }
    return 2 * votes > rays;
}

}  // namespace tetglow
