#include "media/Volume.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace tetglow {

namespace {

// The affine function through four (vertex, value) pairs: solves for the gradient from the
// three edges at vertex 0.
glm::dvec4 affineThrough(const TetMesh& mesh, uint32_t t, const std::vector<double>& value) {
    const auto& v = mesh.tets[t];
    const glm::dvec3 p0 = mesh.vertices[v[0]];
    const glm::dmat3 edges(mesh.vertices[v[1]] - p0, mesh.vertices[v[2]] - p0, mesh.vertices[v[3]] - p0);
    const glm::dvec3 rise(value[v[1]] - value[v[0]], value[v[2]] - value[v[0]], value[v[3]] - value[v[0]]);
    // rise_k = dot(gradient, edge_k): gradient = inverse(transpose(edges)) * rise.
    const glm::dvec3 gradient = glm::inverse(glm::transpose(edges)) * rise;
    return {gradient, value[v[0]] - glm::dot(gradient, p0)};
}

}  // namespace

Volume::Volume(const MediumParams& params, TetMesh mesh, std::vector<double> vertexDensity)
    : traversal_(std::move(mesh)) {
    std::vector<MediumField> regions(std::max<size_t>(1, this->mesh().regionCount()), MediumField{params, {}});
    for (MediumField& r : regions) r.vertexDensity = vertexDensity;
    setRegions(std::move(regions));
}

Volume::Volume(TetMesh mesh, std::vector<MediumField> regions) : traversal_(std::move(mesh)) {
    setRegions(std::move(regions));
}

void Volume::setRegions(std::vector<MediumField> regions) {
    const TetMesh& m = traversal_.mesh();
    if (regions.size() != std::max<size_t>(1, m.regionCount()))
        throw std::invalid_argument("Volume: one medium per region expected");
    regions_.clear();
    tetChord_.clear();
    emissive_ = scatters_ = false;
    bool varying = false;
    for (const MediumField& r : regions) {
        if (!r.vertexDensity.empty() && r.vertexDensity.size() != m.vertices.size())
            throw std::invalid_argument("Volume: one density per tet vertex expected");
        regions_.emplace_back(r.params);
        // A regular tet's mean chord (4 V / S) is 0.55 times the cube root of its volume.
        const int32_t index = int32_t(regions_.size()) - 1;
        const double tets = m.regionCount() ? double(m.regionTets[size_t(index) + 1] - m.regionTets[size_t(index)])
                                            : double(m.tets.size());
        const double volume = m.regionCount() ? m.regionVolume(index) : m.volume();
        tetChord_.push_back(r.vertexDensity.empty() && tets > 0 ? 0.55 * std::cbrt(volume / tets) : 0.0);
        emissive_ |= maxComponent(r.params.emission) > 0;
        scatters_ |= maxComponent(r.params.sigmaS) > 0;
        varying |= !r.vertexDensity.empty();
    }
    // Clear balls pay only where a shadow ray inside one can reach the roulette's first test:
    // in a region of constant density whose mean free path is short against the box.
    const glm::dvec3 extent = traversal_.bounds().hi - traversal_.bounds().lo;
    const double deepest = 0.5 * std::min({extent.x, extent.y, extent.z});
    for (size_t r = 0; r < regions_.size() && clearance_.empty(); ++r)
        if (tetChord_[r] > 0 && minComponent(regions_[r].sigmaT) * deepest > ShadowRoulette{}.at)
            clearance_ = ClearanceGrid(m);
    densityPlane_.assign(varying ? m.tets.size() : 0, glm::dvec4(0, 0, 0, 1));
    for (uint32_t t = 0; t < densityPlane_.size(); ++t)
        if (const auto& density = regions[size_t(std::max(0, m.region(t)))].vertexDensity; !density.empty())
            densityPlane_[t] = affineThrough(m, t, density);
}

double Volume::density(uint32_t tet, const glm::dvec3& p) const {
    if (homogeneous()) return 1;
    const glm::dvec4& a = densityPlane_[tet];
    return std::max(0.0, a.w + glm::dot(glm::dvec3(a), p));
}

