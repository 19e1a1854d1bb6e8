// A tetrahedralized medium ready for queries: the tets, Embree over their boundary, and a
// coarse grid of start tets for point location.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "tet/SurfaceBVH.h"
#include "tet/TetMesh.h"
#include "tet/TetWalk.h"

namespace tetglow {

class TetTraversal {
public:
    static constexpr int64_t kOutside = -1;  // traverse(): the ray starts outside the medium
    static constexpr int64_t kUnknown = -2;  // traverse(): locate the start point first

    explicit TetTraversal(TetMesh mesh);

    const TetMesh& mesh() const { return mesh_; }
    const SurfaceBVH& bvh() const { return bvh_; }
    // Box of the vertices: the surface's, since Steiner points lie inside it.
    const Bounds3& bounds() const { return bounds_; }

    // The tet containing p, or -1 outside the medium. `hint` is a tet near p (along a path, the
    // previous one); without it the grid supplies one. Exact: a visibility walk with exact
    // orientation tests, and where the medium is concave, a line walk with Embree re-entry.
    int64_t locate(const glm::dvec3& p, int64_t hint = -1) const;

    // Tet t holds p, its faces included (exact).
    bool contains(uint32_t t, const glm::dvec3& p) const;

    // Visits, in order, the segments of the ray inside the medium within [tmin, tmax], clipped,
    // crossing from region to region through their interfaces (the segment's tet tells the region);
    // the visitor returns false to stop early. `start` is the tet holding ray.at(tmin), or
    // kOutside / kUnknown. Returns false only if a walk was lost (exact predicates prevent it).
    template <class Visitor>
    bool traverse(const Ray& ray, double tmin, double tmax, Visitor&& visit, int64_t start = kUnknown) const;

    // The ray's first entry into the medium with tnear <= t <= tfar, by the exact tests (as
    // traverse() finds entries: Embree only proposes triangles); its exitT() is the entry's t.
    std::optional<TetWalk> firstEntry(const Ray& ray, double tnear, double tfar) const;

private:
    uint32_t gridTet(const glm::dvec3& p) const;
    // Walks from t towards p; true with t holding p, false when a surface face blocks the way.
    bool visibilityWalk(const glm::dvec3& p, uint32_t& t) const;
    // p strictly on the outer side of face j of tet t (exact).
    bool beyondFace(uint32_t t, int j, const glm::dvec3& p) const;
    int64_t lineLocate(uint32_t from, const glm::dvec3& p) const;
    // The ray's entries into the medium for t >= tnear (up to about tfar), in order, each through its own triangle:
    // those the exact tests find among Embree's candidates and around the candidates they reject.
    std::vector<TetWalk> entriesAlong(const Ray& ray, double tnear, double tfar = INFINITY) const;

    TetMesh mesh_;
    SurfaceBVH bvh_;
    Bounds3 bounds_;  // of the vertices
    glm::dvec3 gridLo_, gridScale_;
    glm::ivec3 gridRes_;
    std::vector<uint32_t> grid_;
};

template <class Visitor>
bool TetTraversal::traverse(const Ray& ray, double tmin, double tmax, Visitor&& visit, int64_t start) const {
    if (start == kUnknown) start = locate(ray.at(tmin));
    double t = tmin;
    std::optional<TetWalk> walk;
    if (start >= 0) walk = TetWalk::start(mesh_, ray, uint32_t(start), tmin);
    // Every decision is the walk's exact one; Embree only proposes where to look. Entries are
    // taken in the order of the exact tests' t, each once: at a vertex where the medium pinches,
    // several share one point, and those that lead straight back out cost nothing.
    std::vector<TetWalk> entries;
    size_t next = 0;
    bool haveEntries = false;
    for (;;) {
        if (walk) {
            for (WalkSegment s; walk->next(s);) {
                if (s.tIn >= tmax) return true;
                if (s.tOut <= t) continue;
                if (!visit(WalkSegment{s.tet, std::max(s.tIn, t), std::min(s.tOut, tmax)})) return true;
            }
            if (walk->lost()) return false;
            if (walk->crossInterface()) continue;  // into the next region, without Embree
            t = std::max(t, walk->exitT());
            if (t >= tmax) return true;  // left the medium at or beyond the end: nothing to ask Embree
        }
        const double tolerance = 1e-9 * (1.0 + std::abs(t));
        if (!haveEntries) {
            entries = entriesAlong(ray, t - tolerance);
            haveEntries = true;
        }
        while (next < entries.size() && entries[next].exitT() < t - tolerance) ++next;
        if (next == entries.size() || entries[next].exitT() > tmax) return true;
        walk = entries[next++];
    }
}

// The parity baseline's inside test, kept as the independent cross-check and as a baseline: count the
// surface crossings of rays from p (odd = inside); with several rays, the majority decides.
// Directions are pseudo-random but fixed for a given p, so results are reproducible.
bool insideByParity(const SurfaceBVH& bvh, const glm::dvec3& p, int rays = 1);

}  // namespace tetglow
