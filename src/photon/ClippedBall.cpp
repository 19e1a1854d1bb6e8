#include "photon/ClippedBall.h"

#include <algorithm>
#include <cmath>

#include "sampling/Sampling.h"

namespace tetglow {

ClippedBall::ClippedBall(const SurfaceBVH& boundary) : boundary_(boundary) {
    // Spherical Fibonacci points: equal areas, no clustering at the poles.
    const double golden = kPi * (3 - std::sqrt(5.0));
    for (int i = 0; i < kDirections; ++i) {
        const double z = 1 - (2 * i + 1.0) / kDirections, r = std::sqrt(1 - z * z);
        directions_[i] = {r * std::cos(golden * i), r * std::sin(golden * i), z};
    }
}

double ClippedBall::inside(const glm::dvec3& p, double r) const {
    double sum = 0;
    for (const glm::dvec3& d : directions_) {
        const auto hit = boundary_.intersect(Ray{p, d}, 0, r);
        const double reach = hit ? hit->t : r;
        sum += reach * reach * reach;
    }
    return 4 * kPi / kDirections * sum / 3;
}

}  // namespace tetglow
