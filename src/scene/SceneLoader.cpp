#include "scene/SceneLoader.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <glm/geometric.hpp>

#include "base/InputFile.h"
#include "scene/GltfScene.h"
#include "scene/JsonReader.h"
#include "scene/PbrtParser.h"
#include "scene/SceneShapes.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxParityRays = 15;
constexpr Range kUnitInterval{.lo = 0, .hi = 1};

RGB rgb(const JsonValue& v) { return v.vec3OrScalar(kColour); }

double scaleOf(JsonObject& o) {
    const JsonValue scale = o["scale"];
    return scale ? scale.number(kColour) : 1.0;
}

// A direction the renderer normalises: its length squared must not underflow.
constexpr double kMinDirection = 1e-12;
void checkDirection(const JsonValue& v, const glm::dvec3& d, const std::string& expected) {
    if (!(glm::length(d) >= kMinDirection)) v.fail(expected);
}

bool parallel(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(glm::cross(a, b)) <= 1e-9 * glm::length(a) * glm::length(b);
}

std::vector<JsonValue> optionalArray(const JsonValue& v) { return v ? v.array() : std::vector<JsonValue>{}; }

// "/media/0 (meshes/fish.obj)": the JSON path, and the mesh file where there is one.
std::string nameOf(const JsonValue& v, const Shape& shape) {
    return shape.file.empty() ? v.path() : v.path() + " (" + shape.file + ")";
}

CameraDesc readCamera(JsonObject& o) {
    CameraDesc c;
    readCameraView(o, c);
    if (auto f = o["resolution"]) {
        const auto size = f.array();
        if (size.size() != 2) f.fail("[width, height]");
        c.width = int(size[0].integer(1, kMaxResolution));
        c.height = int(size[1].integer(1, kMaxResolution));
    }
    if (auto f = o["handedness"])
        c.handedness = f.choice<Handedness>({{"right", Handedness::Right}, {"left", Handedness::Left}});
    return c;
}

TurntableDesc readTurntable(JsonObject& o, const CameraDesc& camera) {
    TurntableDesc t;
    t.frames = int(o["frames"].integer(1, kMaxFrames));
    t.center = camera.lookAt;
    if (auto f = o["center"]) t.center = f.vec3();
    if (auto f = o["axis"]) t.axis = f.vec3();
    if (t.axis == glm::dvec3(0)) o["axis"].fail("a non-zero vector");
    if (auto f = o["degrees"]) t.degrees = f.number();
    return t;
}

void readSpotCone(JsonObject& o, LightDesc& l) {
    const JsonValue lookAt = o["look_at"];
    l.lookAt = lookAt.vec3();
    checkDirection(lookAt, l.lookAt - l.position, "a point at least 1e-12 from \"position\"");
    if (auto f = o["cone_angle"]) l.coneAngle = f.number({.lo = 0, .hi = 90, .loOpen = true});
    // The default falloff band narrows with a cone narrower than itself.
    l.coneDelta = std::min(l.coneDelta, l.coneAngle);
    if (auto f = o["cone_delta"]) l.coneDelta = f.number({.lo = 0, .hi = l.coneAngle});
    if (auto f = o["radius"]) l.radius = f.number(kNonNegative);
}

LightDesc readLight(JsonObject& o, const fs::path& dir) {
    LightDesc l;
    l.type = o["type"].choice<LightType>({{"point", LightType::Point},
                                          {"spot", LightType::Spot},
                                          {"distant", LightType::Distant},
                                          {"quad", LightType::Quad},
                                          {"mesh", LightType::Mesh},
                                          {"environment", LightType::Environment}});
    if (l.type == LightType::Point || l.type == LightType::Spot) l.position = o["position"].vec3();
    if (l.type == LightType::Spot) readSpotCone(o, l);
    if (l.type == LightType::Distant) {
        const JsonValue direction = o["direction"];
        l.direction = direction.vec3();
        checkDirection(direction, l.direction, "a vector of length >= 1e-12");
    }
    if (l.type == LightType::Quad) {
        const Parallelogram p = readParallelogram(o);
        l.corner = p.corner;
        l.edge0 = p.edge0;
        l.edge1 = p.edge1;
    }
    if (l.type == LightType::Mesh)
        l.mesh = o["shape"].readObject([&](JsonObject& s) { return readShape(s, dir, false); }).mesh;
    if (l.type == LightType::Quad || l.type == LightType::Mesh)
        if (auto f = o["two_sided"]) l.twoSided = f.boolean();
    readLightEmission(o, l);
    return l;
}

using MaterialChoices = std::initializer_list<std::pair<std::string_view, MaterialType>>;

