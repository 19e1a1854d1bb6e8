// Validated surface -> TetMesh, through TetGen with the boundary preserved (-pY).
#pragma once
#include <string>
#include <vector>

#include "tet/MeshValidation.h"
#include "tet/RepairClock.h"
#include "tet/TetMesh.h"

namespace tetglow {

struct TetOptions {
    // Steiner points only where a scene needs them (heterogeneous density): 0 disables each.
    double radiusEdgeRatio = 0;  // TetGen -q
    double maxVolume = 0;        // TetGen -a
    std::string cacheDir;        // "" = $TETGLOW_CACHE_DIR, else $XDG_CACHE_HOME/tetglow, else ~/.cache/tetglow
    bool useCache = true;
    // Refuse a mesh that fails validation (today's checks) instead of repairing it (InteriorRepair.h).
    bool strict = false;
    // Seconds the repair of each mesh may take before it stops and the mesh is approximated by
    // the winding number on a grid instead, with a warning naming the stage and its figures
    // (RepairClock.h); 0 approximates every mesh that needs repair.
    double repairTimeLimit = kRepairTimeLimit;

    std::string switches() const;  // the TetGen command line these options give
};

struct TetStats {
    double seconds = 0;  // validation + tetrahedralization (or cache read)
    bool fromCache = false;
    std::string cacheFile;     // "" when caching is off or the directory is not writable
    std::string cacheProblem;  // why cacheFile is "" (no cache folder, the write's error); "" otherwise
    std::string cacheWarning;  // why a cache entry found was not used (also printed to stderr); "" if none
    // Tets larger than TetOptions::maxVolume, and why (also printed to stderr); "" if none.
    std::string maxVolumeWarning;
    // The meshes whose boundary is approximate (winding-number labels on a grid, WindingGrid.h)
    // because their repair or TetGen failed, each named with the failure and where its problems
    // lie (also printed to stderr); "" if none.
    std::string approximateWarning;
};

// The most tets a tetrahedralization may have (about 3 GB with TetGen's own data): a max volume
// that asks for more is an InputError before TetGen starts, instead of hours of refinement.
inline constexpr double kMaxTets = 1e7;
void checkTetCount(double volume, double maxVolume);

// Validates and repairs `surface` (see prepareSurface), then tetrahedralizes its interior.
// TetGen runs in a child process, so its crashes and thrown ints become InputErrors here; unless
// `strict`, TetGen failing is answered by approximating the surfaces (approximateSurface) and
// trying once more, with a warning.
TetMesh tetrahedralize(TriangleMesh surface, const TetOptions& options = {}, TetStats* stats = nullptr,
                       ValidationReport* report = nullptr);

// Several closed surfaces, nested or touching along shared triangles, in one TetGen run
// (-pYnA): every triangle is tet faces, every tet belongs to a region (one per surface, see
// VolumeBoundary). Errors name the surface by `names` (one per surface; "" adds no name).
TetMesh tetrahedralize(std::vector<TriangleMesh> surfaces, const std::vector<std::string>& names,
                       const TetOptions& options = {}, TetStats* stats = nullptr,
                       std::vector<ValidationReport>* reports = nullptr);

// TetGen on a surface as it is, without validation or cache: shows what tetglow survives when
// TetGen fails (0 tets, a thrown int, a crash), each as an InputError. For tests.
TetMesh tetrahedralizeUnchecked(const TriangleMesh& surface, const std::string& switches);

}  // namespace tetglow
