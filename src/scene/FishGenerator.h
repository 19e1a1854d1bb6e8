// The project's own demo medium: a procedural deep-sea fish (anglerfish-like head, dorsal, anal,
// pectoral and forked caudal fins) with a glowing lure bulb on a stalk (the illicium) from its head.
#pragma once
#include "tet/TriangleMesh.h"

namespace tetglow {

// Resolution knobs scale the triangle count smoothly: about 1.1 * rings * segments triangles
// for the body (the lure adds at most a fifth), from about a hundred at 8 x 8 to millions. Rings and segments must stay
// within a factor of 4 of each other; similar values give the best-shaped triangles.
struct FishParams {
    int rings = 112;             // cross-sections from nose to tail, 8 to 2048
    int segments = 96;           // vertices around the largest cross-section, 8 to 2048
    double finThickness = 0.03;  // of the fins (the caudal fin's root is thicker), 0.02 to 0.08
    double tailFork = 0.18;      // how far the caudal lobes reach behind the fork's notch, 0 to 0.3
    double lureRadius = 0.055;   // of the lure bulb, 0.02 to 0.1, or 0 for no lure
};

// About 2 units long with the nose at +x, back at +y, mirror-symmetric about z = 0; the lure
// is a second closed shell, a bulb just ahead of and above the nose on a stalk that rises from
// just clear of the top of the head. Every resolution is closed,
// 2-manifold, outward-wound, free of degenerate triangles and of self-intersections, with
// positions rounded to float. Throws InputError for parameters outside the ranges above.
TriangleMesh makeFish(const FishParams& params = {});

// The showcase's organs, for the same params as the body they go in, each a set of closed icosphere
// shells nested inside makeFish(params) with clearance: every vertex is checked to lie inside the
// body (exactly), and an InputError says so when the body is too coarse to hold them (below about
// 24 rings or segments).
TriangleMesh makeFishPhotophores(const FishParams& params = {});  // two rows of light organs along the belly
TriangleMesh makeFishEyes(const FishParams& params = {});         // one large eye on each side of the head
TriangleMesh makeFishLureCore(const FishParams& params = {});     // the glowing core inside the lure bulb

}  // namespace tetglow
