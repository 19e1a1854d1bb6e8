// The scene-level objects (camera, lights, materials and their extensions, extras) are read from
// the glTF JSON itself: Assimp maps KHR_lights_punctual to its own attenuation model without the
// photometric units, and drops KHR_materials_volume and the extras. The geometry is read from the
// accessors too (scene/GltfDocument.h says why).
#include "scene/GltfScene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "base/Error.h"
#include "scene/AssimpReader.h"
#include "scene/GltfDocument.h"
#include "scene/MeshWeld.h"
#include "scene/SceneLoader.h"
#include "scene/SceneShapes.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

// KHR_lights_punctual gives point and spot lights in candela (lm/sr) and directional ones in lux
// (lm/m^2); tetglow's are radiometric (W/sr, W/m^2). glTF's exporters, Blender's among them, use
// 683 lm/W, the luminous efficacy at 555 nm that defines the candela, for every colour.
constexpr double kLumensPerWatt = 683;
constexpr int kDefaultShortSide = 400;  // pixels along the shorter image axis when nothing says more
constexpr double kPi = 3.14159265358979323846;
constexpr Range kUnit{.lo = 0, .hi = 1};

std::vector<JsonValue> arrayOf(JsonObject& o, const std::string& key) {
    const JsonValue v = o[key];
    return v ? v.array() : std::vector<JsonValue>{};
}

JsonValue absent() { return {nullptr, nlohmann::json::json_pointer(), ""}; }

std::string warning(const JsonValue& v, const std::string& message) { return v.where() + ": warning: " + message; }

// The JSON of a value, for what glTF leaves open: "extras" of any type, names of any string.
const nlohmann::json& rawOf(const GltfDocument& doc, const JsonValue& v) {
    return doc.json.at(nlohmann::json::json_pointer(v.path()));
}

// extras.tetglow of an object whose extras are an object holding one, else a false value.
JsonValue tetglowExtras(const GltfDocument& doc, JsonObject& o) {
    const JsonValue extras = o["extras"];
    if (!extras || !rawOf(doc, extras).is_object()) return absent();
    return JsonObject(extras)["tetglow"];
}

// A node's "name", "" where it has none (or not a string).
std::string nameOf(const GltfDocument& doc, JsonObject& o) {
    const JsonValue name = o["name"];
    return name && rawOf(doc, name).is_string() ? rawOf(doc, name).get<std::string>() : "";
}

// The extensions tetglow reads or may ignore without changing the image's meaning.
void checkRequiredExtensions(JsonObject& root) {
    static const char* const known[] = {
        "KHR_lights_punctual",    "KHR_materials_transmission",      "KHR_materials_ior",
        "KHR_materials_volume",   "KHR_materials_emissive_strength", "KHR_texture_transform",
        "KHR_materials_specular", "KHR_draco_mesh_compression"};
    for (const JsonValue& v : arrayOf(root, "extensionsRequired")) {
        const std::string name = v.string();
        if (std::find(std::begin(known), std::end(known), name) == std::end(known))
            v.error("the extension " + shorten(name) +
                    " is required but not read (read: KHR_lights_punctual, KHR_materials_transmission, _ior, "
                    "_volume, _emissive_strength, KHR_draco_mesh_compression)");
    }
}

// What a mesh with this material becomes.
struct MaterialRole {
    enum class Kind { Surface, Light, Medium } kind = Kind::Surface;
    MaterialDesc surface{MaterialType::Interface};  // Surface: diffuse or interface
    RGB radiance{0};                                // Light
    bool twoSided = false;                          // Light
    MediumDesc medium;                              // Medium: coefficients and boundary
};

// A material with no extensions or extras of tetglow's: diffuse from its base colour, or
// index-matched where it is see-through without a transmission extension (alpha blending).
// pbrMetallicRoughness's baseColorFactor: RGB and alpha.
std::pair<RGB, double> baseColourOf(JsonObject& o) {
    const JsonValue pbr = o["pbrMetallicRoughness"];
    const JsonValue f = pbr ? JsonObject(pbr)["baseColorFactor"] : absent();
    if (!f) return {RGB(1), 1};
    const std::vector<double> c = f.numbers(4, kUnit);
    return {RGB(c[0], c[1], c[2]), c[3]};
}

