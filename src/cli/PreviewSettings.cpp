#include "cli/PreviewSettings.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>

#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow::cli {
namespace {

const std::string kSource = "request";  // errors name the request as the loader names a file
constexpr Range kResolutionScale{.lo = 0, .hi = 1, .loOpen = true};

nlohmann::json unordered(const nlohmann::ordered_json& j) { return nlohmann::json::parse(j.dump()); }
nlohmann::json triple(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

bool changed(const nlohmann::json& now, const nlohmann::json& was, const char* key) {
    return now.contains(key) && (!was.contains(key) || now[key] != was[key]);
}

// `value` as the file's `entry` has `key`: a single number stays one while the value is grey
// (its three channels equal); otherwise the three channels.
nlohmann::ordered_json asFileHas(const nlohmann::ordered_json& entry, const char* key, nlohmann::ordered_json value) {
    const bool single = entry.contains(key) && entry[key].is_number() && value.is_array() && value.size() == 3 &&
                        value[0] == value[1] && value[1] == value[2];
    return single ? value[0] : value;
}

// A light's values as the scene file has them (the emitted quantity, "scale" and "on"), so that
// the preview computes them as the loader does and a save writes them back in the file's units;
// from the loaded light when there is no file (a pbrt scene).
nlohmann::json lightSettings(const LightDesc& l, const nlohmann::ordered_json& entry) {
    const char* key = emissionKey(l.type);
    if (!entry.is_object()) return {{key, triple(emissionOf(l))}, {"scale", 1}, {"on", l.on}};
    const nlohmann::json value = unordered(entry[key]);
    return {{key, value.is_number() ? nlohmann::json{value, value, value} : value},
            {"scale", entry.contains("scale") ? unordered(entry["scale"]) : nlohmann::json(1)},
            {"on", l.on}};
}

// "spot", "environment"; "spot 1", "spot 2" where a type comes more than once.
std::vector<std::string> lightNames(const std::vector<LightDesc>& lights) {
    static const NameTable<LightType, 6> kNames{{{"point", LightType::Point},
                                                 {"spot", LightType::Spot},
                                                 {"distant", LightType::Distant},
                                                 {"quad", LightType::Quad},
                                                 {"mesh light", LightType::Mesh},
                                                 {"environment", LightType::Environment}}};
    std::vector<std::string> names;
    for (const LightDesc& l : lights) {
        const auto same = [&](const LightDesc& o) { return o.type == l.type; };
        const size_t before = size_t(std::count_if(lights.data(), &l, same));
        names.emplace_back(nameOf(kNames, l.type));
        if (std::count_if(lights.begin(), lights.end(), same) > 1)
            names.back().append(" ").append(std::to_string(before + 1));
    }
    return names;
}

// RFC 7386's merge, except that null replaces a value instead of removing it: a number the page
// could not read arrives as null and must be an error, not a silent return to the loaded value.
void merge(nlohmann::json& target, const nlohmann::json& patch) {
    if (!patch.is_object() || !target.is_object()) {
        target = patch;
        return;
    }
    for (const auto& [key, value] : patch.items()) merge(target[key], value);
}

}  // namespace

PreviewSettings::PreviewSettings(const SceneDesc& loaded, const nlohmann::ordered_json& file)
    : loaded_(loaded), scene_(loaded) {
    settings_["integrator"] = unordered(integratorJson(loaded.integrator));
    settings_["media"] = nlohmann::json::array();
    for (const MediumDesc& m : loaded.media) {
        nlohmann::json medium = unordered(mediumCoefficientsJson(m));
        medium["scale"] = 1;  // sigma_a and sigma_s are the loaded ones, "scale" already applied
        settings_["media"].push_back(medium);
    }
    const CameraDesc& c = loaded.camera;
    settings_["camera"] = {
        {"position", triple(c.position)}, {"look_at", triple(c.lookAt)}, {"up", triple(c.up)}, {"fov", c.fov}};
    settings_["lights"] = nlohmann::json::array();
    for (size_t i = 0; i < loaded.lights.size(); ++i)
        settings_["lights"].push_back(
            lightSettings(loaded.lights[i], file.is_object() && file.contains("lights") ? file["lights"][i] : nullptr));
    settings_["resolution_scale"] = 1;
    initial_ = settings_;
}

void PreviewSettings::apply(const std::string& text) {
    const nlohmann::json patch = parseJson(text, kSource);
    if (!patch.is_object()) JsonValue(&patch, nlohmann::json::json_pointer(), kSource).fail("an object");
    nlohmann::json next = settings_;
    for (const auto& [key, value] : patch.items()) {
        nlohmann::json& target = next[key];
        if ((key == "media" || key == "lights") && value.is_array() && target.is_array() &&
            value.size() <= target.size())
            for (size_t i = 0; i < value.size(); ++i) merge(target[i], value[i]);
        else
            merge(target, value);  // an unknown key lands here and read() names it
    }
    // "radius": null goes back to k neighbours (the one tuned key a scene file may leave out).
    nlohmann::json& integrator = next["integrator"];
    if (integrator.is_object() && integrator.contains("radius") && integrator["radius"].is_null())
        integrator.erase("radius");
    scene_ = read(next);
    settings_ = std::move(next);
}

std::string PreviewSettings::changesFrom(const PreviewSettings& before) const {
    std::string out;
    // `words`: what the page calls a key where it is not the key itself.
    const auto compare = [&](const std::string& owner, const nlohmann::json& now, const nlohmann::json& was,
                             const std::map<std::string, std::string>& words = {}) {
        for (const auto& [key, value] : now.items())
            if (!was.contains(key) || was[key] != value) {
                const auto word = words.find(key);
                out +=
                    (out.empty() ? "" : ", ") + owner + (word == words.end() ? key : word->second) + " " + value.dump();
            }
    };
    // Named as the page names them: "body · emission", "spot · intensity".
    const std::vector<std::string> media = mediumNames(), lights = lightNames();
    for (const auto& [key, value] : settings_.items()) {
        const nlohmann::json& was = before.settings_[key];
        if (key == "media")
            for (size_t i = 0; i < value.size(); ++i)
                compare(media[i] + " · ", value[i], was[i], {{"scale", "density scale"}});
        else if (key == "lights")
            for (size_t i = 0; i < value.size(); ++i) compare(lights[i] + " · ", value[i], was[i]);
        else if (value.is_object())
            compare(key + " ", value, was);
        else if (value != was)
            out += (out.empty() ? "" : ", ") + key + " " + value.dump();
    }
    return out;
}

std::vector<std::string> PreviewSettings::mediumNames() const {
    std::vector<std::string> names;
    for (const MediumDesc& m : loaded_.media) names.push_back(m.label.empty() ? m.name : m.label);
    return names;
}

std::vector<std::string> PreviewSettings::lightNames() const { return cli::lightNames(loaded_.lights); }

nlohmann::ordered_json PreviewSettings::editedScene(nlohmann::ordered_json doc) const {
    const nlohmann::json &integrator = settings_["integrator"], &wasIntegrator = initial_["integrator"];
    for (const auto& [key, value] : integrator.items())
        if (changed(integrator, wasIntegrator, key.c_str())) doc["integrator"][key] = value;
    for (const auto& [key, value] : wasIntegrator.items())
        if (!integrator.contains(key) && doc.contains("integrator"))
            doc["integrator"].erase(key);  // "radius": back to k
    for (const auto& [key, value] : settings_["camera"].items())
        if (changed(settings_["camera"], initial_["camera"], key.c_str())) doc["camera"][key] = value;
    if (settings_["resolution_scale"] != initial_["resolution_scale"])
        doc["camera"]["resolution"] = {scene_.camera.width, scene_.camera.height};
    for (size_t i = 0; i < loaded_.lights.size(); ++i) {
        const nlohmann::json &now = settings_["lights"][i], &was = initial_["lights"][i];
        nlohmann::ordered_json& l = doc["lights"][i];
        for (const auto& [key, value] : now.items())
            if (changed(now, was, key.c_str())) l[key] = asFileHas(l, key.c_str(), value);
    }
    size_t entry = 0;  // in the file's "media" (the cavities follow them in the scene, apart in the file)
    for (size_t i = 0; i < loaded_.media.size(); ++i) {
        if (loaded_.media[i].cavity) continue;
        nlohmann::ordered_json& m = doc["media"][entry++];
        const nlohmann::json &now = settings_["media"][i], &was = initial_["media"][i];
        // The file's sigma_a and sigma_s are in units of its "scale". (A scale of 0 made the loaded
        // ones 0: any change writes both as the page has them, with the page's scale.)
        const double fileScale = m.contains("scale") ? m["scale"].get<double>() : 1.0;
        const double unit = fileScale > 0 ? fileScale : 1.0;
        const auto inUnits = [&](const nlohmann::json& v) {
            if (!v.is_array()) return nlohmann::ordered_json(v.get<double>() / unit);
            nlohmann::ordered_json out = nlohmann::ordered_json::array();
            for (const auto& x : v) out.push_back(x.get<double>() / unit);
            return out;
        };
        for (const char* key : {"g", "emission"})
            if (changed(now, was, key)) m[key] = asFileHas(m, key, now[key]);
        const bool zero = fileScale <= 0 &&
                          (changed(now, was, "sigma_a") || changed(now, was, "sigma_s") || changed(now, was, "scale"));
        for (const char* key : {"sigma_a", "sigma_s"})
            if (zero || changed(now, was, key)) m[key] = asFileHas(m, key, inUnits(now[key]));
        if (zero || changed(now, was, "scale")) m["scale"] = unit * now["scale"].get<double>();
    }
    return doc;
}

SceneDesc PreviewSettings::read(const nlohmann::json& settings) const {
    SceneDesc s = loaded_;
    JsonValue(&settings, nlohmann::json::json_pointer(), kSource).readObject([&](JsonObject& o) {
        s.integrator = o["integrator"].readObject(readIntegrator);
        const JsonValue media = o["media"];
        const std::vector<JsonValue> items = media.array();
        if (items.size() != s.media.size())
            media.fail("an array of at most " + std::to_string(s.media.size()) + " media, one per medium of the scene");
        for (size_t i = 0; i < items.size(); ++i) {
            items[i].readObject([&](JsonObject& m) {
                readMediumCoefficients(m, s.media[i]);
                return 0;
            });
            const MediumDesc& m = s.media[i];
            if (m.cavity && (m.sigmaA != RGB(0) || m.sigmaS != RGB(0) || m.emission != RGB(0)))
                items[i].error(m.name + " is a cavity: it holds no medium to tune (its coefficients stay 0)");
        }
        o["camera"].readObject([&](JsonObject& c) {
            readCameraView(c, s.camera);
            return 0;
        });
        const JsonValue lights = o["lights"];
        const std::vector<JsonValue> lightItems = lights.array();
        if (lightItems.size() != s.lights.size())
            lights.fail("an array of at most " + std::to_string(s.lights.size()) +
                        " lights, one per light of the scene");
        for (size_t i = 0; i < lightItems.size(); ++i) {
            lightItems[i].readObject([&](JsonObject& l) {
                readLightEmission(l, s.lights[i]);
                return 0;
            });
        }
        const double scale = o["resolution_scale"].number(kResolutionScale);
        s.camera.width = std::max(1, int(std::lround(loaded_.camera.width * scale)));
        s.camera.height = std::max(1, int(std::lround(loaded_.camera.height * scale)));
        return 0;
    });
    if (!emitsLight(s))
        throw InputError(kSource + ": nothing emits light: turn a light on, or give it or a medium an emission");
    return s;
}

}  // namespace tetglow::cli
