// glTF 2.0 files the tests build: meshes (float positions, 32-bit indices, or compressed by
// KHR_draco_mesh_compression) in one buffer, nodes, materials, cameras and KHR_lights_punctual
// lights, written as .gltf with a .bin beside it or as one .glb.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "tet/TriangleMesh.h"

namespace tetglow::test {

class GltfBuilder {
public:
    GltfBuilder();

    // A mesh of one primitive (material -1: none); returns its index.
    int addMesh(const TriangleMesh& mesh, int material = -1);
    // A mesh of one primitive compressed with libdraco's encoder (KHR_draco_mesh_compression): its
    // accessors give count, min and max but no bufferView, and the extension is required.
    // `quantizationBits` 0 keeps the positions exact; `sequential` picks Draco's sequential
    // connectivity coding over Edgebreaker. Returns the mesh's index.
    int addDracoMesh(const TriangleMesh& mesh, int material = -1, int quantizationBits = 0, bool sequential = false);
    // A node; a root of the scene unless `root` is false (then make it some node's child). Returns its index.
    int addNode(nlohmann::json node, bool root = true);
    int addMaterial(nlohmann::json material);
    int addCamera(double yfov, double aspectRatio);
    int addLight(nlohmann::json light);  // KHR_lights_punctual

    nlohmann::json json;  // edit freely before writing
    std::string bin;      // the buffer's bytes

    // Writes `path` (.gltf) and <stem>.bin beside it; returns `path`.
    std::string writeGltf(const std::string& path) const;
    std::string writeGlb(const std::string& path) const;
    // The JSON as a GLB writes it (the buffer without a URI).
    nlohmann::json glbJson() const;

private:
    int addView(const std::string& bytes);
    int push(const char* key, nlohmann::json value);
};

}  // namespace tetglow::test
