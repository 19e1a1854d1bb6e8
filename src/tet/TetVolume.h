// A tetrahedralized medium ready for queries: the tets, Embree over their boundary, and a
// coarse grid of start tets for point location.
#pragma once
#include <cstdint>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "tet/RayWalk.h"
#include "tet/SurfaceBVH.h"
#include "tet/TetMesh.h"

namespace tetglow {

class TetVolume {
public:
    static constexpr int64_t kOutside = -1;  // traverse(): the ray starts outside the medium
    static constexpr int64_t kUnknown = -2;  // traverse(): locate the start point first

    explicit TetVolume(TetMesh mesh);

    const TetMesh& mesh() const { return mesh_; }
    const SurfaceBVH& bvh() const { return bvh_; }

    // The tet containing p, or -1 outside the medium. `hint` is a tet near p (along a path, the
    // previous one); without it the grid supplies one. Exact: a visibility walk with exact
    // orientation tests, and where the medium is concave, a line walk with Embree re-entry.
    int64_t locate(const glm::dvec3& p, int64_t hint = -1) const;

    // Tet t holds p, its faces included (exact).
    bool contains(uint32_t t, const glm::dvec3& p) const;

    // Visits, in order, the segments of the ray inside the medium within [tmin, tmax], clipped;
    // the visitor returns false to stop early. `start` is the tet holding ray.at(tmin), or
    // kOutside / kUnknown. Returns false only if a walk was lost (exact predicates prevent it).
    template <class Visitor>
    bool traverse(const Ray& ray, double tmin, double tmax, Visitor&& visit, int64_t start = kUnknown) const;

private:
    uint32_t gridTet(const glm::dvec3& p) const;
    // Walks from t towards p; true with t holding p, false when a surface face blocks the way.
    bool visibilityWalk(const glm::dvec3& p, uint32_t& t) const;
    // p strictly on the outer side of face j of tet t (exact).
    bool beyondFace(uint32_t t, int j, const glm::dvec3& p) const;
    // The tet holding p among those sharing a corner with face `face` of `tet`, or -1.
    int64_t locateAroundFace(const glm::dvec3& p, uint32_t tet, int face) const;
    int64_t lineLocate(uint32_t from, const glm::dvec3& p) const;

