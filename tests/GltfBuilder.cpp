#include "GltfBuilder.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "scene/GltfDocument.h"

namespace tetglow::test {
namespace {

void writeBytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

void appendU32(std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

GltfBuilder::GltfBuilder() {
    json = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}}};
}

int GltfBuilder::push(const char* key, nlohmann::json value) {
    if (!json.contains(key)) json[key] = nlohmann::json::array();
    json[key].push_back(std::move(value));
    return int(json[key].size()) - 1;
}

int GltfBuilder::addView(const std::string& bytes) {
    while (bin.size() % 4) bin.push_back('\0');
    const size_t offset = bin.size();
    bin += bytes;
    json["buffers"] = {{{"byteLength", bin.size()}}};
    return push("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}});
}

int GltfBuilder::addMesh(const TriangleMesh& mesh, int material) {
    std::string positions, indices;
    for (const auto& p : mesh.positions)
        for (int k = 0; k < 3; ++k) {
            const auto f = float(p[k]);
            positions.append(reinterpret_cast<const char*>(&f), 4);
        }
    for (const auto& t : mesh.triangles)
        for (const uint32_t i : t) appendU32(indices, i);
    const int p = push("accessors", {{"bufferView", addView(positions)},
                                     {"componentType", 5126},
                                     {"count", mesh.positions.size()},
                                     {"type", "VEC3"}});
    const int i = push("accessors", {{"bufferView", addView(indices)},
                                     {"componentType", 5125},
                                     {"count", mesh.triangles.size() * 3},
                                     {"type", "SCALAR"}});
    nlohmann::json primitive = {{"attributes", {{"POSITION", p}}}, {"indices", i}};
    if (material >= 0) primitive["material"] = material;
    return push("meshes", {{"primitives", {primitive}}});
}

int GltfBuilder::addDracoMesh(const TriangleMesh& mesh, int material, int quantizationBits, bool sequential) {
    draco::Mesh d;
    d.set_num_points(uint32_t(mesh.positions.size()));
    draco::GeometryAttribute position;
    position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, 3 * sizeof(float), 0);
    const int attribute = d.AddAttribute(position, true, uint32_t(mesh.positions.size()));
    nlohmann::json lo = {1e30, 1e30, 1e30}, hi = {-1e30, -1e30, -1e30};
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        float xyz[3];
        for (int k = 0; k < 3; ++k) {
            xyz[k] = float(mesh.positions[i][k]);
            lo[k] = std::min(lo[k].get<double>(), double(xyz[k]));
            hi[k] = std::max(hi[k].get<double>(), double(xyz[k]));
        }
        d.attribute(attribute)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), xyz);
    }
    for (const auto& t : mesh.triangles)
        d.AddFace({draco::PointIndex(t[0]), draco::PointIndex(t[1]), draco::PointIndex(t[2])});
    draco::Encoder encoder;
    encoder.SetTrackEncodedProperties(true);  // for num_encoded_points and _faces
    if (quantizationBits > 0) encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, quantizationBits);
    encoder.SetEncodingMethod(sequential ? draco::MESH_SEQUENTIAL_ENCODING : draco::MESH_EDGEBREAKER_ENCODING);
    draco::EncoderBuffer out;
    if (const draco::Status s = encoder.EncodeMeshToBuffer(d, &out); !s.ok())
        throw std::runtime_error("Draco encoding failed: " + s.error_msg_string());
    // Edgebreaker may reorder and split vertices: the accessors count what the decoder gives.
    const int p = push(
        "accessors",
        {{"componentType", 5126}, {"count", encoder.num_encoded_points()}, {"type", "VEC3"}, {"min", lo}, {"max", hi}});
    // 16-bit indices where they reach every vertex, as Blender's exporter and gltf-pipeline write them.
    const int componentType = encoder.num_encoded_points() <= 65536 ? 5123 : 5125;
    const int i =
        push("accessors",
             {{"componentType", componentType}, {"count", encoder.num_encoded_faces() * 3}, {"type", "SCALAR"}});
    const int view = addView(std::string(out.data(), out.size()));
    nlohmann::json primitive = {
        {"attributes", {{"POSITION", p}}},
        {"indices", i},
        {"extensions",
         {{"KHR_draco_mesh_compression",
           {{"bufferView", view}, {"attributes", {{"POSITION", d.attribute(attribute)->unique_id()}}}}}}}};
    if (material >= 0) primitive["material"] = material;
    for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
        nlohmann::json& names = json[list];
        if (names.is_null()) names = nlohmann::json::array();
        if (std::find(names.begin(), names.end(), "KHR_draco_mesh_compression") == names.end())
            names.push_back("KHR_draco_mesh_compression");
    }
    return push("meshes", {{"primitives", {primitive}}});
}

int GltfBuilder::addNode(nlohmann::json node, bool root) {
    const int index = push("nodes", std::move(node));
    if (root) json["scenes"][0]["nodes"].push_back(index);
    return index;
}

int GltfBuilder::addMaterial(nlohmann::json material) { return push("materials", std::move(material)); }

int GltfBuilder::addCamera(double yfov, double aspectRatio) {
    return push("cameras", {{"type", "perspective"},
                            {"perspective", {{"yfov", yfov}, {"aspectRatio", aspectRatio}, {"znear", 0.01}}}});
}

int GltfBuilder::addLight(nlohmann::json light) {
    auto& lights = json["extensions"]["KHR_lights_punctual"]["lights"];
    if (lights.is_null()) lights = nlohmann::json::array();
    lights.push_back(std::move(light));
    return int(lights.size()) - 1;
}

std::string GltfBuilder::writeGltf(const std::string& path) const {
    nlohmann::json j = json;
    const std::string binName = std::filesystem::path(path).stem().string() + ".bin";
    if (j.contains("buffers") && !j["buffers"][0].contains("uri")) j["buffers"][0]["uri"] = binName;
    writeBytes(path, j.dump());
    writeBytes((std::filesystem::path(path).parent_path() / binName).string(), bin);
    return path;
}

nlohmann::json GltfBuilder::glbJson() const {
    nlohmann::json j = json;
    if (j.contains("buffers")) j["buffers"][0].erase("uri");
    return j;
}

std::string GltfBuilder::writeGlb(const std::string& path) const {
    const std::string out = joinGlb(glbJson().dump(), bin);
    writeBytes(path, out);
    return path;
}

}  // namespace tetglow::test