MaterialDesc readMaterial(JsonObject& o, MaterialChoices types) {
    MaterialDesc m;
    m.type = o["type"].choice<MaterialType>(types);
    if (m.type == MaterialType::Diffuse)
        if (auto f = o["reflectance"]) m.reflectance = f.vec3OrScalar(kUnitInterval);  // energy-conserving
    if (m.type == MaterialType::Dielectric)
        if (auto f = o["ior"]) m.ior = f.number(kPositive);
    return m;
}

SurfaceDesc readSurface(JsonObject& o, const fs::path& dir) {
    Shape shape = o["shape"].readObject([&](JsonObject& s) { return readShape(s, dir, false); });
    SurfaceDesc d;
    d.name = nameOf(o.self(), shape);
    d.mesh = std::move(shape.mesh);
    if (auto f = o["material"])
        d.material = f.readObject([](JsonObject& m) {
            return readMaterial(m, {{"diffuse", MaterialType::Diffuse},
                                    {"dielectric", MaterialType::Dielectric},
                                    {"interface", MaterialType::Interface}});
        });
    return d;
}

DensityDesc readDensity(JsonObject& o) {
    using Type = DensityDesc::Type;
    DensityDesc d;
    d.type = o["type"].choice<Type>({{"constant", Type::Constant}, {"linear", Type::Linear}, {"noise", Type::Noise}});
    switch (d.type) {
        case Type::Constant:
            if (auto f = o["value"]) d.offset = f.number(kNonNegative);
            break;
        case Type::Linear:
            if (auto f = o["offset"]) d.offset = f.number();
            d.gradient = o["gradient"].vec3();
            break;
        case Type::Noise:
            if (auto f = o["offset"]) d.offset = f.number(kNonNegative);
            if (auto f = o["amplitude"]) d.amplitude = f.number(kNonNegative);
            if (auto f = o["frequency"]) d.frequency = f.number(kPositive);
            if (auto f = o["seed"]) d.seed = uint32_t(f.integer(0, std::numeric_limits<uint32_t>::max()));
            break;
    }
    return d;
}

TetOptions readTetOptions(JsonObject& o) {
    TetOptions t;
    if (auto f = o["quality"]) {
        t.radiusEdgeRatio = f.number(kNonNegative);
        // TetGen's -q cannot reach a radius-edge ratio of 1 or less.
        if (t.radiusEdgeRatio > 0 && t.radiusEdgeRatio <= 1) f.fail("0 (off) or a radius-edge ratio > 1");
    }
    if (auto f = o["max_volume"]) t.maxVolume = f.number(kNonNegative);
    if (auto f = o["strict"]) t.strict = f.boolean();
    return t;
}

// What a page or a report may show as a medium's name: one line of a bounded length.
std::string readLabel(const JsonValue& v) {
    const std::string label = v.string();
    if (!validLabel(label))
        v.fail("a name of 1 to " + std::to_string(kMaxLabelBytes) + " bytes without control characters");
    return label;
}

// The shape, name and boundary a medium and a cavity both have.
MediumDesc readRegion(JsonObject& o, const fs::path& dir) {
    Shape shape = o["shape"].readObject([&](JsonObject& s) { return readShape(s, dir, true); });
    MediumDesc m;
    m.name = nameOf(o.self(), shape);
    const JsonValue label = o["name"];
    m.label = label                ? readLabel(label)
              : shape.file.empty() ? o.self().path()
                                   : fs::path(shape.file).filename().string();
    m.boundary = std::move(shape.mesh);
    if (auto f = o["boundary"])
        m.boundaryMaterial = f.readObject([](JsonObject& b) {
            return readMaterial(b, {{"interface", MaterialType::Interface}, {"dielectric", MaterialType::Dielectric}});
        });
    if (auto f = o["tetgen"]) m.tetOptions = f.readObject(readTetOptions);
    return m;
}

MediumDesc readMedium(JsonObject& o, const fs::path& dir) {
    MediumDesc m = readRegion(o, dir);
    readMediumCoefficients(o, m);
    return m;
}

// A region with no medium inside a medium: nothing to read but its shape and boundary.
MediumDesc readCavity(JsonObject& o, const fs::path& dir) {
    MediumDesc m = readRegion(o, dir);
    m.cavity = true;
    m.sigmaA = m.sigmaS = RGB(0);
    return m;
}

