#include "scene/GltfDocument.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "base/ExternalReference.h"
#include "base/InputFile.h"
#include "scene/AssimpReader.h"
#include "scene/GltfDraco.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;

uint32_t readU32(const std::string& data, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, data.data() + at, 4);  // GLB is little-endian, as every machine tetglow builds on
    return v;
}

}  // namespace

std::string joinGlb(std::string json, std::string bin) {
    while (json.size() % 4) json.push_back(' ');
    while (bin.size() % 4) bin.push_back('\0');
    std::string out;
    const auto u32 = [&out](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(kGlbMagic);
    u32(2);
    u32(uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    u32(uint32_t(json.size()));
    u32(kJsonChunk);
    out += json;
    if (!bin.empty()) {
        u32(uint32_t(bin.size()));
        u32(kBinChunk);
        out += bin;
    }
    return out;
}

std::pair<std::string, std::string> splitGlb(const std::string& data, const std::string& path) {
    const auto fail = [&](const std::string& what) { throw InputError(path + ": GLB container: " + what); };
    if (data.size() < 20) fail("shorter than its 12-byte header and one chunk header");
    if (readU32(data, 4) != 2) fail("version " + std::to_string(readU32(data, 4)) + ", only 2 is read");
    if (readU32(data, 8) != data.size())
        fail("the header gives a length of " + std::to_string(readU32(data, 8)) + " bytes, the file has " +
             std::to_string(data.size()));
    std::string json, bin;
    for (size_t at = 12, chunk = 0; at < data.size(); ++chunk) {
        if (data.size() - at < 8) fail("a chunk header is cut off at byte " + std::to_string(at));
        const uint64_t length = readU32(data, at), type = readU32(data, at + 4);
        if (length > data.size() - at - 8)
            fail("chunk " + std::to_string(chunk) + " runs past the end of the file (" + std::to_string(length) +
                 " bytes)");
        std::string bytes = data.substr(at + 8, length);
        if (chunk == 0 && type != kJsonChunk) fail("the first chunk is not JSON");
        if (chunk == 0) json = std::move(bytes);
        if (chunk == 1 && type == kBinChunk) bin = std::move(bytes);
        at += 8 + length;
    }
    return {std::move(json), std::move(bin)};
}

namespace {

std::string decodeBase64(const std::string& text, const JsonValue& where) {
    std::string out;
    out.reserve(text.size() / 4 * 3);
    uint32_t bits = 0;
    int count = 0;
    for (const char c : text) {
        int v = -1;
        if (c >= 'A' && c <= 'Z') v = c - 'A';
        if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
        if (c >= '0' && c <= '9') v = c - '0' + 52;
        if (c == '+') v = 62;
        if (c == '/') v = 63;
        if (c == '=') break;
        if (v < 0) where.error("not base64: the character '" + std::string(1, c) + "'");
        bits = (bits << 6) | uint32_t(v);
        if (++count % 4 == 0) {
            out.push_back(char(bits >> 16));
            out.push_back(char(bits >> 8));
            out.push_back(char(bits));
        }
    }
    if (count % 4 == 2) out.push_back(char(bits >> 4));
    if (count % 4 == 3) {
        out.push_back(char(bits >> 10));
        out.push_back(char(bits >> 2));
    }
    return out;
}

// A buffer's bytes: a data: URI, a file in the glTF's folder, or the GLB's BIN chunk.
std::string readBuffer(const JsonValue& v, const fs::path& dir, std::string& glbBin, uint64_t& bytesRead) {
    JsonObject o(v);
    const uint64_t length = uint64_t(o["byteLength"].integer(1, int64_t(kMaxMeshFileBytes)));
    std::string bytes;
    const JsonValue uri = o["uri"];
    if (!uri) {
        if (glbBin.empty()) v.error("a buffer without a \"uri\" must be a GLB's binary chunk, and there is none");
        bytes = std::move(glbBin);
        glbBin.clear();
    } else if (const std::string text = uri.string(); text.rfind("data:", 0) == 0) {
        const size_t comma = text.find(',');
        if (comma == std::string::npos || text.compare(comma - 7, 7, ";base64") != 0)
            uri.error("a data: URI must be base64 (data:...;base64,...)");
        bytes = decodeBase64(text.substr(comma + 1), uri);
    } else {
        // Another scheme than data: is no file; a file stays in the scene's folder, links resolved.
        if (text.find(':') != std::string::npos)
            uri.error("'" + shorten(text) + "' is not a file in the glTF's folder (only relative paths inside it)");
        const std::optional<std::string> decoded = percentDecoded(text);
        if (!decoded) uri.error("a '%' not followed by two hex digits");
        fs::path file;
        try {
            file = resolveReference(dir, *decoded);
        } catch (const InputError& e) {
            uri.error(e.what());
        }
        bytes = readInputFile(file.string(), kMaxMeshFileBytes - bytesRead, "a glTF's buffers");
    }
    if (bytes.size() < length)
        v.error("byteLength is " + std::to_string(length) + ", but the buffer holds " + std::to_string(bytes.size()) +
                " bytes");
    bytesRead += bytes.size();
    if (bytesRead > kMaxMeshFileBytes) v.error("the buffers together pass the 1024 MiB limit for a mesh");
    return bytes;
}

int componentBytes(int64_t componentType) {
    switch (componentType) {
        case 5121: return 1;  // UNSIGNED_BYTE
        case 5123: return 2;  // UNSIGNED_SHORT
        case 5125:            // UNSIGNED_INT
        case 5126: return 4;  // FLOAT
        default: return 0;
    }
}

// The bytes of accessor `index` and how to step through them, every element checked to lie in
// its buffer view and buffer.
struct AccessorView {
    const char* data = nullptr;
    uint64_t count = 0, stride = 0;
    int64_t componentType = 0;
};

AccessorView accessorView(const GltfDocument& doc, const JsonValue& indexValue, const char* type,
                          std::initializer_list<int64_t> componentTypes) {
    const GltfAccessor accessor = gltfAccessor(doc, indexValue, type, componentTypes);
    JsonObject o(accessor.value);
    AccessorView a{nullptr, accessor.count, 0, accessor.componentType};
    const uint64_t components = std::strcmp(type, "VEC3") == 0 ? 3 : 1;
    const uint64_t element = components * uint64_t(componentBytes(a.componentType));
    const GltfBufferView view = gltfBufferView(doc, o["bufferView"]);
    JsonObject viewObject(view.value);
    const uint64_t viewLength = view.bytes.size();
    a.stride = viewObject["byteStride"] ? uint64_t(viewObject["byteStride"].integer(4, 252)) : element;
    if (a.stride < element)
        viewObject["byteStride"].error("smaller than one element (" + std::to_string(element) + " bytes)");
    const uint64_t offset = o["byteOffset"] ? uint64_t(o["byteOffset"].integer(0)) : 0;
    // offset + stride * (count - 1) + element <= viewLength, without overflow.
    if (offset > viewLength || element > viewLength - offset ||
        (a.count - 1) > (viewLength - offset - element) / a.stride)
        accessor.value.error("the accessor's " + std::to_string(a.count) +
                             " elements run past the end of its buffer view (" + std::to_string(viewLength) +
                             " bytes)");
    a.data = view.bytes.data() + offset;
    return a;
}

std::vector<uint32_t> readIndices(const GltfDocument& doc, const JsonValue& index, uint64_t vertexCount) {
    const AccessorView a = accessorView(doc, index, "SCALAR", {5121, 5123, 5125});
    std::vector<uint32_t> out(a.count);
    const int bytes = componentBytes(a.componentType);
    for (uint64_t i = 0; i < a.count; ++i) {
        uint32_t value = 0;
        std::memcpy(&value, a.data + i * a.stride, size_t(bytes));
        if (value >= vertexCount)
            index.error("index " + std::to_string(value) + " (element " + std::to_string(i) + ") is past the " +
                        std::to_string(vertexCount) + " vertices of POSITION");
        out[i] = value;
    }
    return out;
}

glm::dmat4 localTransform(JsonObject& o) {
    if (auto m = o["matrix"]) {
        const std::vector<double> v = m.numbers(16, kCoordinate);
        if (v[3] != 0 || v[7] != 0 || v[11] != 0 || v[15] != 1)
            m.fail("an affine 4x4 matrix, column-major (elements 3, 7, 11, 15: 0, 0, 0, 1)");
        return glm::make_mat4(v.data());  // column-major, as glTF stores it
    }
    glm::dvec3 t(0), s(1);
    glm::dquat r(1, 0, 0, 0);
    if (auto f = o["translation"]) t = f.vec3();
    if (auto f = o["scale"]) s = f.vec3();
    if (auto f = o["rotation"]) {
        const std::vector<double> q = f.numbers(4, {.lo = -1, .hi = 1});
        r = glm::normalize(glm::dquat(q[3], q[0], q[1], q[2]));  // glTF writes x, y, z, w
        if (!(glm::length(r) > 0.5)) f.fail("a unit quaternion [x, y, z, w]");
    }
    return glm::translate(glm::dmat4(1), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1), s);
}

}  // namespace

bool isGlb(const std::string& data) { return data.size() >= 4 && readU32(data, 0) == kGlbMagic; }

JsonValue gltfExtension(JsonObject& o, const char* name) {
    const JsonValue e = o["extensions"];
    return e ? JsonObject(e)[name] : JsonValue(nullptr, nlohmann::json::json_pointer(), "");
}

GltfAccessor gltfAccessor(const GltfDocument& doc, const JsonValue& index, const char* type,
                          std::initializer_list<int64_t> componentTypes) {
    const std::vector<JsonValue>& accessors = doc.accessors;
    if (accessors.empty()) index.error("the file has no accessors");
    const JsonValue v = accessors[size_t(index.integer(0, int64_t(accessors.size()) - 1))];
    JsonObject o(v);
    if (o["sparse"]) o["sparse"].error("sparse accessors are not read");
    if (o["type"].string() != type) o["type"].fail(std::string("\"") + type + "\"");
    const int64_t componentType = o["componentType"].integer(0);
    bool allowed = false;
    for (const int64_t t : componentTypes) allowed |= componentType == t;
    if (!allowed) o["componentType"].error("this component type is not allowed here");
    // No primitive may hold more than the triangles a whole scene may (a strip: count - 2).
    const auto count = uint64_t(o["count"].integer(1, 3 * int64_t(kMaxSceneMeshTriangles)));
    return {v, count, componentType};
}

GltfBufferView gltfBufferView(const GltfDocument& doc, const JsonValue& index) {
    const std::vector<JsonValue>& views = doc.bufferViews;
    if (views.empty()) index.error("the file has no bufferViews");
    const JsonValue v = views[size_t(index.integer(0, int64_t(views.size()) - 1))];
    JsonObject view(v);
    const JsonValue bufferIndex = view["buffer"];
    if (doc.buffers.empty()) bufferIndex.error("the file has no buffers");
    const std::string& buffer = doc.buffers.at(size_t(bufferIndex.integer(0, int64_t(doc.buffers.size()) - 1)));
    const uint64_t offset = view["byteOffset"] ? uint64_t(view["byteOffset"].integer(0)) : 0;
    const uint64_t length = uint64_t(view["byteLength"].integer(1));
    if (offset > buffer.size() || length > buffer.size() - offset)
        v.error("the buffer view runs past the end of its buffer (" + std::to_string(buffer.size()) + " bytes)");
    return {std::string_view(buffer).substr(offset, length), v};
}

GltfDocument readGltfDocument(const std::string& path, std::string data) {
    GltfDocument doc;
    doc.path = path;
    std::string glbBin;
    if (isGlb(data)) std::tie(data, glbBin) = splitGlb(data, path);
    // The JSON within a scene file's limit: parsed, it takes many times its size.
    if (data.size() > kMaxSceneFileBytes)
        throw InputError(path + ": its JSON is " + std::to_string(data.size() / kMiB) +
                         " MiB, larger than the 64 MiB limit for a scene (embedded data: URIs count; put the "
                         "buffers in a .bin or a GLB)");
    doc.json = parseJson(data, path);
    data.clear();
    JsonObject root(doc.root());
    const JsonValue version = JsonObject(root["asset"])["version"];
    if (version.string().rfind("2.", 0) != 0) version.fail("\"2.x\" (glTF 2.0)");
    uint64_t bytesRead = 0;
    const fs::path dir = fs::path(path).parent_path();
    if (auto buffers = root["buffers"])
        for (const JsonValue& b : buffers.array()) doc.buffers.push_back(readBuffer(b, dir, glbBin, bytesRead));
    if (auto f = root["accessors"]) doc.accessors = f.array();
    if (auto f = root["bufferViews"]) doc.bufferViews = f.array();
    return doc;
}

TriangleMesh primitiveTriangles(const GltfDocument& doc, const JsonValue& primitive,
                                std::vector<std::string>* warnings) {
    JsonObject o(primitive);
    const int64_t mode = o["mode"] ? o["mode"].integer(0, 6) : 4;
    if (mode < 4) {
        if (warnings)
            warnings->push_back(primitive.where() + ": points and lines are skipped (mode " + std::to_string(mode) +
                                ")");
        return {};
    }
    TriangleMesh mesh;
    std::vector<uint32_t> index;
    if (const JsonValue draco = gltfExtension(o, "KHR_draco_mesh_compression")) {
        if (mode != 4) o["mode"].error("a Draco-compressed primitive holds triangles (mode 4)");
        decodeDracoPrimitive(doc, primitive, draco, mesh.positions, index);
    } else {
        const JsonValue position = JsonObject(o["attributes"])["POSITION"];
        const AccessorView p = accessorView(doc, position, "VEC3", {5126});
        mesh.positions.resize(p.count);
        for (uint64_t i = 0; i < p.count; ++i) {
            float xyz[3];
            std::memcpy(xyz, p.data + i * p.stride, sizeof xyz);
            for (int k = 0; k < 3; ++k)
                if (!std::isfinite(xyz[k])) position.error("vertex " + std::to_string(i) + " is not finite");
            mesh.positions[i] = {xyz[0], xyz[1], xyz[2]};
        }
        if (auto f = o["indices"]) {
            index = readIndices(doc, f, p.count);
        } else {
            index.resize(p.count);
            for (uint64_t i = 0; i < p.count; ++i) index[i] = uint32_t(i);
        }
    }
    const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (a != b && b != c && a != c) mesh.triangles.push_back({a, b, c});
    };
    if (mode == 4)
        for (size_t i = 0; i + 2 < index.size(); i += 3) add(index[i], index[i + 1], index[i + 2]);
    if (mode == 5)  // every other triangle of a strip reversed, so that all face the same way
        for (size_t i = 0; i + 2 < index.size(); ++i)
            i % 2 ? add(index[i + 1], index[i], index[i + 2]) : add(index[i], index[i + 1], index[i + 2]);
    if (mode == 6)
        for (size_t i = 1; i + 1 < index.size(); ++i) add(index[0], index[i], index[i + 1]);
    if (mesh.triangles.size() > kMaxSceneMeshTriangles)
        primitive.error("more than " + std::to_string(kMaxSceneMeshTriangles) + " triangles");
    return mesh;
}

