#include "cli/MediaReport.h"

#include <cstdio>

#include "tet/InteriorRepair.h"

namespace tetglow::cli {

void printRepairs(const std::string& medium, const ValidationReport& report) {
    const RepairReport& r = report.repair;
    if (!r.applied) {
        // A clean mesh's own notes (welded vertices, flipped windings) change nothing it encloses
        // but the flips, which are worth a line.
        if (report.flippedTriangles)
            std::fprintf(stderr, "medium %s: repaired: flipped %zu inward-wound triangles\n", medium.c_str(),
                         report.flippedTriangles);
        return;
    }
    std::fprintf(stderr, "medium %s: repaired: %s\n", medium.c_str(), r.summary().c_str());
    const double share = r.boundaryArea > 0 ? r.spannedArea / r.boundaryArea : 0;
    if (share > kLargeHoleShare)
        std::fprintf(stderr,
                     "warning: medium %s: holes spanning %.3g%% of its surface were filled to make it a solid; to "
                     "refuse it instead, give the medium \"tetgen\": {\"strict\": true} (tetrahedralize --strict "
                     "lists every problem); to see the fill, `tetglow tetrahedralize MESH -o fill.vtk` marks the "
                     "spanned faces for ParaView\n",
                     medium.c_str(), 100 * share);
}

void printVolumes(const Scene& scene) {
    for (const SceneVolume& v : scene.volumes()) {
        std::fprintf(stderr, "medium %s: %zu tets, %zu Steiner points, %s in %.2f s\n", v.name.c_str(),
                     v.volume->mesh().tets.size(), v.steinerPoints,
                     v.stats.fromCache ? "read from the cache" : "tetrahedralized", v.stats.seconds);
        for (size_t r = 0; r < v.repairs.size() && r < v.regionMedium.size(); ++r)
            printRepairs(scene.desc().media[v.regionMedium[r]].name, v.repairs[r]);
    }
}

void printRepairs(const SceneDesc& desc) {
    for (const MediumDesc& m : desc.media) {
        TriangleMesh mesh = m.boundary;
        try {
            printRepairs(m.name, prepareSurface(mesh, m.tetOptions.strict));
        } catch (const InputError& e) {
            throw InputError(m.name + ": " + e.what());
        }
    }
}

}  // namespace tetglow::cli
