// Which estimate a photon domain gets, from their measured errors: the photon estimate (its
// variance and its kernel's bias, both at the first pass's radius) or the eye path's walk
// (unbiased, its variance). Progressive photon mapping shrinks the radius every pass, so its
// variance per pass grows as the kernel's volume shrinks (1 / r^dim) while its bias falls; the
// bias is taken as proportional to the radius (a light that changes within the kernel, as at a
// dense medium's boundary; in a smooth field it falls as r^2, faster, so this leans towards the
// unbiased walk). The walk's variance falls as 1 / passes.
#pragma once
#include <cstdint>

namespace tetglow {

// Per pass, over the probes, weighted as the relative MSE is: the variance of one pass's photon
// estimate, its squared bias and the variance of one pass's walk.
struct EstimateErrors {
    double photonVariance = 0, photonBias2 = 0, walkVariance = 0;
};

// The kernel's shrinking: alpha and the kernel's dimension, as PhotonIntegrator::radiusScale.
struct KernelShrink {
    double alpha = 2.0 / 3;
    int dim = 2;
};

// The relative MSE of the mean of the first `passes` passes.
double predictedPhotonMse(const EstimateErrors& e, const KernelShrink& shrink, uint64_t passes);
double predictedWalkMse(const EstimateErrors& e, uint64_t passes);
// The fewest passes, up to `most`, after which the walk's predicted error is below the photon
// estimate's; 0 if it is not by then.
uint64_t walksPayFrom(const EstimateErrors& e, const KernelShrink& shrink, uint64_t most);

}  // namespace tetglow