SceneDesc readScene(JsonObject& o, const std::string& path) {
    const fs::path dir = fs::path(path).parent_path();
    SceneDesc s;
    s.path = path;
    s.camera = o["camera"].readObject(readCamera);
    if (auto f = o["turntable"]) s.turntable = f.readObject([&](JsonObject& t) { return readTurntable(t, s.camera); });
    if (auto f = o["integrator"]) s.integrator = f.readObject(readIntegrator);
    if (auto f = o["output"]) s.output = (dir / f.string()).string();
    for (const JsonValue& v : optionalArray(o["lights"]))
        s.lights.push_back(v.readObject([&](JsonObject& x) { return readLight(x, dir); }));
    for (const JsonValue& v : optionalArray(o["surfaces"]))
        s.surfaces.push_back(v.readObject([&](JsonObject& x) { return readSurface(x, dir); }));
    for (const JsonValue& v : optionalArray(o["media"]))
        s.media.push_back(v.readObject([&](JsonObject& x) { return readMedium(x, dir); }));
    for (const JsonValue& v : optionalArray(o["cavities"]))
        s.media.push_back(v.readObject([&](JsonObject& x) { return readCavity(x, dir); }));
    if (!emitsLight(s))
        o["lights"].error(
            "nothing emits light: add a light with non-zero intensity, irradiance or radiance, or give a medium an "
            "\"emission\"");
    return s;
}

// The bounds of the JSON keys again, once the scene is built: the pbrt-v3 reader makes positions,
// directions and colours through transforms and products.
void checkLimits(const SceneDesc& s) {
    auto fail = [&](const std::string& what, const glm::dvec3& v, const std::string& allowed) {
        char value[96];
        std::snprintf(value, sizeof value, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
        throw InputError(s.path + ": " + what + " " + value + " is out of range: " + allowed);
    };
    auto point = [&](const glm::dvec3& p, const std::string& what) {
        for (int k = 0; k < 3; ++k)
            if (!kCoordinate.contains(p[k])) fail(what, p, "every coordinate in [-1e12, 1e12]");
    };
    auto direction = [&](const glm::dvec3& d, const std::string& what) {
        if (!(glm::length(d) >= kMinDirection)) fail(what, d, "a length >= 1e-12");
    };
    auto colour = [&](const RGB& c, const std::string& what) {
        for (int k = 0; k < 3; ++k)
            if (!kColour.contains(c[k])) fail(what, c, "every channel in [0, 3.40282e38]");
    };
    point(s.camera.position, "the camera position");
    point(s.camera.lookAt, "the camera's look-at point");
    direction(s.camera.lookAt - s.camera.position, "the camera's view direction");
    direction(s.camera.up, "the camera's up direction");
    for (size_t i = 0; i < s.lights.size(); ++i) {
        const LightDesc& l = s.lights[i];
        const std::string name = "light " + std::to_string(i);
        if (l.type == LightType::Point || l.type == LightType::Spot) point(l.position, name + " position");
        if (l.type == LightType::Spot) {
            point(l.lookAt, name + " look-at point");
            direction(l.lookAt - l.position, name + " axis");
        }
        if (l.type == LightType::Distant) {
            point(l.direction, name + " direction");
            direction(l.direction, name + " direction");
        }
        colour(l.intensity, name + " intensity");
        colour(l.irradiance, name + " irradiance");
        colour(l.radiance, name + " radiance");
    }
    for (const MediumDesc& m : s.media) colour(m.emission, m.name + " emission");
}

}  // namespace

void readCameraView(JsonObject& o, CameraDesc& c) {
    c.position = o["position"].vec3();
    const JsonValue lookAt = o["look_at"];
    c.lookAt = lookAt.vec3();
    checkDirection(lookAt, c.lookAt - c.position, "a point at least 1e-12 from \"position\"");
    const JsonValue up = o["up"];
    if (up) c.up = up.vec3();
    if (parallel(c.up, c.lookAt - c.position))
        up.error("the up direction must not be zero or parallel to the view direction (look_at - position)");
    if (auto f = o["fov"]) c.fov = f.number({.lo = 0, .hi = 180, .loOpen = true, .hiOpen = true});
}

void readLightEmission(JsonObject& o, LightDesc& l) {
    const double scale = scaleOf(o);
    emissionOf(l) = scale * rgb(o[emissionKey(l.type)]);
    if (auto f = o["on"]) l.on = f.boolean();
}

