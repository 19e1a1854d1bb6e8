// Embree's BVH over a closed surface: entry points into the medium, re-entry for concave
// shapes, and the crossing counts of the parity test.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "base/Ray.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

struct SurfaceHit {
    double t;
    uint32_t triangle;
    bool entering;  // the ray crosses from outside to inside (against the outward normal)
};

enum class Facing { Any, Entering };

class SurfaceBVH {
public:
    SurfaceBVH(const std::vector<glm::dvec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles);
    ~SurfaceBVH();
    SurfaceBVH(const SurfaceBVH&) = delete;
    SurfaceBVH& operator=(const SurfaceBVH&) = delete;

    // Closest hit with t in [tnear, tfar] of the given facing.
    std::optional<SurfaceHit> intersect(const Ray& ray, double tnear, double tfar, Facing facing = Facing::Any) const;
    // Every triangle the ray crosses for t > tnear, sorted by t (one traversal).
    std::vector<SurfaceHit> allHits(const Ray& ray, double tnear = 0) const;
    // How many triangles the ray crosses for t > 0 (one traversal): the parity test's count.
    int crossings(const Ray& ray) const;
    // Every triangle the ray may cross for tnear <= t <= tfar, in no order and possibly twice, a superset
    // for exact tests to decide (the caller orders what they accept): Embree over the triangles grown in their planes
    // by a margin far above its float error, so that a crossing exactly through an edge or a vertex, which Embree can
    // miss on the triangles themselves, is never left out.
    std::vector<SurfaceHit> candidates(const Ray& ray, double tnear = 0, double tfar = INFINITY) const;
    // The same candidates, each passed to visit(hit) as Embree finds it, in no order; visit returns the t past
    // which it needs none (INFINITY: it needs all), and the traversal stops looking a margin beyond that, and an
    // eighth of the way from tnear further (where Embree's float t of a triangle nearly parallel to the ray may
    // land): every triangle crossed before it is still seen, and the rest of the ray is not searched.
    template <class Visit>
    void visitCandidates(const Ray& ray, double tnear, double tfar, Visit&& visit) const {
        visitCandidates(ray, tnear, tfar, &visit, &callVisit<std::remove_reference_t<Visit>>);
    }

    const glm::dvec3& normal(uint32_t triangle) const { return normals_[triangle]; }  // outward, not unit
    // The ray parameter of the triangle's plane, in double precision.
    double refine(const Ray& ray, uint32_t triangle, float embreeT) const;

private:
    using CandidateVisit = double (*)(void* visit, const SurfaceHit& hit);
    // Calls the visitor of type V behind `visit`: what Embree's filter, a C callback, can hold.
    template <class V>
    static double callVisit(void* visit, const SurfaceHit& hit) {
        return (*static_cast<V*>(visit))(hit);
    }
    void visitCandidates(const Ray& ray, double tnear, double tfar, void* visit, CandidateVisit call) const;

    RTCScene scene_ = nullptr, grown_ = nullptr;
    std::vector<glm::dvec3> normals_, corners_;
    Bounds3 grownBounds_;
    double margin_ = 0;  // how far each triangle was grown
};

// Embree traversals this thread has made through any SurfaceBVH: shows that a walk needs none.
uint64_t surfaceQueries();

RTCDevice embreeDevice();
// Adds the triangles to `scene` as one Embree geometry (positions in float) and returns its id.
unsigned attachTriangles(RTCScene scene, const std::vector<glm::dvec3>& positions,
                         const std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace tetglow