MaterialDesc readSurfaceMaterial(JsonObject& o, std::vector<std::string>& warnings) {
    const auto [base, alpha] = baseColourOf(o);
    double metallic = 1;
    if (auto pbr = o["pbrMetallicRoughness"]) {
        JsonObject p(pbr);
        if (auto f = p["metallicFactor"]) metallic = f.number(kUnit);
        if (auto f = p["baseColorTexture"])
            addWarning(warnings, warning(f, "textures are not read; the baseColorFactor is used"));
    }
    const JsonValue mode = o["alphaMode"];
    const std::string alphaMode = mode ? mode.string() : "OPAQUE";
    const double cutoff = o["alphaCutoff"] ? o["alphaCutoff"].number(kNonNegative) : 0.5;
    if ((alphaMode == "BLEND" && alpha < 1) || (alphaMode == "MASK" && alpha < cutoff))
        return MaterialDesc{MaterialType::Interface};
    if (metallic > 0) addWarning(warnings, warning(o.self(), "metallic is rendered as diffuse (tetglow has no metal)"));
    MaterialDesc m{MaterialType::Diffuse};
    m.reflectance = base;
    return m;
}

MaterialRole readMaterial(const GltfDocument& doc, const JsonValue& v, std::vector<std::string>& warnings) {
    JsonObject o(v);
    MaterialRole r;
    RGB emissive(0);
    if (auto f = o["emissiveFactor"]) emissive = f.vec3(kUnit);
    if (auto e = gltfExtension(o, "KHR_materials_emissive_strength"))
        if (auto f = JsonObject(e)["emissiveStrength"]) emissive *= f.number(kColour);
    if (auto f = o["emissiveTexture"])
        addWarning(warnings, warning(f, "textures are not read; the emissiveFactor is used"));
    double transmission = 0;
    if (auto e = gltfExtension(o, "KHR_materials_transmission")) {
        JsonObject t(e);
        if (auto f = t["transmissionFactor"]) transmission = f.number(kUnit);
        if (auto f = t["transmissionTexture"]) addWarning(warnings, warning(f, "textures are not read"));
    }
    const JsonValue volume = gltfExtension(o, "KHR_materials_volume");
    const JsonValue tetglow = tetglowExtras(doc, o);
    if (emissive != RGB(0)) {
        // An emitting surface is an area light; tetglow's lights absorb what reaches them.
        if (transmission > 0 || volume || tetglow)
            addWarning(warnings, warning(v,
                                         "emissive: rendered as an area light; its transmission, volume and "
                                         "extras are not used"));
        r.kind = MaterialRole::Kind::Light;
        r.radiance = emissive;
        r.twoSided = o["doubleSided"] && o["doubleSided"].boolean();
        return r;
    }
    if (transmission == 0 && !volume && !tetglow) {
        r.surface = readSurfaceMaterial(o, warnings);
        return r;
    }
    r.kind = MaterialRole::Kind::Medium;
    MediumDesc& m = r.medium;
    m.sigmaS = RGB(0);
    if (transmission > 0) {
        m.boundaryMaterial = MaterialDesc{MaterialType::Dielectric};
        if (auto e = gltfExtension(o, "KHR_materials_ior"))
            if (auto f = JsonObject(e)["ior"]) m.boundaryMaterial.ior = f.number(kPositive);
        if (transmission < 1)
            addWarning(warnings, warning(o.self(), "a transmissionFactor below 1 is rendered as 1 (all light enters)"));
        if (baseColourOf(o).first != RGB(1))
            addWarning(warnings, warning(o.self(),
                                         "the baseColorFactor's tint of transmitted light is not rendered "
                                         "(tetglow's glass is clear)"));
    }
    if (volume) {
        // Beer-Lambert: light that travels attenuationDistance keeps attenuationColor of itself.
        // thicknessFactor is ignored: it stands in for a thickness a renderer without the real mesh lacks.
        JsonObject vo(volume);
        RGB colour(1);
        if (auto f = vo["attenuationColor"]) colour = f.vec3({.lo = 0, .hi = 1, .loOpen = true});
        if (auto f = vo["attenuationDistance"]) {
            m.sigmaA = -glm::log(colour) / f.number(kPositive);
            for (int k = 0; k < 3; ++k)
                if (!kColour.contains(m.sigmaA[k]))
                    f.error("sigma_a = -ln(attenuationColor) / attenuationDistance is past 3.40282e38");
        }
    }
    if (tetglow)
        tetglow.readObject([&](JsonObject& t) {
            readMediumCoefficients(t, m);
            return 0;
        });
    return r;
}

