#include "render/NoiseEstimate.h"

#include <algorithm>

namespace tetglow {

// A pixel's n samples split into nE and nO = n - nE, each of variance s^2 and independent. The
// half means differ by d with E[d^2] = s^2 (1/nE + 1/nO) = s^2 n / (nE nO), while the full
// mean's error has E[e^2] = s^2 / n. So e^2 is estimated by d^2 nE nO / n^2: a quarter of d^2
// when the halves are equal, and then without bias whatever the samples' distribution when the
// halves are independent (RenderOptions::independentHalves). One stratified sequence over all
// passes makes the full image better than its halves predict: the estimate is then conservative.
// The converged value in the denominator is the pixel's mean, except where one half's mean is
// more than kFireflyRatio times the other's: there a rare bright path dominates the mean, which
// would hide that pixel's error (its relative error would read as about 1), and the smaller
// half's mean is the better guess. Without this the estimate read 1.4 to 2.1 times low on the
// blue cloud (docs/RESULTS.md, --noise); a ratio as large as 7 is very unlikely from ordinary noise.
static constexpr double kFireflyRatio = 7;

std::optional<double> estimateRelMse(const Film& all, const Film& half) {
    double sum = 0;
    size_t terms = 0;
    for (size_t i = 0; i < all.pixelCount(); ++i) {
        const double n = all.count(i), nE = half.count(i), nO = n - nE;
        if (nE == 0 || nO == 0) continue;
        const double factor = nE * nO / (n * n);
        for (int c = 0; c < 3; ++c) {
            const double sumE = double(half.sum(i)[c]) / kFixedUnit, sumAll = double(all.sum(i)[c]) / kFixedUnit;
            const double meanE = sumE / nE, meanO = (sumAll - sumE) / nO, mean = sumAll / n;
            const double d = meanE - meanO;
            const double low = std::min(meanE, meanO), high = std::max(meanE, meanO);
            const double converged = high > kFireflyRatio * low ? low : mean;
            sum += d * d * factor / (converged * converged + kRelMseFloor);
            ++terms;
        }
    }
    if (terms == 0) return std::nullopt;
    return sum / double(terms);
}

}  // namespace tetglow
