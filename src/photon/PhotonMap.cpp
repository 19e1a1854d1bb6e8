#include "photon/PhotonMap.h"

#include <algorithm>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <nanoflann.hpp>

namespace tetglow {
namespace {

// nanoflann's view of the photon positions.
struct Cloud {
    const std::vector<Photon>& photons;
    size_t kdtree_get_point_count() const { return photons.size(); }
    float kdtree_get_pt(uint32_t i, size_t axis) const { return photons[i].position[int(axis)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Cloud, float, uint32_t>, Cloud, 3,
                                                 uint32_t>;

// The result sets write Neighbours straight into the caller's vector. nanoflann offers a
// point only when its distance2 < worstDist() as read on entering the leaf, which enforces
// the radius bounds; a k-NN set that fills up within a leaf must still check.
class KnnResult {
public:
    KnnResult(std::vector<Neighbour>& out, size_t k, float maxDistance2) : out_(out), k_(k), worst_(maxDistance2) {
        out_.clear();
        out_.reserve(k);
    }
    float worstDist() const { return worst_; }
    bool full() const { return out_.size() == k_; }
    bool addPoint(float distance2, uint32_t index) {
        if (distance2 >= worst_) return true;
        if (full()) out_.pop_back();
        const auto at = std::upper_bound(out_.begin(), out_.end(), distance2,
                                         [](float d2, const Neighbour& n) { return d2 < n.distance2; });
        out_.insert(at, {index, distance2});
        if (full()) worst_ = out_.back().distance2;
        return true;
    }

private:
    std::vector<Neighbour>& out_;
    size_t k_;
    float worst_;
};

class RadiusResult {
public:
    RadiusResult(std::vector<Neighbour>& out, float radius2) : out_(out), radius2_(radius2) { out_.clear(); }
    float worstDist() const { return radius2_; }
    bool full() const { return true; }
    bool addPoint(float distance2, uint32_t index) {
        out_.push_back({index, distance2});
        return true;
    }

private:
    std::vector<Neighbour>& out_;
    float radius2_;
};

}  // namespace

struct PhotonMap::Index {
    std::vector<Photon> photons;
    Cloud cloud{photons};
    Tree tree{3, cloud};  // nanoflann's default leaf size (10) measured as good as 20 or 32
    size_t treeBytes = tree.usedMemory(tree);

    explicit Index(std::vector<Photon> p) : photons(std::move(p)) {}

    template <class Result>
    void search(const glm::vec3& p, Result& result) const {
        tree.findNeighbors(result, &p.x, nanoflann::SearchParams());
    }
};

PhotonMap::PhotonMap(std::vector<Photon> photons) : index_(std::make_unique<Index>(std::move(photons))) {}
PhotonMap::~PhotonMap() = default;
PhotonMap::PhotonMap(PhotonMap&&) noexcept = default;
PhotonMap& PhotonMap::operator=(PhotonMap&&) noexcept = default;

const std::vector<Photon>& PhotonMap::photons() const { return index_->photons; }

size_t PhotonMap::bytes() const { return index_->photons.capacity() * sizeof(Photon) + index_->treeBytes; }

void PhotonMap::knn(const glm::vec3& p, int k, std::vector<Neighbour>& out, float maxDistance2) const {
    KnnResult result(out, std::min(size_t(std::max(k, 0)), size()), maxDistance2);
    if (!result.full()) index_->search(p, result);
}

void PhotonMap::withinRadius(const glm::vec3& p, float radius, std::vector<Neighbour>& out) const {
    RadiusResult result(out, radius * radius);
    index_->search(p, result);
    std::sort(out.begin(), out.end(), [](const Neighbour& a, const Neighbour& b) {
        return a.distance2 != b.distance2 ? a.distance2 < b.distance2 : a.index < b.index;
    });
}

void PhotonMap::assignRadii(int k, float maxRadius, float scale) {
    if (k < 1) throw std::invalid_argument("PhotonMap::assignRadii: k must be at least 1");
    std::vector<Photon>& photons = index_->photons;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, photons.size()), [&](const tbb::blocked_range<size_t>& range) {
        std::vector<Neighbour> near;
        for (size_t i = range.begin(); i != range.end(); ++i) {
            // The photon finds itself at distance 0, so its k-th other photon is entry k.
            knn(photons[i].position, k + 1, near, maxRadius * maxRadius);
            photons[i].radius = scale * (near.size() > size_t(k) ? std::sqrt(near[size_t(k)].distance2) : maxRadius);
        }
    });
}

void PhotonMap::setRadii(float radius) {
    for (Photon& p : index_->photons) p.radius = radius;
}

}  // namespace tetglow
