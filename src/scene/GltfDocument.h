// A glTF 2.0 file as data: its JSON (from a .gltf, or a GLB's JSON chunk), its buffers, the
// triangles of its mesh primitives and the world transform of every node of a scene. What the
// nodes mean (cameras, lights, materials) is read by scene/GltfScene.h.
//
// Geometry is read here from the accessors rather than through Assimp (scene/AssimpReader.h, which
// reads a glTF as one mesh file): a scene needs each primitive apart with its material index and
// each node with its own transform and extensions, which Assimp's merged, renamed and re-split
// meshes do not keep one to one. Every read is bounded: the buffers together within
// kMaxMeshFileBytes, every accessor inside its buffer view and buffer, every index inside its
// accessor, the placed triangles within kMaxSceneMeshTriangles.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "scene/JsonReader.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

struct GltfDocument {
    std::string path;
    nlohmann::json json;
    std::vector<std::string> buffers;  // the bytes of each buffer, at least its byteLength
    // The arrays every primitive looks into, listed once (their elements do not move with the document).
    std::vector<JsonValue> accessors, bufferViews;

    JsonValue root() const { return {&json, nlohmann::json::json_pointer(), path}; }
};

// A .gltf (JSON text) or .glb (binary container) file's bytes `data` read from `path`; buffers
// named by a relative URI are read from the file's folder (never outside it), `data:` URIs
// decoded. Throws InputError "<path>: <JSON pointer>: <problem>".
GltfDocument readGltfDocument(const std::string& path, std::string data);

// The JSON chunk of the GLB container `data` read from `path`, and its BIN chunk (the first
// buffer when that has no URI). Throws InputError "<path>: GLB container: <problem>".
std::pair<std::string, std::string> splitGlb(const std::string& data, const std::string& path);
// The GLB container of `json` and the BIN chunk `bin` (none when empty): splitGlb's inverse.
std::string joinGlb(std::string json, std::string bin);

// True when `data` is a GLB container (its first four bytes are "glTF").
bool isGlb(const std::string& data);

// Accessor `index` (a JSON integer into the document's "accessors"), checked to be of `type` with
// one of `componentTypes`, not sparse, and to count within what a scene may hold.
struct GltfAccessor {
    JsonValue value;  // the accessor's object
    uint64_t count = 0;
    int64_t componentType = 0;
};
GltfAccessor gltfAccessor(const GltfDocument& doc, const JsonValue& index, const char* type,
                          std::initializer_list<int64_t> componentTypes);

// The bytes of buffer view `index` (a JSON integer into the document's "bufferViews"), checked to
// lie inside its buffer.
struct GltfBufferView {
    std::string_view bytes;
    JsonValue value;  // the buffer view's object
};
GltfBufferView gltfBufferView(const GltfDocument& doc, const JsonValue& index);

// An object's extension `name` (its "extensions" object's key `name`), or a false value.
JsonValue gltfExtension(JsonObject& o, const char* name);

// The triangles of mesh primitive `primitive` (an object of a mesh's "primitives") in the mesh's
// own frame: POSITION, with its indices where it has them; modes 4 (triangles), 5 (strip) and 6
// (fan). Other modes (points, lines) give an empty mesh and a warning. A primitive compressed by
// KHR_draco_mesh_compression is decoded (scene/GltfDraco.h).
TriangleMesh primitiveTriangles(const GltfDocument& doc, const JsonValue& primitive,
                                std::vector<std::string>* warnings);

struct GltfNode {
    int index = 0;     // into the document's "nodes"
    glm::dmat4 world;  // the product of the local transforms of the node and its ancestors
};

// The document's scene: its "scene", else the first of its "scenes".
JsonValue sceneOf(const GltfDocument& doc);

// Every node of the document's scene (its "scene", else the first), parents before children.
// A node reached twice (a node with two parents, or a cycle) is an error.
std::vector<GltfNode> sceneNodes(const GltfDocument& doc);

}  // namespace tetglow
