#include "photon/PhotonChoice.h"

#include <cmath>

namespace tetglow {

namespace {

// Sums over passes 0 .. passes - 1 of 1 / (radius factor)^dim and of the radius factor, the
// factor's dim-th power shrinking by (i + alpha) / (i + 1) from pass i to i + 1.
struct ShrinkSums {
    double inverseVolume = 0, radius = 0;
};

template <class Visit>
void forPasses(const KernelShrink& shrink, uint64_t passes, Visit visit) {
    ShrinkSums sums;
    double volume = 1;  // the radius factor to the dim-th power
    for (uint64_t i = 0; i < passes; ++i) {
        if (i > 0) volume *= (i + shrink.alpha) / (i + 1);
        sums.inverseVolume += 1 / volume;
        sums.radius += std::pow(volume, 1.0 / shrink.dim);
        if (!visit(i + 1, sums)) return;
    }
}

double photonMse(const EstimateErrors& e, uint64_t n, const ShrinkSums& s) {
    const double mean = s.radius / double(n);
    return e.photonVariance * s.inverseVolume / (double(n) * double(n)) + e.photonBias2 * mean * mean;
}

}  // namespace

double predictedPhotonMse(const EstimateErrors& e, const KernelShrink& shrink, uint64_t passes) {
    double mse = 0;
    forPasses(shrink, passes, [&](uint64_t n, const ShrinkSums& s) {
        if (n == passes) mse = photonMse(e, n, s);
        return true;
    });
    return mse;
}

double predictedWalkMse(const EstimateErrors& e, uint64_t passes) {
    return passes == 0 ? 0 : e.walkVariance / double(passes);
}

uint64_t walksPayFrom(const EstimateErrors& e, const KernelShrink& shrink, uint64_t most) {
    uint64_t from = 0;
    forPasses(shrink, most, [&](uint64_t n, const ShrinkSums& s) {
        if (predictedWalkMse(e, n) < photonMse(e, n, s)) from = n;
        return from == 0;
    });
    return from;
}

}  // namespace tetglow