JsonValue sceneOf(const GltfDocument& doc) {
    JsonObject root(doc.root());
    const JsonValue scenesValue = root["scenes"];
    const std::vector<JsonValue> scenes = scenesValue ? scenesValue.array() : std::vector<JsonValue>{};
    if (scenes.empty()) doc.root().error("no scene (\"scenes\" is missing or empty)");
    const JsonValue chosen = root["scene"];
    return scenes[chosen ? size_t(chosen.integer(0, int64_t(scenes.size()) - 1)) : 0];
}

std::vector<GltfNode> sceneNodes(const GltfDocument& doc) {
    JsonObject root(doc.root());
    const JsonValue scene = sceneOf(doc);
    const JsonValue nodesValue = root["nodes"];
    const std::vector<JsonValue> nodes = nodesValue ? nodesValue.array() : std::vector<JsonValue>{};
    std::vector<bool> seen(nodes.size(), false);
    std::vector<GltfNode> out, stack;  // depth-first without recursion: a chain of nodes may be long
    const auto push = [&](const JsonValue& index, const glm::dmat4& parent) {
        if (nodes.empty()) index.error("the file has no nodes");
        const auto i = size_t(index.integer(0, int64_t(nodes.size()) - 1));
        if (seen[i]) index.error("node " + std::to_string(i) + " is reached twice (a node has at most one parent)");
        seen[i] = true;
        JsonObject o(nodes[i]);
        stack.push_back({int(i), parent * localTransform(o)});
    };
    if (auto roots = JsonObject(scene)["nodes"]) {
        const std::vector<JsonValue> r = roots.array();
        for (auto it = r.rbegin(); it != r.rend(); ++it) push(*it, glm::dmat4(1));
    }
    while (!stack.empty()) {
        const GltfNode node = stack.back();
        stack.pop_back();
        out.push_back(node);
        // Pushed last to first, so that the nodes come out in the file's order (the "first" camera).
        if (auto children = JsonObject(nodes[size_t(node.index)])["children"]) {
            const std::vector<JsonValue> c = children.array();
            for (auto it = c.rbegin(); it != c.rend(); ++it) push(*it, node.world);
        }
    }
    return out;
}

}  // namespace tetglow
