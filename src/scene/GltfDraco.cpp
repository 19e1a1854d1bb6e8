#include "scene/GltfDraco.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include <draco/compression/decode.h>
#include <draco/compression/point_cloud/point_cloud_decoder.h>
#include <draco/core/varint_decoding.h>
#include <draco/metadata/metadata_decoder.h>

#include "base/InputFile.h"

namespace tetglow {
namespace {

constexpr uint64_t kMaxDracoElementsPerByte = 256;

// The sizes a Draco mesh states ahead of its data: the triangles, and the vertices where the
// sequential coding states them (Edgebreaker's follow from its connectivity, at most three a
// triangle). libdraco reserves memory for them before it reads the data they describe.
struct DracoCounts {
    uint32_t faces = 0;
    std::optional<uint32_t> points;
};

// The counts of the Draco data `bytes`, or the reason they cannot be read. The layout is the
// Draco bitstream's (versions 1.0 to 2.2): header, optional metadata, then the connectivity.
std::string readDracoCounts(std::string_view bytes, DracoCounts& counts) {
    draco::DecoderBuffer buffer;
    buffer.Init(bytes.data(), bytes.size());
    draco::DracoHeader header;
    if (!draco::PointCloudDecoder::DecodeHeader(&buffer, &header).ok()) return "it does not start with a Draco header";
    if (header.encoder_type != draco::TRIANGULAR_MESH) return "it holds a point cloud, not a triangle mesh";
    const uint16_t version = DRACO_BITSTREAM_VERSION(header.version_major, header.version_minor);
    if (header.version_major < 1 || version > draco::kDracoMeshBitstreamVersion)
        return "bitstream version " + std::to_string(header.version_major) + "." +
               std::to_string(header.version_minor) + " (libdraco reads 1.0 to 2.2)";
    buffer.set_bitstream_version(version);
    const std::string cut = "it is cut off in its header";
    if (version >= DRACO_BITSTREAM_VERSION(1, 3) && (header.flags & METADATA_FLAG_MASK)) {
        draco::GeometryMetadata metadata;
        if (!draco::MetadataDecoder().DecodeGeometryMetadata(&buffer, &metadata)) return "its metadata cannot be read";
    }
    // Counts are varints from 2.0 on (2.2 for the sequential coding), 32-bit words before.
    const auto count = [&](uint16_t varintSince, uint32_t& v) {
        return version >= varintSince ? draco::DecodeVarint(&v, &buffer) : buffer.Decode(&v);
    };
    uint32_t skipped = 0, points = 0;
    if (header.encoder_method == draco::MESH_SEQUENTIAL_ENCODING) {
        if (!count(DRACO_BITSTREAM_VERSION(2, 2), counts.faces) || !count(DRACO_BITSTREAM_VERSION(2, 2), points))
            return cut;
        counts.points = points;
    } else if (header.encoder_method == draco::MESH_EDGEBREAKER_ENCODING) {
        uint8_t traversal = 0;
        const uint16_t v2 = DRACO_BITSTREAM_VERSION(2, 0);
        if (!buffer.Decode(&traversal)) return cut;
        if (version < DRACO_BITSTREAM_VERSION(2, 2) && !count(v2, skipped)) return cut;  // new vertices
        if (!count(v2, skipped) || !count(v2, counts.faces)) return cut;                 // encoded vertices, faces
    } else {
        return "unknown connectivity coding " + std::to_string(header.encoder_method);
    }
    return "";
}

std::string vec3Text(const double* v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", v[0], v[1], v[2]);
    return text;
}

// Every vertex inside the accessor's min and max, where it gives them, within 1% of the box's
// largest side: Draco's quantization may move a vertex by half a step of its grid.
void checkBounds(const GltfAccessor& accessor, const std::vector<glm::dvec3>& positions, const JsonValue& draco) {
    JsonObject o(accessor.value);
    const JsonValue minValue = o["min"], maxValue = o["max"];
    if (!minValue || !maxValue) return;
    const std::vector<double> lo = minValue.numbers(3), hi = maxValue.numbers(3);
    double side = 0;
    for (int k = 0; k < 3; ++k) side = std::max(side, hi[k] - lo[k]);
    const double slack = 0.01 * side;
    for (size_t i = 0; i < positions.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (!(positions[i][k] >= lo[k] - slack && positions[i][k] <= hi[k] + slack)) {
                const double p[3] = {positions[i].x, positions[i].y, positions[i].z};
                draco.error("decoded vertex " + std::to_string(i) + " " + vec3Text(p) + " lies outside the min " +
                            vec3Text(lo.data()) + " and max " + vec3Text(hi.data()) + " of POSITION (" +
                            accessor.value.path() + ")");
            }
}

// The POSITION attribute `id` of the decoded mesh as doubles, one per point.
std::vector<glm::dvec3> decodedPositions(const draco::Mesh& mesh, const JsonValue& id, const JsonValue& draco) {
    const draco::PointAttribute* a = mesh.GetAttributeByUniqueId(uint32_t(id.integer(0, INT32_MAX)));
    if (!a) id.error("the Draco data has no attribute with this id");
    if (a->num_components() != 3)
        id.error("the Draco attribute has " + std::to_string(a->num_components()) + " components, POSITION 3");
    std::vector<glm::dvec3> positions(mesh.num_points());
    for (uint32_t i = 0; i < mesh.num_points(); ++i) {
        const draco::AttributeValueIndex value = a->mapped_index(draco::PointIndex(i));
        float xyz[3];
        if (value.value() >= a->size() || !a->ConvertValue<float, 3>(value, xyz))
            draco.error("decoded vertex " + std::to_string(i) + " has no position");
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(xyz[k])) draco.error("decoded vertex " + std::to_string(i) + " is not finite");
        positions[i] = {xyz[0], xyz[1], xyz[2]};
    }
    return positions;
}

}  // namespace

void decodeDracoPrimitive(const GltfDocument& doc, const JsonValue& primitive, const JsonValue& draco,
                          std::vector<glm::dvec3>& positions, std::vector<uint32_t>& indices) {
    JsonObject p(primitive), d(draco);
    const GltfBufferView view = gltfBufferView(doc, d["bufferView"]);
    const JsonValue id = JsonObject(d["attributes"])["POSITION"];
    const GltfAccessor position = gltfAccessor(doc, JsonObject(p["attributes"])["POSITION"], "VEC3", {5126});
    std::optional<GltfAccessor> corners;
    if (const JsonValue f = p["indices"]) corners = gltfAccessor(doc, f, "SCALAR", {5121, 5123, 5125});
    const auto mismatch = [&](const std::string& what, uint64_t decoded, const GltfAccessor& a) {
        draco.error("the Draco data holds " + std::to_string(decoded) + " " + what + ", its accessor (" +
                    a.value.path() + ") counts " + std::to_string(a.count));
    };

    // Before decoding: what the data states against the accessors and the limit of a mesh's
    // buffers (the decoded mesh as uncompressed accessors would hold it).
    DracoCounts counts;
    if (const std::string why = readDracoCounts(view.bytes, counts); !why.empty())
        draco.error("the Draco data cannot be decoded: " + why);
    if (corners && uint64_t(counts.faces) * 3 != corners->count)
        mismatch("triangle corners", uint64_t(counts.faces) * 3, *corners);
    if (counts.points && *counts.points != position.count) mismatch("vertices", *counts.points, position);
    if (12 * (uint64_t(counts.faces) + position.count) > kMaxMeshFileBytes)
        draco.error("the Draco data holds " + std::to_string(counts.faces) + " triangles and " +
                    std::to_string(position.count) + " vertices, more than the 1024 MiB limit for a mesh's buffers");
    // libdraco sizes its tables by the stated counts before it reads the data they describe.
    // Even a regular grid takes a third of a byte a triangle (a quarter of a byte a vertex), so a
    // count far past the data is a corrupt header, not a mesh.
    const uint64_t most = kMaxDracoElementsPerByte * view.bytes.size();
    if (counts.faces > most || position.count > most)
        draco.error("the Draco data states " + std::to_string(counts.faces) + " triangles and " +
                    std::to_string(position.count) + " vertices in " + std::to_string(view.bytes.size()) +
                    " bytes, more than " + std::to_string(kMaxDracoElementsPerByte) +
                    " a byte: it is cut off or corrupt");

    draco::DecoderBuffer buffer;
    buffer.Init(view.bytes.data(), view.bytes.size());
    draco::StatusOr<std::unique_ptr<draco::Mesh>> decoded = draco::Decoder().DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        draco.error("the Draco data cannot be decoded (libdraco: " + decoded.status().error_msg_string() + ")");
    const draco::Mesh& mesh = *decoded.value();
    if (corners && uint64_t(mesh.num_faces()) * 3 != corners->count)
        mismatch("triangle corners", uint64_t(mesh.num_faces()) * 3, *corners);
    if (mesh.num_points() != position.count) mismatch("vertices", mesh.num_points(), position);
    positions = decodedPositions(mesh, id, draco);
    checkBounds(position, positions, draco);
    indices.clear();
    indices.reserve(size_t(mesh.num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (const draco::PointIndex& corner : mesh.face(f)) {
            if (corner.value() >= mesh.num_points())
                draco.error("decoded triangle " + std::to_string(f.value()) + " names vertex " +
                            std::to_string(corner.value()) + " of " + std::to_string(mesh.num_points()));
            indices.push_back(corner.value());
        }
}

}  // namespace tetglow