// A name for messages ("/nodes/3 (Body)") and, where it is a clean one, for the preview.
std::pair<std::string, std::string> nodeNames(const std::string& name, const JsonValue& node) {
    return {name.empty() ? node.path() : node.path() + " (" + shorten(name, 64) + ")",
            validLabel(name) ? name : node.path()};
}

CameraDesc readCamera(const JsonValue& v, const glm::dmat4& world, const std::vector<int>& resolution) {
    JsonObject o(v);
    const JsonValue type = o["type"];
    if (type.string() != "perspective") type.error("only perspective cameras are read");
    JsonObject p(o["perspective"]);
    const double yfov = p["yfov"].number({.lo = 0, .hi = kPi, .loOpen = true, .hiOpen = true});
    double aspect = 1;
    if (auto f = p["aspectRatio"]) aspect = f.number({.lo = 1.0 / kMaxResolution, .hi = kMaxResolution});
    CameraDesc c;
    c.width = c.height = kDefaultShortSide;
    (aspect >= 1 ? c.width : c.height) =
        std::clamp(int(std::lround(kDefaultShortSide * std::max(aspect, 1 / aspect))), 1, kMaxResolution);
    if (!resolution.empty()) {
        c.width = resolution[0];
        c.height = resolution[1];
    }
    // yfov spans the image's height; tetglow's fov spans its shorter axis.
    const double narrow = std::min(1.0, double(c.width) / c.height);
    c.fov = glm::degrees(2 * std::atan(std::tan(yfov / 2) * narrow));
    // The camera looks down its -Z with +Y up; its image x axis is its +X, which a mirroring
    // transform turns into cross(up, view): the left-handed camera.
    c.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    c.lookAt = c.position + glm::normalize(glm::dvec3(world * glm::dvec4(0, 0, -1, 0)));
    c.up = glm::dvec3(world * glm::dvec4(0, 1, 0, 0));
    if (glm::determinant(glm::dmat3(world)) < 0) c.handedness = Handedness::Left;
    return c;
}

LightDesc readLight(const JsonValue& v, const glm::dmat4& world, std::vector<std::string>& warnings) {
    JsonObject o(v);
    LightDesc l;
    l.type = o["type"].choice<LightType>(
        {{"point", LightType::Point}, {"spot", LightType::Spot}, {"directional", LightType::Distant}});
    RGB colour(1);
    if (auto f = o["color"]) colour = f.vec3(kUnit);
    const double intensity = o["intensity"] ? o["intensity"].number(kColour) : 1;
    emissionOf(l) = colour * (intensity / kLumensPerWatt);
    if (auto f = o["range"])
        addWarning(warnings, warning(f, "the range is ignored (light falls off with 1/d^2 to infinity)"));
    const glm::dvec3 axis = glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
    if (!(glm::length(axis) > 0)) v.error("the light's node transform is singular");
    // Only the fields of the light's type are set, so that the scene writes and reads back the same.
    if (l.type == LightType::Distant) l.direction = glm::normalize(axis);
    if (l.type != LightType::Distant) l.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    if (l.type == LightType::Spot) {
        l.lookAt = l.position + glm::normalize(axis);
        JsonObject s(o["spot"]);
        double inner = 0, outer = kPi / 4;
        if (auto f = s["outerConeAngle"]) outer = f.number({.lo = 0, .hi = kPi / 2, .loOpen = true});
        // The spec asks inner < outer; Blender writes them equal for a spot without blend.
        if (auto f = s["innerConeAngle"]) inner = f.number({.lo = 0, .hi = outer});
        l.coneAngle = glm::degrees(outer);
        l.coneDelta = glm::degrees(outer - inner);
    }
    return l;
}

