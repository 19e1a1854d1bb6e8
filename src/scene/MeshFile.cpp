#include "scene/MeshFile.h"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "base/InputFile.h"
#include "scene/AssimpReader.h"
#include "scene/GltfVersion.h"
#include "scene/ObjReader.h"
#include "scene/OffReader.h"
#include "scene/PlyReader.h"
#include "scene/StlReader.h"
#include "scene/TextEncoding.h"

namespace tetglow {
namespace {

enum class Format { Obj, Off, Ply, Stl, Gltf, Glb, Fbx, Collada };

const char* name(Format f) {
    switch (f) {
        case Format::Obj: return "an OBJ";
        case Format::Off: return "an OFF";
        case Format::Ply: return "a PLY";
        case Format::Stl: return "an STL";
        default: return "a scene";
    }
}

bool startsWith(const std::string& data, size_t at, const char* prefix) {
    return data.compare(at, std::strlen(prefix), prefix) == 0;
}

// The format by the file's first bytes; by the extension where they do not say.
Format formatOf(const std::string& data, const std::string& path) {
    if (startsWith(data, 0, "ply\n") || startsWith(data, 0, "ply\r\n")) return Format::Ply;
    if (startsWith(data, 0, "glTF")) return Format::Glb;
    if (startsWith(data, 0, "Kaydara FBX Binary")) return Format::Fbx;
    // A binary STL's 80-byte header is free text, "solid" included: its size tells it.
    if (isBinaryStl(data)) return Format::Stl;
    const std::string head = data.substr(0, 4096);
    const size_t text = std::min(head.find_first_not_of(" \t\r\n"), head.size());
    if (startsWith(head, text, "OFF")) return Format::Off;
    if (startsWith(head, text, "solid")) return Format::Stl;
    if (startsWith(head, text, "{") && head.find("\"asset\"") != std::string::npos) return Format::Gltf;
    if (startsWith(head, text, "<") && head.find("<COLLADA") != std::string::npos) return Format::Collada;
    if (startsWith(head, text, "; FBX")) return Format::Fbx;
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    const std::pair<const char*, Format> byExtension[] = {{".off", Format::Off},   {".stl", Format::Stl},
                                                          {".gltf", Format::Gltf}, {".glb", Format::Glb},
                                                          {".fbx", Format::Fbx},   {".dae", Format::Collada}};
    for (const auto& [e, f] : byExtension)
        if (ext == e) return f;
    // Control characters other than whitespace do not occur in OBJ text.
    if (std::any_of(head.begin(), head.end(),
                    [](char c) { return (unsigned char)c < 32 && !std::isspace((unsigned char)c); }))
        throw InputError(path +
                         ": binary file, not a mesh tetglow reads (OBJ, OFF, PLY, STL, glTF, GLB, FBX, Collada)");
    return Format::Obj;
}

}  // namespace

MeshFile readMeshFile(const std::string& path, const std::string& node, std::vector<std::string>* warnings) {
    std::string data = readInputFile(path, kMaxMeshFileBytes, "a mesh");
    if (!isBinaryStl(data)) data = utf8Text(std::move(data), path);  // a binary STL's header is free
    const Format format = formatOf(data, path);
    if (format == Format::Gltf || format == Format::Glb) refuseGltf1(data, path, format == Format::Glb);
    if (format < Format::Gltf && !node.empty())
        throw InputError(path + ": " + name(format) + " file has no nodes to choose '" + shorten(node) +
                         "' from (only glTF, GLB, FBX and Collada files have)");
    MeshFile out;
    switch (format) {
        case Format::Obj: out.mesh = parseObj(data, path, warnings); break;
        case Format::Off: out.mesh = parseOff(data, path); break;
        case Format::Ply: out = parsePly(data, path, warnings); break;
        case Format::Stl: out.mesh = parseStl(data, path); break;
        case Format::Gltf:
        case Format::Glb:
            out.mesh =
                parseSceneMeshes(std::move(data), path,
                                 format == Format::Gltf ? SceneMeshFormat::Gltf : SceneMeshFormat::Glb, node, warnings);
            out.up = {0, 1, 0};
            out.upFrom = "glTF is Y-up";
            break;
        case Format::Fbx:
            out.mesh = parseSceneMeshes(std::move(data), path, SceneMeshFormat::Fbx, node, warnings, &out.up);
            if (out.up != glm::dvec3(0)) out.upFrom = "the FBX file's UpAxis";
            break;
        case Format::Collada:
            out.mesh = parseSceneMeshes(std::move(data), path, SceneMeshFormat::Collada, node, warnings);
            // The importer turns a Z-up file to Y-up (its root node's transform), as it does every Collada file.
            out.up = {0, 1, 0};
            out.upFrom = "the Collada file's up_axis, which the importer turns to +Y";
            break;
    }
    if (out.mesh.triangles.empty()) throw InputError(path + ": no triangles (empty file or not a mesh)");
    return out;
}

}  // namespace tetglow
