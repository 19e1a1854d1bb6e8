// A procedural cumulus cloud for the cloud-study scenes: a puffy dome on a flat-ish base.
#pragma once
#include <cstdint>

#include "tet/TriangleMesh.h"

namespace tetglow {

struct CloudParams {
    int subdivisions = 5;     // of the icosphere it is built from, 1 to 8: 20 * 4^s triangles
    uint32_t seed = 1;        // any value; each gives another cloud
    int bumps = 7;            // large puffs (a crown and a ring of towers around it), 1 to 16
    double roughness = 0.05;  // height of the small puffs that cover it, relative to its radius, 0 to 0.15
};

// Exactly 2 units wide along x and 1.2 tall along y, up to float rounding, and 1 to 2 deep along
// z (the longer horizontal side is turned to x). Star-shaped about the origin, which lies inside
// about a quarter of the way up: every ray from the origin leaves through the surface once, at a
// radius that is a smooth positive function of the ray's direction. That function moves the icosphere's vertices
// radially, so every triangle keeps facing away from the origin and no two can cross, at any resolution and seed. The
// mesh is closed, 2-manifold, outward-wound and free of degenerate triangles, with positions rounded to float. The same
// parameters give the same mesh (no standard-library distributions, whose numbers differ between implementations).
// Throws InputError for parameters outside the ranges above.
TriangleMesh makeCloud(const CloudParams& params = {});

}  // namespace tetglow