struct SceneExtras {
    std::vector<int> resolution;  // empty: from the camera's aspectRatio
    IntegratorDesc integrator;
    RGB environment{0};
};

SceneExtras readSceneExtras(const GltfDocument& doc, const JsonValue& scene) {
    SceneExtras x;
    JsonObject so(scene);
    const JsonValue tetglow = tetglowExtras(doc, so);
    if (!tetglow) return x;
    tetglow.readObject([&](JsonObject& o) {
        if (auto f = o["resolution"]) {
            const auto size = f.array();
            if (size.size() != 2) f.fail("[width, height]");
            for (const JsonValue& n : size) x.resolution.push_back(int(n.integer(1, kMaxResolution)));
        }
        if (auto f = o["integrator"]) x.integrator = f.readObject(readIntegrator);
        if (auto f = o["environment"]) x.environment = f.vec3OrScalar(kColour);
        return 0;
    });
    return x;
}

// Each mesh primitive of a node, grouped by material, placed in world space and welded.
std::map<int, TriangleMesh> placedMeshes(const GltfDocument& doc, const JsonValue& mesh, const glm::dmat4& world,
                                         const JsonValue& node, std::vector<std::string>& warnings, size_t& triangles) {
    std::map<int, TriangleMesh> byMaterial;
    JsonObject m(mesh);
    for (const JsonValue& p : m["primitives"].array()) {
        JsonObject po(p);
        const int material = po["material"] ? int(po["material"].integer(0, 1 << 30)) : -1;
        TriangleMesh part = primitiveTriangles(doc, p, &warnings);
        triangles += part.triangles.size();
        if (triangles > kMaxSceneMeshTriangles)
            node.error("more than " + std::to_string(kMaxSceneMeshTriangles) + " triangles once every node is placed");
        TriangleMesh& whole = byMaterial[material];
        const auto offset = uint32_t(whole.positions.size());
        whole.positions.insert(whole.positions.end(), part.positions.begin(), part.positions.end());
        for (auto t : part.triangles) whole.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    const double det = glm::determinant(glm::dmat3(world));
    for (auto& [material, whole] : byMaterial) {
        if (placePositions(whole.positions, world) != SIZE_MAX)
            node.error("a vertex lies outside [-1e12, 1e12] once placed by the node's transform");
        // glTF's rule: a mirroring world transform turns the triangles' front to the other side.
        if (det < 0)
            for (auto& t : whole.triangles) std::swap(t[1], t[2]);
        weldEqualPositions(whole);
    }
    return byMaterial;
}

// The scene the extras start: its integrator and the environment's light.
SceneDesc sceneOfExtras(const std::string& path, const SceneExtras& extras) {
    SceneDesc s;
    s.path = path;
    s.integrator = extras.integrator;
    if (extras.environment != RGB(0)) {
        LightDesc env;
        env.type = LightType::Environment;
        env.radiance = extras.environment;
        s.lights.push_back(env);
    }
    return s;
}

// A node's mesh placed in the world, as the role of its material makes it: a surface, a light
// or a medium's boundary.
void addPlacedMesh(SceneDesc& s, const MaterialRole& r, const std::string& name, const std::string& label,
                   TriangleMesh placed) {
    switch (r.kind) {
        case MaterialRole::Kind::Surface: s.surfaces.push_back({name, std::move(placed), r.surface}); break;
        case MaterialRole::Kind::Light: {
            LightDesc l;
            l.type = LightType::Mesh;
            l.radiance = r.radiance;
            l.twoSided = r.twoSided;
            l.mesh = std::move(placed);
            s.lights.push_back(std::move(l));
            break;
        }
        case MaterialRole::Kind::Medium: {
            MediumDesc m = r.medium;
            m.name = name;
            m.label = label;
            m.boundary = std::move(placed);
            s.media.push_back(std::move(m));
            break;
        }
    }
}

// No camera node, or none named `cameraName`: the error names the camera nodes there are.
[[noreturn]] void noCamera(const JsonValue& sceneValue, const std::string& cameraName,
                           const std::vector<std::string>& cameraNodes) {
    if (cameraName.empty()) sceneValue.error("the scene has no camera node");
    sceneValue.error("no camera node named '" + shorten(cameraName, 40) + "' (camera nodes: " +
                     (cameraNodes.empty() ? std::string("none") : [&] {
                         std::string list;
                         for (const auto& c : cameraNodes) list += (list.empty() ? "" : ", ") + c;
                         return list;
                     }()) +
                     ")");
}

}  // namespace

