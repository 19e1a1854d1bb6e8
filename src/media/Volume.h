// Participating media confined to a tetrahedralized set of closed meshes, one medium per region
// (VolumeBoundary: nested or touching meshes in one tet mesh; a cavity is a region whose
// coefficients are all zero). Optical depth is exact: density is constant or linear inside
// each tet, so every segment of a ray walk integrates in closed form, region by region, and
// free-flight distances are sampled by inverting that integral.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec4.hpp>

#include "base/Spectrum.h"
#include "media/PhaseFunction.h"
#include "media/Roulette.h"
#include "sampling/Rng.h"
#include "tet/ClearanceGrid.h"
#include "tet/RegionExit.h"
#include "tet/TetTraversal.h"

namespace tetglow {

struct MediumParams {
    RGB sigmaA{0}, sigmaS{1};  // per unit length at density 1
    double g = 0;              // Henyey-Greenstein asymmetry
    RGB emission{0};           // radiance emitted per unit length at density 1
};

// Where a walk through the medium begins.
struct WalkStart {
    uint32_t index = 0;           // a surface triangle, or a tet
    bool throughSurface = false;  // true: the ray enters through that triangle; false: starts inside that tet
    bool located = true;          // false: the origin lies in the region of that tet, in a tet not known
    static WalkStart surface(uint32_t triangle) { return {triangle, true, true}; }
    static WalkStart inside(uint32_t tet) { return {tet, false, true}; }
    // In the region of `tet` (one of constant density), near it: flights and shadow rays from
    // here ask the region's exit first and locate their tet only where they must.
    static WalkStart inRegion(uint32_t tet) { return {tet, false, false}; }
};

// One region's medium: its coefficients and what follows from them.
struct Medium {
    MediumParams params;
    RGB sigmaT{1};
    HenyeyGreenstein phase;
    explicit Medium(const MediumParams& p = {}) : params(p), sigmaT(p.sigmaA + p.sigmaS), phase(p.g) {}
};

// Where a walk left a medium, or stopped at an interface (see Volume::setStops), before the end
// of its stretch: through surface triangle `triangle` at ray parameter t, from tet `tet`; tet is
// kTouch where a walk entering through a triangle found that the ray only touches the medium.
struct WalkExit {
    bool left = false;
    uint32_t triangle = 0, tet = 0;
    double t = 0;
    static constexpr uint32_t kTouch = UINT32_MAX;
    static WalkExit of(const TetWalk& walk, double tMax) {
        if (!walk.exited() || !(walk.exitT() < tMax)) return {};
        return {true, walk.exitTriangle(), walk.steps() == 0 ? kTouch : walk.exitTet(), walk.exitT()};
    }
};

struct FreeFlight {
    bool scattered = false;  // an interaction at t (in tet); otherwise the ray passed tMax or left the medium
    double t = 0;
    uint32_t tet = 0;
    bool located = true;   // false: tet is a tet of the interaction's region only (WalkStart::inRegion)
    double density = 1;    // at the interaction
    RGB transmittance{1};  // from the start to the interaction, or to where the flight ended
    // Emission collected exactly on the way, in the regions without extinction (where the
    // transmittance stays what it was on entering them): emission times density, integrated.
    RGB glow{0};
    WalkExit exit;  // without an interaction
};

// A stretch of a ray through one region of constant density, from t0 (its start, or where it
// enters the medium) to `end`, found by one exit query: `whole` where what lies beyond end is known
// too (the ray leaves the medium or stops at an interface there, exit.left, or end is the
// stretch's tMax); otherwise end is only as far as the query looked.
struct RegionStretch {
    int32_t region = 0;
    uint32_t tet = 0;  // the start's tet, or the tet the ray enters: a tet of the region near t0
    double t0 = 0, end = 0;
    bool whole = false;
    WalkExit exit;
};

// What one region holds: its coefficients, and its density as one value >= 0 per tet vertex
// (only its own tets' vertices are read), or empty for density 1 everywhere.
struct MediumField {
    MediumParams params;
    std::vector<double> vertexDensity;
};

class Volume {
public:
    // The same medium in every region.
    Volume(const MediumParams& params, TetMesh mesh, std::vector<double> vertexDensity = {});
    // One medium per region of the mesh.
    Volume(TetMesh mesh, std::vector<MediumField> regions);
    // New coefficients and densities on the same tets (the preview's re-tuning: no new tets).
    void setRegions(std::vector<MediumField> regions);
    // Free flights stop at these interface triangles (true: a dielectric between two regions)
    // and cross the others, index-matched, inside the walk. By default they cross every one.
    void setStops(std::vector<bool> stops) { stops_ = std::move(stops); }
    bool stopsAt(uint32_t triangle) const { return !stops_.empty() && stops_[triangle]; }
    // Transmittance and shadow rays walk this many tets of a region of constant density, then
    // find its exit with one query of the surface BVH (regionExit), where the tets between carry no
    // news; 0: walk every tet.
    void setExitQueryAfter(size_t steps) { exitQueryAfter_ = steps; }