IntegratorDesc readIntegrator(JsonObject& o) {
    IntegratorDesc d;
    if (auto f = o["type"]) d.type = f.choice<IntegratorType>(kIntegratorNames);
    if (auto f = o["spp"]) {
        d.spp = int(f.integer(1, kMaxSpp));
        d.sppGiven = true;
    }
    if (auto f = o["max_depth"]) d.maxDepth = int(f.integer(1, kMaxDepth));
    if (auto f = o["seed"]) d.seed = uint64_t(f.integer(0));
    if (auto f = o["boundary"]) d.boundary = f.choice<BoundaryMode>(kBoundaryNames);
    if (auto f = o["step"]) d.stepSize = f.number(kPositive);
    if (auto f = o["parity_rays"]) {
        d.parityRays = int(f.integer(1, kMaxParityRays));
        // A majority vote needs an odd count.
        if (d.parityRays % 2 == 0) f.fail("an odd integer in 1.." + std::to_string(kMaxParityRays));
    }
    if (auto f = o["photons"]) d.photons = uint64_t(f.integer(1, kMaxPhotons));
    if (auto f = o["k"]) d.k = int(f.integer(1, 100000));
    if (auto f = o["radius"]) d.radius = f.number(kPositive);
    if (auto f = o["estimate"]) d.estimate = f.choice<PhotonEstimate>(kEstimateNames);
    if (auto f = o["alpha"]) d.alpha = f.number({.lo = 0, .hi = 1, .loOpen = true});
    if (auto f = o["boundary_correction"]) d.boundaryCorrection = f.boolean();
    if (auto f = o["final_gather"]) d.finalGather = f.boolean();
    if (auto f = o["time"]) d.timeLimit = f.number(kPositive);
    return d;
}

void readMediumCoefficients(JsonObject& o, MediumDesc& m) {
    const double scale = scaleOf(o);
    if (auto f = o["sigma_a"]) m.sigmaA = rgb(f);
    if (auto f = o["sigma_s"]) m.sigmaS = rgb(f);
    m.sigmaA *= scale;
    m.sigmaS *= scale;
    if (auto f = o["g"]) m.g = f.number({.lo = -1, .hi = 1, .loOpen = true, .hiOpen = true});
    if (auto f = o["emission"]) m.emission = rgb(f);
    if (auto f = o["density"]) m.density = f.readObject(readDensity);
}

bool validLabel(const std::string& label) {
    const auto control = [&](size_t i) {
        const auto c = static_cast<unsigned char>(label[i]);  // C0 and DEL, or C1 (U+0080..U+009F) in UTF-8
        return c < 0x20 || c == 0x7f ||
               (c == 0xc2 && i + 1 < label.size() && static_cast<unsigned char>(label[i + 1]) < 0xa0);
    };
    bool clean = !label.empty() && label.size() <= kMaxLabelBytes;
    for (size_t i = 0; i < label.size() && clean; ++i) clean = !control(i);
    return clean;
}

bool emitsLight(const SceneDesc& s) {
    for (const LightDesc& l : s.lights)
        if (l.on && (l.intensity != RGB(0) || l.radiance != RGB(0) || l.irradiance != RGB(0))) return true;
    for (const MediumDesc& m : s.media)
        if (m.emission != RGB(0)) return true;
    return false;
}

SceneDesc loadJsonSceneText(const std::string& text, const std::string& path) {
    return loadJsonScene(parseJson(text, path), path);
}

SceneDesc loadScene(const std::string& path, const std::string& camera) {
    const InputLog log;
    const auto read = [&] {
        auto pbrt = [&] {
            SceneDesc s = loadPbrtScene(path);
            checkLimits(s);
            return s;
        };
        auto gltf = [&](std::string data) {
            SceneDesc s = loadGltfScene(path, std::move(data), camera);
            checkLimits(s);
            return s;
        };
        // A GLB carries its buffers: it may be as large as a mesh file.
        if (looksLikeGltf(path, "")) return gltf(readInputFile(path, kMaxMeshFileBytes, "a glTF scene"));
        if (!camera.empty())
            throw InputError("--camera " + shorten(camera) + ": " + path +
                             " is not a glTF scene; only glTF scenes name their cameras");
        if (fs::path(path).extension() == ".pbrt") return pbrt();  // without reading the file here too
        std::string text = readInputFile(path, kMaxSceneFileBytes, "a scene file");
        if (looksLikeGltf(path, text)) return gltf(std::move(text));
        if (looksLikePbrt(text)) return pbrt();
        const nlohmann::json doc = parseJson(text, path);
        if (doc.is_object() && doc.contains("asset") && !doc.contains("camera")) return gltf(std::move(text));
        return loadJsonScene(doc, path);
    };
    SceneDesc scene = read();
    scene.inputs = log.files();
    return scene;
}

SceneDesc loadJsonScene(const nlohmann::json& doc, const std::string& path) {
    return JsonValue(&doc, nlohmann::json::json_pointer(), path).readObject([&](JsonObject& o) {
        return readScene(o, path);
    });
}

}  // namespace tetglow