double Volume::densityIntegral(uint32_t tet, const Ray& ray, double tIn, double tOut) const {
    if (homogeneous()) return tOut - tIn;
    // Linear along the segment: the midpoint rule is exact.
    return (tOut - tIn) * density(tet, ray.at(0.5 * (tIn + tOut)));
}

double Volume::columnDistance(uint32_t tet, const Ray& ray, double tIn, double tOut, double column) const {
    if (homogeneous()) return std::min(column, tOut - tIn);
    // density(tIn + x) = r0 + k x: r0 x + k x^2 / 2 = column, in the cancellation-free form.
    const double r0 = density(tet, ray.at(tIn));
    const double k = (density(tet, ray.at(tOut)) - r0) / (tOut - tIn);
    return std::min(2 * column / (r0 + std::sqrt(std::max(0.0, r0 * r0 + 2 * k * column))), tOut - tIn);
}

TetWalk Volume::beginWalk(const Ray& ray, WalkStart start) const {
    if (start.throughSurface) return TetWalk::enter(mesh(), ray, start.index);
    if (!start.located) {
        // The exact tet of the origin, found from the region's tet near it. An origin that
        // rounding put outside the region (it lies inside by more than the exit query's
        // tolerance along the ray that placed it) keeps that tet.
        const int64_t tet = traversal_.locate(ray.o, start.index);
        if (tet >= 0 && mesh().region(uint32_t(tet)) == mesh().region(start.index)) start.index = uint32_t(tet);
    }
    return TetWalk::start(mesh(), ray, start.index, 0);
}

FreeFlight Volume::sampleFlight(const Ray& ray, WalkStart start, double tMax, int hero, double u, const RGB& ratios,
                                bool jump) const {
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
        const Medium& medium = at(s.tet);
        const double piece = densityIntegral(s.tet, ray, tIn, tOut), sigma = medium.sigmaT[hero];
        if (sigma > 0 && depth[hero] + sigma * piece >= target) {
            const double need = (target - depth[hero]) / sigma;  // column still to go
            flight.scattered = true;
            flight.t = tIn + columnDistance(s.tet, ray, tIn, tOut, need);
            flight.tet = s.tet;
            flight.density = density(s.tet, ray.at(flight.t));
            depth += medium.sigmaT * need;
            return false;
        }
        pass(medium, piece);
        return s.tOut < tMax;
    };
    // With no interaction possible (u = 1: transmittance), the walk may end in one exit query.
    if (std::isinf(target)) {
        flight.exit = walkToExit(ray, start, tMax, visit, pass, [](const Medium&, double) { return true; });
        flight.transmittance = exp(-depth);
        return flight;
    }
    std::optional<TetWalk> entered;
    std::optional<RegionStretch> stretch;
    if (jump) stretch = stretchStart(ray, start, entered);
    if (stretch) {
        const size_t region = size_t(stretch->region);
        const double sigma = regions_[region].sigmaT[hero];
        if (tetChord_[region] > 0 && tetChord_[region] * kFlightSteps * sigma < 1) {
            // From a point in a region of constant density (or its entry into one): its exit by
            // one query, and the interaction, where it comes first. Only an exit before the
            // interaction matters: the query looks that far (an eighth beyond, where Embree's float
            // t of a triangle nearly parallel to the ray may land), not across the whole medium,
            // and finds and decides fewer candidates.
            const double t = sigma > 0 ? stretch->t0 + target / sigma : INFINITY;
            if (findEnd(*stretch, ray, std::min(tMax, stretch->t0 + 1.125 * (t - stretch->t0)), tMax))
                if (auto flight = flightWithin(*stretch, hero, u, ratios)) return *flight;
        }
    }
    TetWalk w = entered ? *entered : beginWalk(ray, start);
    walkOn(w, visit);
    const WalkExit exit = WalkExit::of(w, tMax);
    flight.transmittance = exp(-depth);
    if (!flight.scattered) flight.exit = exit;
    return flight;
}

