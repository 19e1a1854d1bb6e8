// Free flights through a volume: the distance to the next interaction sampled exactly, by
// inverting the optical depth its walk integrates region by region, or by one exit query where a
// region of constant density is long against its tets; and the transmittance, a flight that
// cannot interact.
#pragma once
#include <optional>

#include "media/Volume.h"

namespace tetglow {

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

// Free flight along `ray` (unit direction) from `start` up to tMax, the distance sampled
// exactly for the hero channel's extinction (see SpectralPath). `ratios` are the path's
// pdf ratios (SpectralPath::r), for the spectral MIS weight of FreeFlight::glow.
// With `jump`, a flight in a region of constant density may find the region's exit by one
// query of the surface BVH and jump to its interaction, whose tet it then leaves unlocated.
FreeFlight sampleFlight(const Volume& volume, const Ray& ray, WalkStart start, double tMax, int hero, double u,
                        const RGB& ratios = RGB(1), bool jump = false);
// The stretch from `start` through the region of constant density it begins in, looking at
// most `depth` mean free paths of the region's smallest extinction ahead (and not beyond tMax).
// Nothing where the walk must decide (the ray only touches the medium, the region's density
// varies, or its exit is too close to another crossing to call) or where walking is cheaper
// (the region's mean free path is a few tet chords: sampleFlight's rule, for its mean extinction).
std::optional<RegionStretch> regionStretch(const Volume& volume, const Ray& ray, WalkStart start, double tMax,
                                           double depth);
// A free flight (see sampleFlight) inside `stretch`, without a walk: its interaction, which
// is left unlocated, or the stretch passed whole. Nothing where the interaction is too close
// to the stretch's end to call, or lies beyond an end that is not whole.
std::optional<FreeFlight> flightWithin(const Volume& volume, const RegionStretch& stretch, int hero, double u,
                                       const RGB& ratios = RGB(1));
// exp(-optical depth) from `start` to tMax or to where the ray leaves the medium (or
// stops at an interface).
RGB transmittance(const Volume& volume, const Ray& ray, WalkStart start, double tMax);

}  // namespace tetglow
