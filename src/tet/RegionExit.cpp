#include "tet/RegionExit.h"

#include <algorithm>
#include <cmath>

namespace tetglow {

RegionExit regionExit(const TetTraversal& volume, const Ray& ray, int32_t region, double tFrom, double tTo) {
    const TetMesh& mesh = volume.mesh();
    const RayProjection project(ray);
    // Closer than this, two crossings' computed t may be out of order: the walk decides.
    const double tolerance = 1e-9 * (1.0 + std::abs(tFrom) + (std::isfinite(tTo) ? std::abs(tTo) : 0.0));
    RegionExit first{RegionExit::Kind::None, 0, 0, INFINITY};
    double second = INFINITY;  // the next exit's t
    // Decides triangle s; false where the ray passes outside it, near an edge or a vertex (the
    // exact crossing may then be a neighbour's, which the grown triangles need not propose).
    auto decide = [&](uint32_t s) {
        // The triangle's tet face on the region's side (an interface has one on each side).
        uint32_t face = mesh.surfaceFace[s];
        if (mesh.region(face >> 2) != region) {
            face = mesh.surfaceFaceFront[s];
            if (face == UINT32_MAX || mesh.region(face >> 2) != region) return true;
        }
        const auto& tv = mesh.tets[face >> 2];
        const int* f = kInwardFace[face & 3];
        const uint32_t ia = tv[f[0]], ib = tv[f[1]], ic = tv[f[2]];
        const RayProjection::Point a = project(mesh.vertices[ia]), b = project(mesh.vertices[ib]),
                                   c = project(mesh.vertices[ic]);
        const double ab = side(ia, a.uv, ib, b.uv), bc = side(ib, b.uv, ic, c.uv), ca = side(ic, c.uv, ia, a.uv);
        if (ab > 0 && bc > 0 && ca > 0) return true;  // entering through it
        // Wound inward, the face is clockwise around the origin exactly where the ray leaves through it.
        if (!(ab < 0 && bc < 0 && ca < 0)) return false;
        // The same face wound outward, (a, c, b), as the walk passes it.
        const double t = crossingT(a.t, c.t, b.t, -ca, -bc, -ab);
        if (t < tFrom - tolerance) return true;  // an earlier pass through the region
        if (t < first.t) {
            if (first.triangle != s || first.kind != RegionExit::Kind::Exit) second = first.t;
            first = {RegionExit::Kind::Exit, s, face >> 2, t};
        } else if (t < second && s != first.triangle) {
            second = t;
        }
        return true;
    };
    double ahead = INFINITY;  // the nearest candidate past tFrom
    // Past the first exit found (and the tolerance of a tie with it) no candidate can change the answer.
    volume.bvh().visitCandidates(ray, tFrom - tolerance, tTo + tolerance, [&](const SurfaceHit& candidate) {
        if (candidate.t > tFrom + tolerance) ahead = std::min(ahead, candidate.t);
        if (!decide(candidate.triangle))
            anySurfaceAround(mesh, candidate.triangle, [&](uint32_t s) {
                decide(s);
                return false;
            });
        return first.kind == RegionExit::Kind::Exit ? first.t + tolerance : INFINITY;
    });
    // A closed region has an exit along every ray: none found is not as expected.
    if (first.kind == RegionExit::Kind::None) return std::isinf(tTo) ? RegionExit{} : first;
    if (first.t <= tFrom + tolerance || second - first.t <= tolerance || std::abs(first.t - tTo) <= tolerance)
        return {};
    // A candidate well before the exit found that decided nothing there: where the ray passes a
    // vertex along triangles nearly parallel to it, the exit the walk takes may be one no
    // candidate proposed.
    if (ahead < std::min(first.t, tTo) - 1e-4 * (1 + std::abs(first.t))) return {};
    if (first.t > tTo) return {RegionExit::Kind::None};
    return first;
}

}  // namespace tetglow
