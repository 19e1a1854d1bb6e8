#include "media/ShadowRay.h"

#include <algorithm>
#include <cmath>

namespace tetglow {

FreeFlight shadowFlight(const Volume& volume, const Ray& ray, WalkStart start, double tMax, Rng& rng,
                        ShadowRoulette roulette) {
    RGB depth(0);
    bool stopped = false;
    auto pass = [&](const Medium& medium, double length) {
        depth += medium.sigmaT * length;
        stopped = !roulette.reach(minComponent(depth), rng);
        return !stopped;
    };
    // Where roulette will likely end the ray within kQuerySteps mean tet steps, walking is cheaper
    // than an exit query (which costs about 14 steps on blub, bench_shadow; 8 leans to asking).
    constexpr double kQuerySteps = 8;
    auto worthAsking = [&](const Medium& medium, double meanStep) {
        const double sigma = minComponent(medium.sigmaT);
        return roulette.at - minComponent(depth) > sigma * kQuerySteps * meanStep;
    };
    const WalkExit exit = volume.walkToExit(
        ray, start, tMax,
        [&](const WalkSegment& s) {
            const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
            if (tOut <= tIn) return s.tIn < tMax;
            return pass(volume.at(s.tet), volume.densityIntegral(s.tet, ray, tIn, tOut)) && s.tOut < tMax;
        },
        pass, worthAsking);
    FreeFlight flight;
    flight.transmittance = stopped ? RGB(0) : exp(-depth) * roulette.weight;
    if (!stopped) flight.exit = exit;
    return flight;
}

double sureDepth(const Volume& volume, WalkStart start, const glm::dvec3& origin, double tMax) {
    const ClearanceGrid& clearance = volume.clearance();
    if (start.throughSurface || clearance.empty()) return 0;
    const int32_t r = volume.mesh().region(start.index);
    if (!(volume.tetChord(r) > 0)) return 0;  // its density varies
    const double sigma = minComponent(volume.region(r).sigmaT);
    if (!(sigma * clearance.largest() > ShadowRoulette{}.at)) return 0;
    return sigma * std::min(clearance.lowerBound(origin), tMax);
}

}  // namespace tetglow
