// The volumetric photon map: the stored photons and a k-d tree over their positions
// (nanoflann). Queries are const and safe for any number of concurrent readers.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "photon/Photon.h"

namespace tetglow {

struct Neighbour {
    uint32_t index;   // into PhotonMap::photons()
    float distance2;  // squared distance from the query point
};

class PhotonMap {
public:
    explicit PhotonMap(std::vector<Photon> photons);
    ~PhotonMap();
    PhotonMap(PhotonMap&&) noexcept;
    PhotonMap& operator=(PhotonMap&&) noexcept;

    // The k nearest photons with distance2 < maxDistance2, nearest first (fewer when the map
    // or the ball holds fewer). Equal distances come in no particular order.
    void knn(const glm::vec3& p, int k, std::vector<Neighbour>& out, float maxDistance2 = INFINITY) const;
    // Every photon with distance < radius, nearest first; equal distances by index.
    void withinRadius(const glm::vec3& p, float radius, std::vector<Neighbour>& out) const;

    // Sets each photon's radius to `scale` times the distance of its k-th nearest other photon,
    // or times maxRadius when that is farther (or when there are not k others). In parallel;
    // each radius depends only on the photon set. Not to be run alongside queries.
    void assignRadii(int k, float maxRadius, float scale = 1);
    void setRadii(float radius);  // the same radius for every photon

    const std::vector<Photon>& photons() const;
    size_t size() const { return photons().size(); }
    // Heap memory held: the photon array's capacity plus the tree's nodes and index array
    // (as nanoflann counts them, including its allocator's unused tail).
    size_t bytes() const;

private:
    struct Index;  // keeps nanoflann out of this header; heap-held so moves keep its references valid
    std::unique_ptr<Index> index_;
};

}  // namespace tetglow
