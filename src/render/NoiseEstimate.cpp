#include "render/NoiseEstimate.h"

namespace tetglow {

// A pixel's n samples split into nE and nO = n - nE, each of variance s^2 and independent. The
// half means differ by d with E[d^2] = s^2 (1/nE + 1/nO) = s^2 n / (nE nO), while the full
// mean's error has E[e^2] = s^2 / n. So e^2 is estimated by d^2 nE nO / n^2: a quarter of d^2
// when the halves are equal, and then without bias whatever the samples' distribution when the
// halves are independent (RenderOptions::independentHalves). One stratified sequence over all
// passes makes the full image better than its halves predict: the estimate is then conservative.
// The converged value in the denominator is the pixel's mean. A scene lit by rare bright paths
// (the blue cloud at 20 to 50 passes) then reads low: such a path raises the mean and hides its
// pixel's error. Taking the smaller half there instead fixed the cloud but made the estimate 20
// times the error on the photon-mapped fish, whose caustic pixels see sparse kernel hits
// (docs/notes/2026-12-04-noise-estimate.md).
void RelMseSum::addPixel(const Film& all, const Film& half, size_t i) {
    const double n = all.count(i), nE = half.count(i), nO = n - nE;
    if (nE == 0 || nO == 0) return;
    const double factor = nE * nO / (n * n);
    for (int c = 0; c < 3; ++c) {
        const double sumE = double(half.sum(i)[c]) / kFixedUnit, sumAll = double(all.sum(i)[c]) / kFixedUnit;
        const double meanE = sumE / nE, meanO = (sumAll - sumE) / nO, mean = sumAll / n;
        const double d = meanE - meanO;
        sum += d * d * factor / (mean * mean + kRelMseFloor);
        ++terms;
    }
}

std::optional<double> estimateRelMse(const Film& all, const Film& half) {
    RelMseSum s;
    for (size_t i = 0; i < all.pixelCount(); ++i) s.addPixel(all, half, i);
    return s.mean();
}

}  // namespace tetglow
