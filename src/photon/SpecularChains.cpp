// The chain light (PhotonIntegrator::EyeLight::ChainLight) split over the pixel. A small light
// seen through glass shows, in the pixels at the glass's edge, as a sliver of each pixel whose
// rays the chain bends onto the light: one sample in a few hundred lands on it, hundreds of
// times brighter than the pixel's mean (on the demo fish, two such pixels held half of the
// image's error at 24 passes). So is a small glowing medium seen along a chain (the lure, seen by
// total internal reflection in the skin). Every pixel that can see glass traces kChainSplits more
// rays, over the whole pixel, that follow the specular chain only: a walk of the tets for the
// transmittance and the emission, no photons, no light sampling.
#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "photon/PhotonIntegrator.h"
#include "scene/Material.h"

namespace tetglow {

void PhotonIntegrator::markChainPixels() {
    const Camera& camera = scene_.camera();
    const int w = camera.width(), h = camera.height();
    const std::vector<glm::dvec3> key = {camera.position(), camera.generateRay(0, 0).d, camera.generateRay(w, h).d,
                                         glm::dvec3(w, h, 0)};
    if (key == chainCamera_) return;
    chainCamera_ = key;
    // Whether the ray through film position (x, y) meets a specular surface before any other
    // (index-matched boundaries let it through).
    auto specular = [&](double x, double y) {
        const auto hit = scene_.intersectOpaque(camera.generateRay(x, y));
        return hit && isSpecular(scene_.material(*hit));
    };
    std::vector<char> corners(size_t(w + 1) * (h + 1));
    chainPixels_.assign(size_t(w) * h, 0);
    tbb::parallel_for(tbb::blocked_range<int>(0, h + 1), [&](const auto& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x <= w; ++x) corners[size_t(y) * (w + 1) + x] = specular(x, y);
    });
    tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const auto& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x < w; ++x) {
                const size_t c = size_t(y) * (w + 1) + x;
                chainPixels_[size_t(y) * w + x] = corners[c] || corners[c + 1] || corners[c + w + 1] ||
                                                  corners[c + w + 2] || specular(x + 0.5, y + 0.5);
            }
    });
}

int PhotonIntegrator::chainPixel(const Ray& cameraRay) const {
    const Camera& camera = scene_.camera();
    const int w = camera.width(), h = camera.height();
    if (chainPixels_.size() != size_t(w) * h) return -1;
    const glm::dvec2 film = camera.filmPosition(cameraRay.d);
    const int x = int(std::floor(film.x)), y = int(std::floor(film.y));
    if (x < 0 || y < 0 || x >= w || y >= h || !chainPixels_[size_t(y) * w + x]) return -1;
    return y * w + x;
}

RGB PhotonIntegrator::splitChainLight(int pixel, Rng& rng) const {
    const Camera& camera = scene_.camera();
    const int x = pixel % camera.width(), y = pixel / camera.width();
    // A Fibonacci lattice shifted at random over the pixel (Cranley and Patterson): each ray is
    // uniform in the pixel and the rays spread evenly, so that a sliver of the pixel that sees
    // the light is met in proportion to its area more often than by chance (on the demo, five
    // such rays leave the error of a pass where eight independent ones did, in 0.8 times the time).
    const double su = rng.uniform(), sv = rng.uniform();
    RGB sum(0);
    for (int i = 0; i < kChainSplits; ++i) {
        const double u = std::fmod(double(i) / kChainSplits + su, 1.0),
                     v = std::fmod(double(kChainLatticeGenerator * i % kChainSplits) / kChainSplits + sv, 1.0);
        sum += eyePath(camera.generateRay(x + u, y + v), rng, -1, nullptr, EyeLight::ChainLight);
    }
    return sum / double(kChainSplits);
}

PhotonIntegrator::ChainStretch PhotonIntegrator::chainStretch(int v, const Ray& ray, WalkStart start, double tMax,
                                                              bool emission) const {
    const Volume& volume = *scene_.volumes()[size_t(v)].volume;
    ChainStretch stretch;
    RGB depth(0);
    auto pass = [&](const Medium& medium, double column) {
        if (emission && maxComponent(medium.params.emission) > 0) stretch.emitted += emittedOver(medium, depth, column);
        depth += medium.sigmaT * column;
        return true;
    };
    stretch.exit = volume.walkToExit(
        ray, start, tMax,
        [&](const WalkSegment& s) {
            const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
            if (tOut > tIn) pass(volume.at(s.tet), volume.densityIntegral(s.tet, ray, tIn, tOut));
            return s.tOut < tMax;
        },
        pass, [](const Medium&, double) { return true; });
    stretch.transmittance = exp(-depth);
    return stretch;
}

}  // namespace tetglow
