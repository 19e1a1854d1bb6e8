#include "scene/SceneWriter.h"

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "base/OutputFile.h"

namespace tetglow {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keys in the order FORMAT.md lists them

Json vec(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }

// Indented like dump(2), but an array of numbers or strings stays on one line: [0, 1.5, 5].
void print(const Json& j, const std::string& indent, std::string& out) {
    const bool flat = j.is_array() && std::none_of(j.begin(), j.end(), [](const Json& x) { return x.is_structured(); });
    if (flat || !j.is_structured() || j.empty()) {
        if (!flat) return void(out += j.dump());
        out += '[';
        for (size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
        out += ']';
        return;
    }
    const std::string inner = indent + "  ";
    out += j.is_object() ? "{\n" : "[\n";
    size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
        out += inner;
        if (j.is_object()) out += Json(it.key()).dump() + ": ";
        print(*it, inner, out);
        out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += indent + (j.is_object() ? "}" : "]");
}

Json densityJson(const DensityDesc& d) {
    switch (d.type) {
        case DensityDesc::Type::Constant: return {{"type", "constant"}, {"value", d.offset}};
        case DensityDesc::Type::Linear:
            return {{"type", "linear"}, {"offset", d.offset}, {"gradient", vec(d.gradient)}};
        case DensityDesc::Type::Noise: break;
    }
    return {{"type", "noise"},
            {"offset", d.offset},
            {"amplitude", d.amplitude},
            {"frequency", d.frequency},
            {"seed", d.seed}};
}

class Writer {
public:
    Writer(const SceneDesc& scene, const std::string& jsonPath)
        : scene_(scene), dir_(fs::path(jsonPath).parent_path()), stem_(fs::path(jsonPath).stem().string()) {}

    Json scene() {
        const CameraDesc& c = scene_.camera;
        Json j;
        j["camera"] = {{"position", vec(c.position)},
                       {"look_at", vec(c.lookAt)},
                       {"up", vec(c.up)},
                       {"fov", c.fov},
                       {"resolution", {c.width, c.height}},
                       {"handedness", c.handedness == Handedness::Left ? "left" : "right"}};
        j["integrator"] = integratorJson(scene_.integrator);
        if (const TurntableDesc& t = scene_.turntable; t.frames > 1)
            j["turntable"] = {
                {"frames", t.frames}, {"center", vec(t.center)}, {"axis", vec(t.axis)}, {"degrees", t.degrees}};
        // loadScene takes "output" relative to the scene file's folder.
        // (An output named without a folder lies in the working directory: absolute("") throws.)
        if (!scene_.output.empty())
            j["output"] =
                fs::absolute(scene_.output).lexically_relative(fs::absolute(dir_.empty() ? "." : dir_)).string();
        j["lights"] = Json::array();
        for (size_t i = 0; i < scene_.lights.size(); ++i) j["lights"].push_back(light(scene_.lights[i], i));
        j["surfaces"] = Json::array();
        for (size_t i = 0; i < scene_.surfaces.size(); ++i)
            j["surfaces"].push_back({{"shape", mesh(scene_.surfaces[i].mesh, "surface", i)},
                                     {"material", material(scene_.surfaces[i].material)}});
        j["media"] = Json::array();
        for (size_t i = 0; i < scene_.media.size(); ++i)
            if (!scene_.media[i].cavity) j["media"].push_back(medium(scene_.media[i], i));
        for (size_t i = 0; i < scene_.media.size(); ++i)
            if (scene_.media[i].cavity) j["cavities"].push_back(region(scene_.media[i], i));
        return j;
    }

    std::vector<std::string> written;
    std::vector<OutputWrite> writes;  // of the files in `written`, for writeTogether

private:
    static Json material(const MaterialDesc& m) {
        switch (m.type) {
            case MaterialType::Diffuse: return {{"type", "diffuse"}, {"reflectance", vec(m.reflectance)}};
            case MaterialType::Dielectric: return {{"type", "dielectric"}, {"ior", m.ior}};
            case MaterialType::Interface: break;
        }
        return {{"type", "interface"}};
    }

    // A "mesh" shape whose OBJ file holds the world-space triangles as they are.
    Json mesh(const TriangleMesh& m, const std::string& role, size_t index) {
        const std::string file = stem_ + "-" + role + "-" + std::to_string(index) + ".obj";
        prepareOutput((dir_ / file).string(), scene_.inputs);
        const std::string header = "# " + role + " " + std::to_string(index) + " of " + scene_.path + ", world space\n";
        writes.push_back(
            streamWrite((dir_ / file).string(), [&m, header](std::ostream& out) { writeObj(m, out, header); }, false));
        written.push_back((dir_ / file).string());
        return {{"type", "mesh"}, {"file", file}};
    }

    Json light(const LightDesc& l, size_t index) {
        Json j = lightShape(l, index);
        if (!l.on) j["on"] = false;
        return j;
    }

    // Its type, place and emission.
    Json lightShape(const LightDesc& l, size_t index) {
        switch (l.type) {
            case LightType::Point:
                return {{"type", "point"}, {"position", vec(l.position)}, {"intensity", vec(l.intensity)}};
            case LightType::Spot:
                return {{"type", "spot"},
                        {"position", vec(l.position)},
                        {"look_at", vec(l.lookAt)},
                        {"cone_angle", l.coneAngle},
                        {"cone_delta", l.coneDelta},
                        {"intensity", vec(l.intensity)},
                        {"radius", l.radius}};
            case LightType::Distant:
                return {{"type", "distant"}, {"direction", vec(l.direction)}, {"irradiance", vec(l.irradiance)}};
            case LightType::Quad:
                return {{"type", "quad"},        {"corner", vec(l.corner)},     {"edge0", vec(l.edge0)},
                        {"edge1", vec(l.edge1)}, {"radiance", vec(l.radiance)}, {"two_sided", l.twoSided}};
            case LightType::Mesh:
                return {{"type", "mesh"},
                        {"shape", mesh(l.mesh, "light", index)},
                        {"radiance", vec(l.radiance)},
                        {"two_sided", l.twoSided}};
            case LightType::Environment: break;
        }
        return {{"type", "environment"}, {"radiance", vec(l.radiance)}};
    }

    // What a medium and a cavity both have.
    Json region(const MediumDesc& m, size_t index) {
        Json tetgen = {{"quality", m.tetOptions.radiusEdgeRatio}, {"max_volume", m.tetOptions.maxVolume}};
        if (m.tetOptions.strict) tetgen["strict"] = true;
        Json j = m.label.empty() ? Json::object() : Json{{"name", m.label}};
        j.update(Json{{"shape", mesh(m.boundary, m.cavity ? "cavity" : "medium", index)},
                      {"boundary", material(m.boundaryMaterial)},
                      {"tetgen", tetgen}});
        return j;
    }

    Json medium(const MediumDesc& m, size_t index) {
        Json j = region(m, index);
        j.update(mediumCoefficientsJson(m));
        return j;
    }

    const SceneDesc& scene_;
    fs::path dir_;
    std::string stem_;
};

}  // namespace

Json integratorJson(const IntegratorDesc& d) {
    Json j = {{"type", nameOf(kIntegratorNames, d.type)},
              {"spp", d.spp},
              {"max_depth", d.maxDepth},
              {"seed", d.seed},
              {"boundary", nameOf(kBoundaryNames, d.boundary)},
              {"step", d.stepSize},
              {"parity_rays", d.parityRays},
              {"photons", d.photons},
              {"k", d.k},
              {"estimate", nameOf(kEstimateNames, d.estimate)},
              {"boundary_correction", d.boundaryCorrection},
              {"final_gather", d.finalGather}};
    // 0 means "not set" for these three; the loader takes only positive values.
    if (d.radius > 0) j["radius"] = d.radius;
    if (d.alpha > 0) j["alpha"] = d.alpha;
    if (d.timeLimit > 0) j["time"] = d.timeLimit;
    return j;
}

Json mediumCoefficientsJson(const MediumDesc& m) {
    return {{"sigma_a", vec(m.sigmaA)},
            {"sigma_s", vec(m.sigmaS)},
            {"g", m.g},
            {"emission", vec(m.emission)},
            {"density", densityJson(m.density)}};
}

std::vector<std::string> writeScene(const SceneDesc& scene, const std::string& jsonPath) {
    Writer writer(scene, jsonPath);
    const std::string text = sceneJsonText(writer.scene());
    // All or nothing: a failure at the last mesh leaves the earlier ones as they were.
    std::vector<OutputWrite> files = std::move(writer.writes);
    files.push_back(streamWrite(jsonPath, [&](std::ostream& out) { out << text; }));
    writeTogether(files);
    return writer.written;
}

std::string sceneJsonText(const nlohmann::ordered_json& scene) {
    std::string text;
    print(scene, "", text);
    return text + '\n';
}

void writeSceneJson(const nlohmann::ordered_json& scene, const std::string& jsonPath) {
    const std::string text = sceneJsonText(scene);
    writeStream(jsonPath, [&](std::ostream& out) { out << text; });
}

}  // namespace tetglow
