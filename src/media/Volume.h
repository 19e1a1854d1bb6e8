// A volume: one tet mesh of nested or touching closed meshes (VolumeBoundary), one medium per
// region (a cavity is a region whose coefficients are all zero), and the walk of a ray through
// its tets. Optical depth is exact: density is constant or linear inside each tet, so every
// segment of a walk integrates in closed form, region by region. The samplers that use it are
// media/FreeFlight.h and media/ShadowRay.h.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec4.hpp>

#include "base/Spectrum.h"
#include "media/PhaseFunction.h"
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
    // Transmittance and shadow rays walk exitQueryAfter_ tets of a region of constant density, then
    // find its exit with one query of the surface BVH (regionExit), where the tets between carry no
    // news; 0: walk every tet. Production keeps 1; tests and benchmarks set it (tests/ExitQueryAccess.h).
    friend struct ExitQueryAccess;

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

    bool deepShadows() const { return !clearance_.empty(); }
    // Balls around interior points that hold no boundary (empty unless deepShadows()).
    const ClearanceGrid& clearance() const { return clearance_; }
    // Region r's tets' mean chord; 0 where its density varies.
    double tetChord(int32_t r) const { return tetChord_[size_t(r)]; }

    // walk() for a stretch that needs only the optical depth: once exitQueryAfter_ segments are
    // walked, the walk is inside a region of constant density and worthAsking(medium, the region's
    // mean chord of a tet) says so, the rest of the way to the region's exit (or tMax) goes to
    // pass(medium, length) at once (false: stop), unless that exit is an interface the walk
    // crosses or too close to call. Returns where the ray left.
    template <class Visit, class Pass, class Worth>
    WalkExit walkToExit(const Ray& ray, WalkStart start, double tMax, Visit&& visit, Pass&& pass,
                        Worth&& worthAsking) const;
    // An exit through an interface that flights cross, index-matched, inside the walk.
    bool crossesAt(const RegionExit& e) const {
        return e.kind == RegionExit::Kind::Exit && mesh().surfaceFaceFront[e.triangle] != UINT32_MAX &&
               !stopsAt(e.triangle);
    }

private:
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