std::optional<RegionStretch> Volume::stretchStart(const Ray& ray, WalkStart start,
                                                  std::optional<TetWalk>& entered) const {
    RegionStretch stretch;
    stretch.tet = start.index;
    if (start.throughSurface) {
        // Entering through the surface, the walk's first tet and the entry's t come at once.
        entered = beginWalk(ray, start);
        if (entered->exited()) return std::nullopt;  // a touch
        stretch.tet = entered->exitTet();
        stretch.t0 = entered->exitT();
    }
    stretch.region = mesh().region(stretch.tet);
    return stretch;
}

bool Volume::findEnd(RegionStretch& stretch, const Ray& ray, double reach, double tMax) const {
    const RegionExit e = regionExit(traversal_, ray, stretch.region, stretch.t0, reach);
    if (e.kind == RegionExit::Kind::Unsure) return false;
    const bool exits = e.kind == RegionExit::Kind::Exit;
    stretch.end = exits ? e.t : reach;
    // Past an interface the walk crosses, the flight goes on in another region.
    stretch.whole = exits ? !crossesAt(e) : reach >= tMax;
    if (exits && stretch.whole) stretch.exit = {true, e.triangle, e.tet, e.t};
    return true;
}

bool Volume::stretchAsks(int32_t region) const {
    const double chord = tetChord_[size_t(region)];
    return chord > 0 && chord * kFlightSteps * average(regions_[size_t(region)].sigmaT) < 1;
}

std::optional<RegionStretch> Volume::regionStretch(const Ray& ray, WalkStart start, double tMax, double depth) const {
    // The region behind the entry triangle, or the tet's, decides before a walk enters it (in the
    // rare entry through a neighbour of another region, the entered tet's decides again).
    const int32_t region = start.throughSurface ? mesh().surfaceRegions[start.index][0] : mesh().region(start.index);
    if (region < 0 || !stretchAsks(region)) return std::nullopt;
    std::optional<TetWalk> entered;
    std::optional<RegionStretch> stretch = stretchStart(ray, start, entered);
    if (!stretch || !stretchAsks(stretch->region)) return std::nullopt;
    const RGB& sigma = regions_[size_t(stretch->region)].sigmaT;
    const double least = minComponent(sigma);
    const double reach = least > 0 ? std::min(tMax, stretch->t0 + depth / least) : tMax;
    if (!findEnd(*stretch, ray, reach, tMax)) return std::nullopt;
    return stretch;
}

std::optional<FreeFlight> Volume::flightWithin(const RegionStretch& stretch, int hero, double u,
                                               const RGB& ratios) const {
    const Medium& medium = regions_[size_t(stretch.region)];
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

RGB Volume::transmittance(const Ray& ray, WalkStart start, double tMax) const {
    return sampleFlight(ray, start, tMax, 0, 1.0).transmittance;  // u = 1: an infinite target, no interaction
}

FreeFlight Volume::shadowFlight(const Ray& ray, WalkStart start, double tMax, Rng& rng, ShadowRoulette roulette) const {
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
    const WalkExit exit = walkToExit(
        ray, start, tMax,
        [&](const WalkSegment& s) {
            const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
            if (tOut <= tIn) return s.tIn < tMax;
            return pass(at(s.tet), densityIntegral(s.tet, ray, tIn, tOut)) && s.tOut < tMax;
        },
        pass, worthAsking);
    FreeFlight flight;
    flight.transmittance = stopped ? RGB(0) : exp(-depth) * roulette.weight;
    if (!stopped) flight.exit = exit;
    return flight;
}

double Volume::sureDepth(WalkStart start, const glm::dvec3& origin, double tMax) const {
    if (start.throughSurface || clearance_.empty()) return 0;
    const size_t r = size_t(mesh().region(start.index));
    if (!(tetChord_[r] > 0)) return 0;  // its density varies
    const double sigma = minComponent(regions_[r].sigmaT);
    if (!(sigma * clearance_.largest() > ShadowRoulette{}.at)) return 0;
    return sigma * std::min(clearance_.lowerBound(origin), tMax);
}

}  // namespace tetglow
