#include "media/FreeFlight.h"

#include <cmath>

namespace tetglow {

namespace {

// An exit query that looks only as far as the interaction costs a few tet steps
// (bench_shadow's BM_FreeFlight), but leaves the interaction's tet to be located where the
// next ray walks: a flight asks it where it would walk more than kFlightSteps tets on average
// (its mean free path over the mean chord). 16 made the sphere scene walk (0.85x its samples
// per second); asking at every mean free path made jade's flights jump and its shadow rays
// locate (0.8x).
constexpr double kFlightSteps = 4;

// The region and tet a stretch from `start` begins in; a start through the surface leaves its
// walk in *entered. Nothing where the ray only touches the medium.
std::optional<RegionStretch> stretchStart(const Volume& volume, const Ray& ray, WalkStart start,
                                          std::optional<TetWalk>& entered) {
    RegionStretch stretch;
    stretch.tet = start.index;
    if (start.throughSurface) {
        // Entering through the surface, the walk's first tet and the entry's t come at once.
        entered = volume.beginWalk(ray, start);
        if (entered->exited()) return std::nullopt;  // a touch
        stretch.tet = entered->exitTet();
        stretch.t0 = entered->exitT();
    }
    stretch.region = volume.mesh().region(stretch.tet);
    return stretch;
}

// The end of `stretch` by one exit query as far as reach (at most tMax); false where unsure.
bool findEnd(const Volume& volume, RegionStretch& stretch, const Ray& ray, double reach, double tMax) {
    const RegionExit e = regionExit(volume.traversal(), ray, stretch.region, stretch.t0, reach);
    if (e.kind == RegionExit::Kind::Unsure) return false;
    const bool exits = e.kind == RegionExit::Kind::Exit;
    stretch.end = exits ? e.t : reach;
    // Past an interface the walk crosses, the flight goes on in another region.
    stretch.whole = exits ? !volume.crossesAt(e) : reach >= tMax;
    if (exits && stretch.whole) stretch.exit = {true, e.triangle, e.tet, e.t};
    return true;
}

// Whether a stretch through `region` is found by an exit query: its density is constant and its
// mean free path spans more than kFlightSteps tet chords (else its flights walk, and so does it).
bool stretchAsks(const Volume& volume, int32_t region) {
    const double chord = volume.tetChord(region);
    return chord > 0 && chord * kFlightSteps * average(volume.region(region).sigmaT) < 1;
}

}  // namespace

FreeFlight sampleFlight(const Volume& volume, const Ray& ray, WalkStart start, double tMax, int hero, double u,
                        const RGB& ratios, bool jump) {
    // The distance solves the hero channel's optical depth = -ln(1 - u), region by region.
    const double target = -std::log1p(-u);
    RGB depth(0);  // optical depth so far
    FreeFlight flight;
    // A stretch without an interaction.
    auto pass = [&](const Medium& medium, double piece) {
        if (isBlack(medium.sigmaT) && maxComponent(medium.params.emission) > 0) {
            // The transmittance is constant here: the emission integrates exactly, weighted
            // like a path that passed the stretch (SpectralPath::pass) against its pdf ratios.
            const RGB tr = exp(-depth);
            flight.glow += medium.params.emission * piece * tr / average(ratios * tr);
        }
        depth += medium.sigmaT * piece;
        return true;
    };
    auto visit = [&](const WalkSegment& s) {
        const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
        if (tOut <= tIn) return s.tIn < tMax;
        const Medium& medium = volume.at(s.tet);
        const double piece = volume.densityIntegral(s.tet, ray, tIn, tOut), sigma = medium.sigmaT[hero];
        if (sigma > 0 && depth[hero] + sigma * piece >= target) {
            const double need = (target - depth[hero]) / sigma;  // column still to go
            flight.scattered = true;
            flight.t = tIn + volume.columnDistance(s.tet, ray, tIn, tOut, need);
            flight.tet = s.tet;
            flight.density = volume.density(s.tet, ray.at(flight.t));
            depth += medium.sigmaT * need;
            return false;
        }
        pass(medium, piece);
        return s.tOut < tMax;
    };
    // With no interaction possible (u = 1: transmittance), the walk may end in one exit query.
    if (std::isinf(target)) {
        flight.exit = volume.walkToExit(ray, start, tMax, visit, pass, [](const Medium&, double) { return true; });
        flight.transmittance = exp(-depth);
        return flight;
    }
    std::optional<TetWalk> entered;
    std::optional<RegionStretch> stretch;
    if (jump) stretch = stretchStart(volume, ray, start, entered);
    if (stretch) {
        const double chord = volume.tetChord(stretch->region);
        const double sigma = volume.region(stretch->region).sigmaT[hero];
        if (chord > 0 && chord * kFlightSteps * sigma < 1) {
            // From a point in a region of constant density (or its entry into one): its exit by
            // one query, and the interaction, where it comes first. Only an exit before the
            // interaction matters: the query looks that far (an eighth beyond, where Embree's float
            // t of a triangle nearly parallel to the ray may land), not across the whole medium,
            // and finds and decides fewer candidates.
            const double t = sigma > 0 ? stretch->t0 + target / sigma : INFINITY;
            if (findEnd(volume, *stretch, ray, std::min(tMax, stretch->t0 + 1.125 * (t - stretch->t0)), tMax))
                if (auto flight = flightWithin(volume, *stretch, hero, u, ratios)) return *flight;
        }
    }
    TetWalk w = entered ? *entered : volume.beginWalk(ray, start);
    volume.walkOn(w, visit);
    const WalkExit exit = WalkExit::of(w, tMax);
    flight.transmittance = exp(-depth);
    if (!flight.scattered) flight.exit = exit;
    return flight;
}

std::optional<RegionStretch> regionStretch(const Volume& volume, const Ray& ray, WalkStart start, double tMax,
                                           double depth) {
    // The region behind the entry triangle, or the tet's, decides before a walk enters it (in the
    // rare entry through a neighbour of another region, the entered tet's decides again).
    const TetMesh& mesh = volume.mesh();
    const int32_t region = start.throughSurface ? mesh.surfaceRegions[start.index][0] : mesh.region(start.index);
    if (region < 0 || !stretchAsks(volume, region)) return std::nullopt;
    std::optional<TetWalk> entered;
    std::optional<RegionStretch> stretch = stretchStart(volume, ray, start, entered);
    if (!stretch || !stretchAsks(volume, stretch->region)) return std::nullopt;
    const RGB& sigma = volume.region(stretch->region).sigmaT;
    const double least = minComponent(sigma);
    const double reach = least > 0 ? std::min(tMax, stretch->t0 + depth / least) : tMax;
    if (!findEnd(volume, *stretch, ray, reach, tMax)) return std::nullopt;
    return stretch;
}

std::optional<FreeFlight> flightWithin(const Volume& volume, const RegionStretch& stretch, int hero, double u,
                                       const RGB& ratios) {
    const Medium& medium = volume.region(stretch.region);
    const double sigma = medium.sigmaT[hero], t = sigma > 0 ? stretch.t0 - std::log1p(-u) / sigma : INFINITY;
    const double end = stretch.end;
    const bool interacts = t < end - 1e-9 * (1 + end);  // else too close to the end to call, or beyond it
    if (!interacts && !(t > end && stretch.whole)) return std::nullopt;
    FreeFlight flight;
    if (interacts) {
        flight.scattered = true;
        flight.t = t;
        flight.tet = stretch.tet;
        flight.located = false;
        flight.transmittance = exp(-medium.sigmaT * (t - stretch.t0));
        return flight;
    }
    const double length = end - stretch.t0;
    flight.transmittance = exp(-medium.sigmaT * length);
    // Without extinction the emission integrates exactly (as sampleFlight's walk does).
    if (isBlack(medium.sigmaT)) flight.glow = medium.params.emission * length / average(ratios);
    flight.exit = stretch.exit;
    return flight;
}

RGB transmittance(const Volume& volume, const Ray& ray, WalkStart start, double tMax) {
    return sampleFlight(volume, ray, start, tMax, 0, 1.0).transmittance;  // u = 1: an infinite target, no interaction
}

}  // namespace tetglow
