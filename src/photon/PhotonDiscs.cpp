#include "photon/PhotonDiscs.h"

#include <cmath>
#include <limits>

#include <glm/common.hpp>

namespace tetglow {
namespace {

constexpr uint32_t kLeafSize = 8;  // beam benchmark: 8 to 12 beat 4 by 20%, 2 by 40%

// The sphere's box, one float step wider than rounded: the query tests in double, and a
// point strictly inside the sphere must stay strictly inside the box.
void sphereBox(const Photon& p, glm::vec3& lo, glm::vec3& hi) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::nextafter(p.position[a] - p.radius, -inf);
        hi[a] = std::nextafter(p.position[a] + p.radius, inf);
    }
}

}  // namespace

PhotonDiscs::PhotonDiscs(std::span<const Photon> photons) {
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < photons.size(); ++i)
        if (photons[i].radius > 0) order.push_back(i);
    if (order.empty()) return;
    discs_.reserve(order.size());
    photon_.reserve(order.size());
    build(order, 0, uint32_t(order.size()), photons);
}

// Median split on the longest axis of the photon positions' box. A total order (ties by
// index) makes the tree independent of how nth_element breaks ties.
uint32_t PhotonDiscs::build(std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                            std::span<const Photon> photons) {
    const uint32_t node = uint32_t(nodes_.size());
    nodes_.push_back({});
    glm::vec3 lo(INFINITY), hi(-INFINITY), centreLo(INFINITY), centreHi(-INFINITY);
    for (uint32_t i = begin; i < end; ++i) {
        const Photon& p = photons[order[i]];
        glm::vec3 l, h;
        sphereBox(p, l, h);
        lo = glm::min(lo, l);
        hi = glm::max(hi, h);
        centreLo = glm::min(centreLo, p.position);
        centreHi = glm::max(centreHi, p.position);
    }
    nodes_[node].lo = lo;
    nodes_[node].hi = hi;
    if (end - begin <= kLeafSize) {
        nodes_[node].next = uint32_t(discs_.size());
        nodes_[node].count = end - begin;
        for (uint32_t i = begin; i < end; ++i) {
            const Photon& p = photons[order[i]];
            discs_.push_back({p.position, p.radius});
            photon_.push_back(order[i]);
        }
        return node;
    }
    const glm::vec3 extent = centreHi - centreLo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](uint32_t a, uint32_t b) {
        const float pa = photons[a].position[axis], pb = photons[b].position[axis];
        return pa != pb ? pa < pb : a < b;
    });
    build(order, begin, mid, photons);
    const uint32_t right = build(order, mid, end, photons);
    nodes_[node].next = right;
    nodes_[node].count = 0;
    return node;
}

size_t PhotonDiscs::bytes() const {
    return nodes_.capacity() * sizeof(Node) + discs_.capacity() * sizeof(Disc) + photon_.capacity() * sizeof(uint32_t);
}

}  // namespace tetglow
