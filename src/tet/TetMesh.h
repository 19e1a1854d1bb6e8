// The medium's interior as tetrahedra: compact arrays, face adjacency, exact boundary.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "tet/TriangleMesh.h"

namespace tetglow {

// Local faces: face j of a tet is opposite its vertex j. kInwardFace[j] lists the other three
// local vertices in the order whose normal points into a positively oriented tet.
inline constexpr int kInwardFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

struct TetMesh {
    // The surface's vertices come first, in the surface's order; interior Steiner points follow.
    std::vector<glm::dvec3> vertices;
    // Positively oriented: dot(v1 - v0, cross(v2 - v0, v3 - v0)) > 0.
    std::vector<std::array<uint32_t, 4>> tets;
    // adjacency[t][j], across face j: >= 0 is 4 * neighbour + the neighbour's local face;
    // < 0 is ~s for surface triangle s (the medium's boundary).
    std::vector<std::array<int32_t, 4>> adjacency;
    // The validated boundary, wound outward; its vertex ids index `vertices`.
    std::vector<std::array<uint32_t, 3>> surface;
    // surfaceFace[s] = 4 * tet + local face: the tet face that is surface triangle s, behind it
    // (on the side its normal points away from).
    std::vector<uint32_t> surfaceFace;

    size_t surfaceVertexCount = 0;

    // Regions, one per input surface (see VolumeBoundary): region r owns tets
    // [regionTets[r], regionTets[r + 1]), each region's in Morton order. A surface triangle is an
    // interface where there is a region in front of it too: its tet faces on both sides are
    // boundary faces (~s), and the walk decides what happens there.
    std::vector<uint32_t> regionTets{0};
    std::vector<int32_t> regionParent;  // the region around region r, -1 none
    // Per surface triangle: the regions behind and in front of it (-1: outside every region),
    // the tet face in front (UINT32_MAX where no region is), and {input surface, its triangle}.
    std::vector<std::array<int32_t, 2>> surfaceRegions;
    std::vector<uint32_t> surfaceFaceFront;
    std::vector<std::array<uint32_t, 2>> surfaceSource;

    static bool isBoundary(int32_t adj) { return adj < 0; }
    static uint32_t neighbourTet(int32_t adj) { return uint32_t(adj) >> 2; }
    static int neighbourFace(int32_t adj) { return adj & 3; }
    static uint32_t surfaceTriangle(int32_t adj) { return ~uint32_t(adj); }

    size_t regionCount() const { return regionParent.size(); }
    // The tet face across surface triangle s from tet face `face` (4 * tet + local face), or
    // UINT32_MAX where no region is on the other side.
    uint32_t across(uint32_t s, uint32_t face) const {
        return surfaceFace[s] == face ? surfaceFaceFront[s] : surfaceFace[s];
    }
    // The region owning tet t. Inline for the walk's every segment: one region needs no search.
    int32_t region(uint32_t t) const { return regionTets.size() <= 2 ? 0 : regionOf(t); }
    double tetVolume(uint32_t t) const;
    double regionVolume(int32_t r) const;         // sum of its tet volumes
    double regionSurfaceVolume(int32_t r) const;  // enclosed by its surface triangles (divergence theorem)
    double volume() const;                        // sum of tet volumes
    double surfaceVolume() const;                 // the boundary's own volume (divergence theorem)
    glm::dvec3 centroid(uint32_t t) const;
    size_t bytesPerTet() const { return sizeof(tets[0]) + sizeof(adjacency[0]); }
    TriangleMesh surfaceMesh() const;
    // The surface triangle on the other side of edge (a, b) of surface triangle s, found by
    // turning around the edge through the tets (no extra storage).
    uint32_t surfaceAcross(uint32_t s, uint32_t a, uint32_t b) const;

private:
    int32_t regionOf(uint32_t t) const;  // region() by binary search over regionTets
};

// Binary cache file: a header (version, key, checksum of the rest) and the arrays. Writing goes
// through a temporary file and a rename, so a reader never sees half an entry. `named`: as
// OutputWrite's (false for a cache entry, whose name the program chose).
void writeTetMesh(const TetMesh& mesh, uint64_t key, const std::string& path, bool named = true);

enum class CacheRead {
    Used,          // `mesh` holds the entry
    Absent,        // no file
    OtherVersion,  // written by another version of tetglow: not an error, only a rebuild
    Damaged,       // anything else: `problem` says what (a bad checksum, a FIFO, a bad index, ...)
};
// Never throws and never fills `mesh` from an entry that is not whole, so a bad cache only
// costs a new tetrahedralization. Reads at most kMaxCacheFileBytes.
CacheRead readTetMesh(TetMesh& mesh, uint64_t key, const std::string& path, std::string* problem = nullptr);

}  // namespace tetglow
