#include <chrono>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "photon/PhotonIntegrator.h"

namespace tetglow {

// Per probe (and per measured domain, for the walk): two independent passes of each estimate.
struct PhotonIntegrator::PilotSamples {
    size_t probes = 0;
    std::vector<RGB> photon[2], halfRadius[2], walk[2];
    std::vector<char> met;  // per probe and domain: the first photon pass's path read its photons
};

void PhotonIntegrator::choose(const std::atomic<bool>* cancel) {
    storeUnwalked();
    std::vector<int> measured;
    for (size_t d = 0; d < choices_.size(); ++d)
        if (choices_[d].measured) measured.push_back(int(d));
    chosen_ = measured.empty();
    if (chosen_) return;
    const auto start = std::chrono::steady_clock::now();
    PilotSamples pilot;
    chosen_ = samplePilot(measured, pilot, cancel);
    if (chosen_) judge(pilot, measured);
    for (MediumPhotons& mp : media_) {  // the render's passes trace their own
        mp.map.reset();
        mp.beams.reset();
    }
    surface_.reset();
    caustic_.reset();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_ = {};
    stats_.pilotSeconds = seconds;
    storeUnwalked();
}

bool PhotonIntegrator::samplePilot(const std::vector<int>& measured, PilotSamples& pilot,
                                   const std::atomic<bool>* cancel) {
    // The probes: a regular subset of the pixels, each with one eye path per pilot pass, from
    // sequences of their own. Photons and paths depend on the seed alone and every sum below runs
    // in probe order, so every thread count, and every part of a farm render, chooses alike.
    const Camera& camera = scene_.camera();
    const uint64_t pixels = uint64_t(camera.width()) * camera.height();
    const uint64_t stride = std::max<uint64_t>(1, pixels / kPilotProbes);
    const size_t probes = size_t((pixels + stride - 1) / stride), domains = media_.size();
    const uint64_t seed = mixBits(desc_.seed ^ 0x243f6a8885a308d3ull);
    auto probeRay = [&](size_t j, Rng& rng) {
        const uint64_t pixel = j * stride;
        const double jx = rng.uniform(), jy = rng.uniform();
        return camera.generateRay(double(pixel % camera.width()) + jx, double(pixel / camera.width()) + jy);
    };
    // Each estimate and pass draws from a sequence of its own: two passes of one Sobol sequence
    // would be stratified against each other, and their difference would not measure the variance.
    auto probeRng = [&](size_t estimate, int h, size_t j) {
        return Rng::pixelSample(mixBits(seed + 2 * estimate + size_t(h)), j, 0);
    };
    auto forProbes = [&](auto body) {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, probes), [&](const auto& range) {
            for (size_t j = range.begin(); j != range.end(); ++j) body(j);
        });
    };
    // Per pass h: the photon estimate at every probe at the first pass's radius and at half of it
    // (the same photons and eye paths), the domains the first pass's paths read photons from, and
    // per measured domain the walk's estimate where they met it (elsewhere the two estimates
    // agree in expectation and in cost, and count for neither).
    pilot.probes = probes;
    pilot.met.assign(probes * domains, 0);
    for (int h = 0; h < 2; ++h) {
        for (double factor : {1.0, 0.5}) {
            loadPhotons(seed, uint64_t(h), 0, factor, std::nullopt, cancel);
            if (cancel && cancel->load()) return false;
            std::vector<RGB>& estimate = factor == 1 ? pilot.photon[h] : pilot.halfRadius[h];
            estimate.resize(probes);
            const bool meeting = h == 0 && factor == 1;
            forProbes([&](size_t j) {
                Rng rng = probeRng(0, h, j);
                const Ray ray = probeRay(j, rng);
                estimate[j] = eyePath(ray, rng, -1, meeting ? &pilot.met[j * domains] : nullptr);
            });
            if (!meeting) continue;
            for (int w = 0; w < 2; ++w) {
                pilot.walk[w].assign(probes * measured.size(), RGB(0));
                for (size_t i = 0; i < measured.size(); ++i)
                    forProbes([&](size_t j) {
                        if (!pilot.met[j * domains + size_t(measured[i])]) return;
                        Rng rng = probeRng(1 + i, w, j);
                        const Ray ray = probeRay(j, rng);
                        pilot.walk[w][j * measured.size() + i] = eyePath(ray, rng, measured[i], nullptr);
                    });
            }
        }
    }

    return true;
}

void PhotonIntegrator::judge(const PilotSamples& pilot, const std::vector<int>& measured) {
    // Per pixel and channel, weighted by 1 / (value^2 + 0.01) as the relative MSE is, the value
    // read off the photon passes' mean (the walk's would weigh its own samples: a thin glowing
    // medium's walk finds its emission at rare collisions, mostly 0). The variance of one pass of
    // each estimate from the difference of its two independent passes. The kernel's bias from the
    // change of the photon estimate when the radius halves: taken as proportional to the radius,
    // it is twice that change, whose square's expectation is the mean change squared less that
    // mean's variance; or, where larger, from the difference of the photons' and the walk's means,
    // less those means' variances: the walk's noise can hide the bias there, and a bias that the
    // radius does not resolve at all hardly changes when it halves.
    const KernelShrink shrink{
        desc_.alpha > 0 ? desc_.alpha : balancedAlpha(desc_.estimate == PhotonEstimate::Beam ? 2 : 3),
        desc_.estimate == PhotonEstimate::Beam ? 2 : 3};
    const size_t probes = pilot.probes;
    const size_t domains = media_.size();
    for (size_t i = 0; i < measured.size(); ++i) {
        DomainChoice& choice = choices_[size_t(measured[i])];
        double photonVariance = 0, walkVariance = 0, change2 = 0, difference2 = 0;
        for (size_t j = 0; j < probes; ++j) {
            if (!pilot.met[j * domains + size_t(measured[i])]) continue;
            ++choice.probes;
            const RGB y0 = pilot.walk[0][j * measured.size() + i], y1 = pilot.walk[1][j * measured.size() + i];
            for (int c = 0; c < 3; ++c) {
                const double x0 = pilot.photon[0][j][c], x1 = pilot.photon[1][j][c];
                const double mean = (x0 + x1) / 2, w = 1 / (mean * mean + 0.01);
                const double d0 = x0 - pilot.halfRadius[0][j][c], d1 = x1 - pilot.halfRadius[1][j][c];
                photonVariance += w * (x0 - x1) * (x0 - x1) / 2;
                walkVariance += w * (y0[c] - y1[c]) * (y0[c] - y1[c]) / 2;
                change2 += w * ((d0 + d1) * (d0 + d1) / 4 - (d0 - d1) * (d0 - d1) / 4);
                const double d = mean - (y0[c] + y1[c]) / 2;
                difference2 += w * d * d;
            }
        }
        const double n = 3.0 * double(probes);
        choice.errors.photonVariance = photonVariance / n;
        choice.errors.walkVariance = walkVariance / n;
        choice.errors.photonBias2 =
            std::max({0.0, 4 * change2 / n, (difference2 - photonVariance / 2 - walkVariance / 2) / n});
        choice.photonMse = predictedPhotonMse(choice.errors, shrink, choice.passes);
        choice.walkMse = predictedWalkMse(choice.errors, choice.passes);
        choice.walksPayFrom = walksPayFrom(choice.errors, shrink, kMaxPredictedPasses);
        choice.walked = choice.probes >= kMinPilotProbes && choice.walkMse < choice.photonMse;
        media_[size_t(measured[i])].walked = choice.walked;
    }
}

}  // namespace tetglow