bool looksLikeGltf(const std::string& path, const std::string& data) {
    const std::string ext = fs::path(path).extension().string();
    return ext == ".gltf" || ext == ".glb" || isGlb(data);
}

SceneDesc loadGltfScene(const std::string& path, std::string data, const std::string& cameraName) {
    const GltfDocument doc = readGltfDocument(path, std::move(data));
    JsonObject root(doc.root());
    checkRequiredExtensions(root);
    std::vector<std::string> warnings;
    const std::vector<JsonValue> nodes = arrayOf(root, "nodes"), meshes = arrayOf(root, "meshes"),
                                 cameras = arrayOf(root, "cameras"), materialValues = arrayOf(root, "materials");
    std::vector<JsonValue> lights;
    if (auto e = gltfExtension(root, "KHR_lights_punctual")) {
        JsonObject lo(e);
        lights = arrayOf(lo, "lights");
    }
    std::vector<MaterialRole> materials;
    for (const JsonValue& m : materialValues) materials.push_back(readMaterial(doc, m, warnings));
    const auto index = [](const JsonValue& v, size_t size, const char* what) {
        if (size == 0) v.error(std::string("the file has no ") + what);
        return size_t(v.integer(0, int64_t(size) - 1));
    };

    const JsonValue sceneValue = sceneOf(doc);
    const SceneExtras extras = readSceneExtras(doc, sceneValue);
    SceneDesc s = sceneOfExtras(path, extras);
    bool haveCamera = false;
    std::vector<std::string> cameraNodes;
    size_t triangles = 0;
    for (const GltfNode& n : sceneNodes(doc)) {
        const JsonValue node = nodes[size_t(n.index)];
        JsonObject o(node);
        const std::string nodeName = nameOf(doc, o);
        const auto [name, label] = nodeNames(nodeName, node);
        if (auto f = o["camera"]) {
            cameraNodes.push_back('\'' + shorten(nodeName, 40) + '\'');
            if (!haveCamera && (cameraName.empty() || nodeName == cameraName)) {
                if (glm::determinant(glm::dmat3(n.world)) == 0)
                    node.error("the camera's transform is singular (scale 0)");
                s.camera = readCamera(cameras[index(f, cameras.size(), "cameras")], n.world, extras.resolution);
                haveCamera = true;
            }
        }
        if (auto e = gltfExtension(o, "KHR_lights_punctual")) {
            const JsonValue light = JsonObject(e)["light"];
            s.lights.push_back(
                readLight(lights[index(light, lights.size(), "KHR_lights_punctual lights")], n.world, warnings));
        }
        if (o["skin"] || o["weights"]) addWarning(warnings, warning(node, "skins and morph targets are not applied"));
        const JsonValue meshIndex = o["mesh"];
        if (!meshIndex) continue;
        const JsonValue mesh = meshes[index(meshIndex, meshes.size(), "meshes")];
        if (glm::determinant(glm::dmat3(n.world)) == 0) {
            addWarning(warnings, warning(node, "skipped: its transform is singular (scale 0)"));
            continue;
        }
        for (auto& [material, placed] : placedMeshes(doc, mesh, n.world, node, warnings, triangles)) {
            if (placed.triangles.empty()) continue;
            const MaterialRole none;
            if (material >= int(materials.size()))
                node.error("a primitive names material " + std::to_string(material) + "; the file has " +
                           std::to_string(materials.size()));
            addPlacedMesh(s, material < 0 ? none : materials[size_t(material)], name, label, std::move(placed));
        }
    }
    if (!haveCamera) noCamera(sceneValue, cameraName, cameraNodes);
    for (const auto& w : warnings) std::cerr << w << '\n';
    if (!emitsLight(s))
        sceneValue.error("nothing emits light: no KHR_lights_punctual light, emissive material or glowing medium");
    return s;
}

}  // namespace tetglow
