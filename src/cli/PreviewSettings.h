// What `tetglow preview` tunes, kept under the scene file's own keys:
//   {"integrator": {...}, "media": [{"scale", "sigma_a", "sigma_s", "g", "emission", "density"}, ...],
//    "camera": {"position", "look_at", "up", "fov"},
//    "lights": [{"intensity" (or the type's "irradiance", "radiance"), "scale", "on"}, ...],
//    "resolution_scale": s}
// The page changes them with a JSON merge patch (RFC 7386, but media and lights merge entry by
// entry and null
// is a value, so an error, except for integrator "radius": null, back to k neighbours), and the
// patched settings are read by the scene loader's own functions, so a bad value gets the
// loader's one-line error and no key the loader does not know (a mesh file, say) gets through.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/SceneDescription.h"

namespace tetglow::cli {

class PreviewSettings {
public:
    // `file`: the JSON scene file `loaded` was read from (null for a pbrt scene); the lights'
    // values are kept in its terms (the emitted quantity and "scale" as it has them).
    explicit PreviewSettings(const SceneDesc& loaded, const nlohmann::ordered_json& file = nullptr);
    // Throws InputError ("request: /media/0/g: expected a number in (-1, 1), got 1.5") and keeps
    // the settings as they were.
    void apply(const std::string& patch);
    const nlohmann::json& json() const { return settings_; }
    // The loaded scene with the settings: what is rendered and what a save writes.
    const SceneDesc& scene() const { return scene_; }
    // The values that differ from `before`, named as the page names them: "body · emission
    // [1e+30,1e+30,1e+30], spot · scale 90, integrator photons 20000" ("" when none do).
    std::string changesFrom(const PreviewSettings& before) const;
    // Per medium, what the page calls it: its "name" in the scene file, else its mesh's file
    // name, or its place in the file ("/media/2") when it is a built-in shape.
    std::vector<std::string> mediumNames() const;
    // Per light, its type ("spot"), numbered where the type comes more than once ("spot 2").
    std::vector<std::string> lightNames() const;
    // The JSON scene file `original`, as it was read, with the values changed since loading in
    // the file's own terms: only changed keys are written (sigma_a and sigma_s in units of the
    // medium's own "scale", a new scale as a multiple of it; a light's values as they are; a
    // single number stays one while the value is grey); every other key, mesh references, light
    // scales and units included, stays as it was.
    nlohmann::ordered_json editedScene(nlohmann::ordered_json original) const;

private:
    SceneDesc read(const nlohmann::json& settings) const;

    SceneDesc loaded_;
    nlohmann::json initial_, settings_;  // initial_: as loaded
    SceneDesc scene_;
};

}  // namespace tetglow::cli
