// Where a ray inside a region leaves it, in one query of the surface BVH instead of a walk of
// every tet on the way: what a shadow ray through a homogeneous region needs.
#pragma once
#include <cstdint>

#include "base/Ray.h"
#include "tet/TetTraversal.h"

namespace tetglow {

struct RegionExit {
    enum class Kind {
        Exit,    // leaves through `triangle` at t, from `tet` (the region's tet behind that face)
        None,    // does not leave before tTo
        Unsure,  // two crossings, or a crossing and tFrom or tTo, too close to order: walk instead
    };
    Kind kind = Kind::Unsure;
    uint32_t triangle = 0, tet = 0;
    double t = 0;
};

// The first exit of the ray from region `region` after tFrom, where the walk has the ray inside it
// (just past a tet face at tFrom). The BVH's grown triangles propose the candidates; each is
// decided by the walk's own exact tests (the same projection of the same vertices, side() with
// simulation of simplicity), so the exit is the face the walk would leave through, and its t the
// walk's to rounding of the last bits.
RegionExit regionExit(const TetTraversal& volume, const Ray& ray, int32_t region, double tFrom, double tTo);

}  // namespace tetglow
