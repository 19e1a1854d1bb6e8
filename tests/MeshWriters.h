// Small writers of every mesh format tetglow reads, for the tests: each returns the file's bytes.
#pragma once
#include <string>
#include <vector>

#include "tet/TriangleMesh.h"

namespace tetglow::test {

// Polygons over shared positions, each counter-clockwise seen from outside.
struct PolygonMesh {
    std::vector<glm::dvec3> positions;
    std::vector<std::vector<uint32_t>> faces;
    TriangleMesh fanned() const;  // each polygon as the fan (v0 vk vk+1)
};

// The box [0, 2] x [0, 3] x [0, 4] (volume 24) as six quads.
PolygonMesh boxQuads();

std::string objText(const PolygonMesh& m);
std::string offText(const PolygonMesh& m);
std::string plyAscii(const PolygonMesh& m);
// Binary PLY with double positions, an extra property and a uchar count: its byte order chosen.
std::string plyBinary(const PolygonMesh& m, bool littleEndian);
// Each quad (v0 v1 v2 v3) as the strip (v0 v1 v3 v2), the strips parted by -1 in one list.
std::string plyStrips(const PolygonMesh& m);
std::string stlAscii(const TriangleMesh& m);
// Binary STL with the given 80-byte header (padded with spaces).
std::string stlBinary(const TriangleMesh& m, const std::string& header);

// glTF 2.0: meshes in one buffer (float positions, uint32 indices); nodes as given.
struct GltfNode {
    std::string name;
    int mesh = -1;  // index into the meshes, or -1
    std::vector<int> children;
    std::string transform;  // JSON members, e.g. "\"translation\": [1, 2, 3]"; "" for none
};
struct Gltf {
    std::string json, bin;
};
// `binUri`: the buffer's uri ("" for the GLB chunk).
Gltf gltf(const std::vector<TriangleMesh>& meshes, const std::vector<GltfNode>& nodes, const std::vector<int>& roots,
          const std::string& binUri);
std::string glb(const Gltf& g);  // g made with binUri ""
// Collada 1.4.1 with one node instancing the mesh as a polylist; `upAxis` "Y_UP" or "Z_UP".
// `bindShape` (16 numbers, row-major): the mesh instanced as a skin of one joint at the origin,
// with that bind-shape matrix ("" for a plain geometry).
std::string collada(const PolygonMesh& m, const std::string& upAxis, const std::string& bindShape = "");
std::string collada(const TriangleMesh& m, const std::string& upAxis);
// ASCII FBX 7.4 with one model holding the polygons.
std::string fbxAscii(const PolygonMesh& m);

}  // namespace tetglow::test