    const TetTraversal& traversal() const { return traversal_; }
    const TetMesh& mesh() const { return traversal_.mesh(); }
    const Medium& region(int32_t r) const { return regions_[size_t(r)]; }
    const Medium& at(uint32_t tet) const { return regions_[size_t(mesh().region(tet))]; }
    bool homogeneous() const { return densityPlane_.empty(); }
    bool emissive() const { return emissive_; }
    bool scatters() const { return scatters_; }
    double density(uint32_t tet, const glm::dvec3& p) const;
    // Density integrated along the ray (unit direction) over [tIn, tOut] inside `tet`.
    double densityIntegral(uint32_t tet, const Ray& ray, double tIn, double tOut) const;
    // The distance x from tIn at which the density integrated inside `tet` reaches `column`
    // (at most tOut - tIn): densityIntegral inverted.
    double columnDistance(uint32_t tet, const Ray& ray, double tIn, double tOut, double column) const;

    TetWalk beginWalk(const Ray& ray, WalkStart start) const;
    // Calls visit(segment) for the walk's segments from `start` in order, crossing the
    // interfaces it does not stop at, until visit returns false; returns the walk, exited()
    // where the ray left the medium or stopped at an interface.
    template <class Visit>
    TetWalk walk(const Ray& ray, WalkStart start, Visit&& visit) const;
    // The same, going on with a walk begun (or stopped by its visitor) before; false where visit stopped it.
    template <class Visit>
    bool walkOn(TetWalk& walk, Visit&& visit) const;

    // Free flight along `ray` (unit direction) from `start` up to tMax, the distance sampled
    // exactly for the hero channel's extinction (see SpectralPath). `ratios` are the path's
    // pdf ratios (SpectralPath::r), for the spectral MIS weight of FreeFlight::glow.
    // With `jump`, a flight in a region of constant density may find the region's exit by one
    // query of the surface BVH and jump to its interaction, whose tet it then leaves unlocated.
    FreeFlight sampleFlight(const Ray& ray, WalkStart start, double tMax, int hero, double u,
                            const RGB& ratios = RGB(1), bool jump = false) const;
    // The stretch from `start` through the region of constant density it begins in, looking at
    // most `depth` mean free paths of the region's smallest extinction ahead (and not beyond tMax).
    // Nothing where the walk must decide (the ray only touches the medium, the region's density
    // varies, or its exit is too close to another crossing to call) or where walking is cheaper
    // (the region's mean free path is a few tet chords: sampleFlight's rule, for its mean extinction).
    std::optional<RegionStretch> regionStretch(const Ray& ray, WalkStart start, double tMax, double depth) const;
    // A free flight (see sampleFlight) inside `stretch`, without a walk: its interaction, which
    // is left unlocated, or the stretch passed whole. Nothing where the interaction is too close
    // to the stretch's end to call, or lies beyond an end that is not whole.
    std::optional<FreeFlight> flightWithin(const RegionStretch& stretch, int hero, double u,
                                           const RGB& ratios = RGB(1)) const;
    // exp(-optical depth) from `start` to tMax or to where the ray leaves the medium (or
    // stops at an interface).
    RGB transmittance(const Ray& ray, WalkStart start, double tMax) const;
    // The same for a shadow ray, with Russian roulette once the transmittance has fallen below
    // 1/20 (as pbrt-v4's ratio tracking does): the walk stops there with probability 3/4 (a
    // transmittance of 0, no exit) and a survivor counts 4 times, tested again whenever its
    // weighted transmittance is below 1/20 (ShadowRoulette; `roulette` may hold tests decided
    // before, by sureDepth). Unbiased; deep in a dense medium a shadow ray walks a few tets, not
    // all to the boundary.
    FreeFlight shadowFlight(const Ray& ray, WalkStart start, double tMax, Rng& rng, ShadowRoulette roulette = {}) const;
    // An optical depth (its smallest channel's) that a ray from `origin`, in the region of
    // `start`'s tet, surely gathers before tMax: in a region of constant density, along the ball
    // around `origin` that holds no boundary (ClearanceGrid). 0 where the density varies, the ray
    // starts on the surface, or no such ball is deep enough for the shadow roulette's first test.
    double sureDepth(WalkStart start, const glm::dvec3& origin, double tMax) const;
    // Whether sureDepth may be above 0 anywhere here (a region is dense enough for it).
    bool deepShadows() const { return !clearance_.empty(); }

private:
    // walk() for a stretch that needs only the optical depth: once exitQueryAfter_ segments are
    // walked, the walk is inside a region of constant density and worthAsking(medium, the region's
    // mean chord of a tet) says so, the rest of the way to the region's exit (or tMax) goes to
    // pass(medium, length) at once (false: stop), unless that exit is an interface the walk
    // crosses or too close to call. Returns where the ray left.
    template <class Visit, class Pass, class Worth>
    WalkExit walkToExit(const Ray& ray, WalkStart start, double tMax, Visit&& visit, Pass&& pass,
                        Worth&& worthAsking) const;

