// The repair of broken meshes (validation, then exact splitting of crossings, the constrained
// tetrahedralization in its box and the winding-number labels), on small meshes whose corners lie
// on an integer grid: coincident vertices, shared and collinear edges, coplanar and touching
// triangles are then common, as in the meshes people bring. Input: a vertex count n (at most
// kMaxVertices), n corners of three signed bytes each, then triangles as three bytes each (indices
// modulo n, at most kMaxTriangles); bytes left over are ignored.
#include "FuzzInput.h"
#include "base/ChildProcess.h"
#include "tet/InteriorRepair.h"

namespace {

constexpr size_t kMaxVertices = 32, kMaxTriangles = 48;

}  // namespace

// CGAL's autorefinement and TetGen run in child processes, capped below libFuzzer's own limits
// (fuzz/run.sh: -timeout=10, -rss_limit_mb=2048), so that a child that never finishes is its
// error, not a hang of the target.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    tetglow::capChildLimits({512.0 * (1 << 20), 3});
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    const size_t n = std::min<size_t>(data[0], kMaxVertices);
    if (n == 0 || size < 1 + 3 * n) return 0;
    tetglow::TriangleMesh mesh;
    for (size_t v = 0; v < n; ++v) {
        const uint8_t* c = data + 1 + 3 * v;
        mesh.positions.push_back({double(int8_t(c[0])), double(int8_t(c[1])), double(int8_t(c[2]))});
    }
    for (size_t at = 1 + 3 * n; at + 3 <= size && mesh.triangles.size() < kMaxTriangles; at += 3)
        mesh.triangles.push_back({uint32_t(data[at] % n), uint32_t(data[at + 1] % n), uint32_t(data[at + 2] % n)});
    try {
        tetglow::prepareSurface(mesh, false);
    } catch (const tetglow::InputError&) {}
    return 0;
}
