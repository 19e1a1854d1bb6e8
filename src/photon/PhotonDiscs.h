// The beam radiance estimate's acceleration structure (Jarosz, Zwicker, Jensen 2008, "The Beam
// Radiance Estimate for Volumetric Photon Mapping"): a BVH over the photons' spheres of radius
// Photon::radius, to find every photon disc (centred on the photon, facing the ray) that a ray
// segment crosses.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "photon/Photon.h"

namespace tetglow {

class PhotonDiscs {
public:
    // Photons with radius <= 0 have no disc and are left out. The build is deterministic.
    explicit PhotonDiscs(std::span<const Photon> photons);

    // Calls visit(uint32_t index, double t, double distance2) for each photon whose disc the ray
    // o + t d (d unit) crosses with tmin <= t <= tmax: t = dot(photon - o, d) is the closest
    // approach, distance2 < radius^2 the squared distance from the photon to the line.
    // `index` is the photon's position in the span given to the constructor.
    template <class F>
    void query(const glm::dvec3& o, const glm::dvec3& d, double tmin, double tmax, F&& visit) const;

    size_t size() const { return discs_.size(); }  // the photons with a disc
    size_t bytes() const;                          // heap memory held

private:
    struct Node {  // 32 bytes; the left child of an inner node follows it
        glm::vec3 lo;
        uint32_t next;  // leaf: first disc; inner node: right child
        glm::vec3 hi;
        uint32_t count;  // discs in a leaf, 0 for an inner node
    };
    static_assert(sizeof(Node) == 32);
    struct Disc {
        glm::vec3 position;
        float radius;
    };
    static constexpr int kMaxDepth = 64;  // median splits: depth <= log2(#discs)

    std::vector<Node> nodes_;       // depth first, root at 0
    std::vector<Disc> discs_;       // in leaf order
    std::vector<uint32_t> photon_;  // each disc's photon index

    uint32_t build(std::vector<uint32_t>& order, uint32_t begin, uint32_t end, std::span<const Photon> photons);
};

template <class F>
void PhotonDiscs::query(const glm::dvec3& o, const glm::dvec3& d, double tmin, double tmax, F&& visit) const {
    if (nodes_.empty() || !(tmin <= tmax)) return;
    const glm::dvec3 inv = 1.0 / d;  // +-inf along an axis-parallel direction
    uint32_t stack[kMaxDepth];
    int top = 0;
    uint32_t i = 0;
    for (;;) {
        const Node& n = nodes_[i];
        // Slab test. An axis d is parallel to gives +-inf, or NaN where o lies on a box plane:
        // each sphere lies strictly inside its padded box, so such a line misses them all and
        // whatever the NaN decides is right.
        const glm::dvec3 a = (glm::dvec3(n.lo) - o) * inv, b = (glm::dvec3(n.hi) - o) * inv;
        double t0 = tmin, t1 = tmax;
        for (int axis = 0; axis < 3; ++axis) {
            t0 = std::max(t0, std::min(a[axis], b[axis]));
            t1 = std::min(t1, std::max(a[axis], b[axis]));
        }
        if (t0 <= t1) {
            if (n.count == 0) {
                stack[top++] = n.next;
                i = i + 1;
                continue;
            }
            for (uint32_t k = n.next; k < n.next + n.count; ++k) {
                const glm::dvec3 v = glm::dvec3(discs_[k].position) - o;
                const double t = glm::dot(v, d);
                if (t < tmin || t > tmax) continue;
                const glm::dvec3 w = v - t * d;
                const double distance2 = glm::dot(w, w), r = discs_[k].radius;
                if (distance2 < r * r) visit(photon_[k], t, distance2);
            }
        }
        if (top == 0) return;
        i = stack[--top];
    }
}

}  // namespace tetglow
