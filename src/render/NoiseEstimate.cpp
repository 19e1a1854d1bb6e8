#include "render/NoiseEstimate.h"

namespace tetglow {

// A pixel's n samples split into nE and nO = n - nE, each of variance s^2 and independent. The
// half means differ by d with E[d^2] = s^2 (1/nE + 1/nO) = s^2 n / (nE nO), while the full
// mean's error has E[e^2] = s^2 / n. So e^2 is estimated by d^2 nE nO / n^2: a quarter of d^2
// when the halves are equal. The passes are not independent: the first numbers of a pixel's
// samples are stratified over the passes (render/Renderer.h), which makes the full image better
// than independent samples would, and better than each half lets one predict: on a smooth scene
// the estimate is about twice the error. After few passes of a scene lit by rare bright paths it
// is low instead: the passes have not met those paths yet (docs/RESULTS.md, --noise).
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
            sum += d * d * factor / (mean * mean + kRelMseFloor);
            ++terms;
        }
    }
    if (terms == 0) return std::nullopt;
    return sum / double(terms);
}

}  // namespace tetglow