    TetMesh mesh_;
    SurfaceBVH bvh_;
    double shift_ = 0;  // 1e-9 of the bounding-box diagonal: see traverse()
    glm::dvec3 gridLo_, gridScale_;
    glm::ivec3 gridRes_;
    std::vector<uint32_t> grid_;
};

template <class Visitor>
bool TetVolume::traverse(const Ray& ray, double tmin, double tmax, Visitor&& visit, int64_t start) const {
    if (start == kUnknown) start = locate(ray.at(tmin));
    double t = tmin;
    // Runs one walk; false when the visitor stopped, tmax was reached or the walk was lost.
    auto run = [&](TetWalk& walk) {
        WalkSegment s;
        while (walk.next(s)) {
            if (s.tIn >= tmax) return false;
            if (s.tOut <= t) continue;
            s.tIn = std::max(s.tIn, t), s.tOut = std::min(s.tOut, tmax);
            if (!visit(s)) return false;
        }
        t = std::max(t, walk.exitT());
        return !walk.lost();
    };
    std::optional<TetWalk> walk;
    if (start >= 0) walk = TetWalk::start(mesh_, ray, uint32_t(start), tmin);
    // At a surface vertex or edge that the ray passes exactly through, whether the medium goes
    // on is decided on a line shifted by 1e-9 diagonals (the chord changes by about as much):
    // it re-enters through a triangle around the crossing, or it was never outside, and then
    // the tet holding its point just beyond is around the crossing too.
    auto shiftedRay = [&] {
        // Perpendicular to d in a direction unrelated to the axes (meshes often have vertices
        // in axis-aligned rows); the second vector covers d parallel to the first.
        glm::dvec3 side = glm::cross(ray.d, glm::dvec3(0.5257, 0.6172, 0.5853));
        if (glm::dot(side, side) < 0.01 * glm::dot(ray.d, ray.d)) side = glm::cross(ray.d, glm::dvec3(0.6172, -0.5853, 0.5257));
        return Ray{ray.o + glm::normalize(side) * shift_, ray.d};
    };
    auto resumeBeyond = [&](uint32_t triangle) {
        const double window = 1e-6 * (1 + std::abs(t)), probe = t + shift_ / glm::length(ray.d);
        const Ray shifted = shiftedRay();
        if ((walk = TetWalk::enterNear(mesh_, shifted, triangle, t, t + window))) return true;
        const uint32_t face = mesh_.surfaceFace[triangle];
        const int64_t inside = probe < tmax ? locateAroundFace(shifted.at(probe), face >> 2, face & 3) : -1;
        if (inside >= 0) walk = TetWalk::start(mesh_, shifted, uint32_t(inside), t = probe);
        return inside >= 0;
    };
    // Entries in order along the ray, each tried once.
    std::vector<SurfaceHit> hits;
    size_t next = 0;
    bool haveHits = false;
    const auto tolerance = [&] { return 1e-9 * (1.0 + std::abs(t)); };
    for (size_t round = 0; round <= 2 * mesh_.surface.size(); ++round) {
        if (walk) {
            if (!run(*walk)) return !walk->lost();
            const bool degenerate = walk->exitDegenerate();
            const uint32_t exit = walk->exitTriangle();
            if (!degenerate && (walk = walk->reenter())) continue;
            walk.reset();
            if (degenerate && resumeBeyond(exit)) continue;
        }
        if (!haveHits) hits = bvh_.allHits(ray, std::max(0.0, t - tolerance())), haveHits = true;
        while (next < hits.size() && hits[next].t < t - tolerance()) ++next;
        if (next == hits.size() || hits[next].t > tmax) return true;
        if (!hits[next].entering) {
            // An exit while outside: Embree missed the entry (it can, exactly at a vertex). If
            // the medium is really there just before the exit, walk back to where it began.
            const double tx = hits[next].t, tp = tx - 1e-6 * (tx - t);
            uint32_t tet = mesh_.surfaceFace[hits[next++].triangle] >> 2;  // next to the exit
            // On the shifted line: this one may pass exactly through the vertex Embree missed.
            const Ray shifted = shiftedRay();
            if (!(tp > t) || !visibilityWalk(shifted.at(tp), tet)) continue;
            std::vector<WalkSegment> before;
            TetWalk back = TetWalk::start(mesh_, Ray{shifted.o, -shifted.d}, tet, -tp);
            for (WalkSegment s; back.next(s) && s.tIn < -t;) before.push_back({s.tet, std::max(-s.tOut, t), -s.tIn});
            if (back.lost()) before.clear();
            for (auto it = before.rbegin(); it != before.rend(); ++it) {
                if (it->tIn >= tmax) return true;
                if (!visit(WalkSegment{it->tet, it->tIn, std::min(it->tOut, tmax)})) return true;
            }
            walk = TetWalk::start(mesh_, shifted, tet, t = tp);
            continue;
        }
        TetWalk entry = TetWalk::enter(mesh_, ray, hits[next++].triangle);
        if (!(entry.exited() && entry.steps() == 0)) {
            walk = entry;
        } else if (entry.exitT() > t) {  // touched without entering, by the exact tests
            t = entry.exitT();
            resumeBeyond(entry.exitTriangle());
        }
    }
    return false;
}

// The seed's inside test, kept as the independent cross-check and as a baseline: count the
// surface crossings of rays from p (odd = inside); with several rays, the majority decides.
// Directions are pseudo-random but fixed for a given p, so results are reproducible.
bool insideByParity(const SurfaceBVH& bvh, const glm::dvec3& p, int rays = 1);

}  // namespace tetglow