    // The region and tet a stretch from `start` begins in; a start through the surface leaves its
    // walk in *entered. Nothing where the ray only touches the medium.
    std::optional<RegionStretch> stretchStart(const Ray& ray, WalkStart start, std::optional<TetWalk>& entered) const;
    // Whether a stretch through `region` is found by an exit query: its density is constant and its
    // mean free path spans more than kFlightSteps tet chords (else its flights walk, and so does it).
    bool stretchAsks(int32_t region) const;
    // The end of `stretch` by one exit query as far as reach (at most tMax); false where unsure.
    bool findEnd(RegionStretch& stretch, const Ray& ray, double reach, double tMax) const;

    // An exit through an interface that flights cross, index-matched, inside the walk.
    bool crossesAt(const RegionExit& e) const {
        return e.kind == RegionExit::Kind::Exit && mesh().surfaceFaceFront[e.triangle] != UINT32_MAX &&
               !stopsAt(e.triangle);
    }

    // An exit query that looks only as far as the interaction costs a few tet steps
    // (bench_shadow's BM_FreeFlight), but leaves the interaction's tet to be located where the
    // next ray walks: a flight asks it where it would walk more than kFlightSteps tets on average
    // (its mean free path over the mean chord). 16 made the sphere scene walk (0.85x its samples
    // per second); asking at every mean free path made jade's flights jump and its shadow rays
    // locate (0.8x).
    static constexpr double kFlightSteps = 4;

    std::vector<Medium> regions_;
    std::vector<double> tetChord_;  // per region: its tets' mean chord, 0 where its density varies
    bool emissive_ = false, scatters_ = false;
    TetTraversal traversal_;
    ClearanceGrid clearance_;
    std::vector<glm::dvec4> densityPlane_;  // per tet: density(p) = w + dot(xyz, p)
    std::vector<bool> stops_;               // per surface triangle, or empty: none
    size_t exitQueryAfter_ = 1;
};

template <class Visit>
TetWalk Volume::walk(const Ray& ray, WalkStart start, Visit&& visit) const {
    TetWalk w = beginWalk(ray, start);
    walkOn(w, visit);
    return w;
}

template <class Visit>
bool Volume::walkOn(TetWalk& w, Visit&& visit) const {
    do {
        for (WalkSegment s; w.next(s);)
            if (!visit(s)) return false;
    } while (w.exited() && !stopsAt(w.exitTriangle()) && w.crossInterface());
    return true;
}

template <class Visit, class Pass, class Worth>
WalkExit Volume::walkToExit(const Ray& ray, WalkStart start, double tMax, Visit&& visit, Pass&& pass,
                            Worth&& worthAsking) const {
    // The rest of the way from tNow in tet's region, by one exit query; nothing where the walk
    // must decide (a near-tie, or an interface it crosses).
    auto leave = [&](uint32_t tet, double tNow) -> std::optional<WalkExit> {
        const RegionExit e = regionExit(traversal_, ray, mesh().region(tet), tNow, tMax);
        if (e.kind == RegionExit::Kind::Unsure || crossesAt(e)) return std::nullopt;
        const bool exits = e.kind == RegionExit::Kind::Exit;
        if (!pass(at(tet), (exits ? e.t : tMax) - std::max(tNow, 0.0))) return WalkExit{};
        return exits ? WalkExit{true, e.triangle, e.tet, e.t} : WalkExit{};
    };
    auto worth = [&](uint32_t tet) {
        const size_t r = size_t(mesh().region(tet));
        return tetChord_[r] > 0 && worthAsking(regions_[r], tetChord_[r]);
    };
    if (!start.located && worth(start.index))  // no tet to walk from: ask at once
        if (const auto exit = leave(start.index, 0)) return *exit;
    TetWalk w = beginWalk(ray, start);
    size_t steps = 0;
    uint32_t tet = 0;
    double tNow = 0;
    bool ask = false;
    walkOn(w, [&](const WalkSegment& s) {
        if (!visit(s)) return false;
        tet = s.tet;
        tNow = s.tOut;
        if (++steps != exitQueryAfter_ || w.exited()) return true;  // asked once: after that, the walk
        ask = worth(tet);
        return !ask;
    });
    if (!ask) return WalkExit::of(w, tMax);
    if (const auto exit = leave(tet, tNow)) return *exit;
    walkOn(w, visit);  // the walk goes on from where it was
    return WalkExit::of(w, tMax);
}

}  // namespace tetglow
