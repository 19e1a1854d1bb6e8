// withDracoDecoded (scene/GltfDraco.h): Draco primitives rewritten as plain accessors.
#include <algorithm>
#include <cstring>

#include "base/InputFile.h"
#include "scene/GltfDraco.h"

namespace tetglow {
namespace {

std::string base64(const std::string& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 2]));
        for (size_t k = 0; k < 4; ++k) out.push_back(i + k <= bytes.size() ? digits[(v >> (18 - 6 * k)) & 63] : '=');
    }
    return out;
}

// One decoded primitive: where it lies in the document, and its bytes in the new buffer.
struct Decoded {
    std::string primitive;  // JSON pointer
    int64_t position = 0;
    std::optional<int64_t> indices;
    size_t positionsAt = 0, indicesAt = 0, vertices = 0, corners = 0;
};

}  // namespace

std::optional<std::string> withDracoDecoded(const std::string& path, const std::string& data) {
    if (data.find("KHR_draco_mesh_compression") == std::string::npos) return std::nullopt;
    GltfDocument doc = readGltfDocument(path, data);
    std::string bytes;
    std::vector<Decoded> decoded;
    JsonObject root(doc.root());
    if (const JsonValue meshes = root["meshes"])
        for (const JsonValue& mesh : meshes.array())
            for (const JsonValue& p : JsonObject(mesh)["primitives"].array()) {
                JsonObject o(p);
                const JsonValue draco = gltfExtension(o, "KHR_draco_mesh_compression");
                if (!draco) continue;
                std::vector<glm::dvec3> positions;
                std::vector<uint32_t> corners;
                decodeDracoPrimitive(doc, p, draco, positions, corners);
                Decoded d;
                d.primitive = p.path();
                d.position = JsonObject(o["attributes"])["POSITION"].integer(0);
                if (const JsonValue f = o["indices"]) d.indices = f.integer(0);
                d.positionsAt = bytes.size();
                d.vertices = positions.size();
                for (const glm::dvec3& v : positions)
                    for (int k = 0; k < 3; ++k) {
                        const auto f = float(v[k]);
                        bytes.append(reinterpret_cast<const char*>(&f), 4);
                    }
                d.indicesAt = bytes.size();
                d.corners = corners.size();
                bytes.append(reinterpret_cast<const char*>(corners.data()), corners.size() * 4);
                if (bytes.size() > kMaxMeshFileBytes)
                    draco.error("the decoded meshes pass the 1024 MiB limit for a mesh's buffers");
                decoded.push_back(std::move(d));
            }
    if (decoded.empty()) return std::nullopt;
    // The edits, once every JsonValue into the document is done with.
    nlohmann::json& j = doc.json;
    const size_t buffer = j.contains("buffers") ? j["buffers"].size() : 0;
    j["buffers"][buffer] = {{"byteLength", bytes.size()},
                            {"uri", "data:application/octet-stream;base64," + base64(bytes)}};
    const auto view = [&](size_t offset, size_t length) {
        j["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", offset}, {"byteLength", length}});
        return j["bufferViews"].size() - 1;
    };
    for (const Decoded& d : decoded) {
        nlohmann::json& p = j[nlohmann::json::json_pointer(d.primitive)];
        nlohmann::json& position = j["accessors"][d.position];
        position.erase("byteOffset");
        position["bufferView"] = view(d.positionsAt, d.vertices * 12);
        nlohmann::json corners = {{"bufferView", view(d.indicesAt, d.corners * 4)},
                                  {"componentType", 5125},
                                  {"count", d.corners},
                                  {"type", "SCALAR"}};
        if (d.indices) {
            j["accessors"][*d.indices] = corners;
        } else {
            j["accessors"].push_back(corners);
            p["indices"] = j["accessors"].size() - 1;
        }
        // Attributes other than POSITION in the Draco data (normals, texture coordinates) are
        // not decoded, and so dropped: a mesh file is read for its shape alone.
        for (const auto& [name, id] : p["extensions"]["KHR_draco_mesh_compression"]["attributes"].items()) {
            if (name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0)
                throw InputError(path + ": " + d.primitive + ": a skinned Draco-compressed mesh is not read (its " +
                                 name + " would need decoding too)");
            if (name != "POSITION") p["attributes"].erase(name);
        }
        p["extensions"].erase("KHR_draco_mesh_compression");
    }
    for (const char* list : {"extensionsUsed", "extensionsRequired"})
        if (j.contains(list) && j[list].is_array()) {
            auto& names = j[list];
            names.erase(std::remove(names.begin(), names.end(), "KHR_draco_mesh_compression"), names.end());
        }
    if (!isGlb(data)) return j.dump();
    return joinGlb(j.dump(), splitGlb(data, path).second);
}

}  // namespace tetglow
