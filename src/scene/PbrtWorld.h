// pbrt-v3's world block -> SceneDesc: light sources, materials, area lights, named media and
// shapes, each with pbrt-v3's parameters, defaults and conventions.
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/PbrtParams.h"
#include "scene/SceneDescription.h"

namespace tetglow {

// A directive with a type and parameters: Shape "trianglemesh" "point P" [...].
struct PbrtCall {
    std::string type;
    PbrtParams params;
    PbrtLocation where;
};

// The state AttributeBegin saves and AttributeEnd restores (pbrt-v3's GraphicsState).
struct PbrtAttributes {
    std::optional<PbrtCall> material;  // none given: pbrt-v3's default, "matte"
    std::string namedMaterial;         // NamedMaterial, "" when a Material came later
    std::map<std::string, MaterialDesc> namedMaterials;
    struct AreaLight {
        RGB radiance{1};
        bool twoSided = false;
    };
    std::optional<AreaLight> areaLight;
    bool reverseOrientation = false;
    std::string insideMedium, outsideMedium;
};

class PbrtWorld {
public:
    PbrtWorld(std::filesystem::path searchDir, std::vector<std::string>& warnings)
        : searchDir_(std::move(searchDir)), warnings_(warnings) {}

    void lightSource(PbrtCall& call, const glm::dmat4& lightToWorld);
    PbrtAttributes::AreaLight areaLightSource(PbrtCall& call);
    void checkMaterial(PbrtCall& call);          // Material: errors now, not at the first Shape
    MaterialDesc namedMaterial(PbrtCall& call);  // MakeNamedMaterial: call.type is the name
    void namedMedium(PbrtCall& call);            // MakeNamedMedium: call.type is the name
    void shape(PbrtCall& call, const glm::dmat4& objectToWorld, const PbrtAttributes& attributes);
    // Once the world is read: every medium's (and cavity's) stated outside medium is the one the
    // meshes put around it, else an error naming the shape. The nesting, when there is one to check.
    std::shared_ptr<const MediaNesting> checkNesting() const;

    std::vector<LightDesc> lights;
    std::vector<SurfaceDesc> surfaces;
    std::vector<MediumDesc> media;

private:
    struct Medium {
        RGB sigmaA, sigmaS;
        double g;
    };
    MaterialDesc material(PbrtCall& shape, const PbrtAttributes& attributes);
    void warn(const PbrtLocation& where, const std::string& message) { pbrtWarn(warnings_, where, message); }

    std::filesystem::path searchDir_;
    std::vector<std::string>& warnings_;
    std::map<std::string, Medium> namedMedia_;
    struct Interface {
        std::string inside, outside;  // as the MediumInterface named them
        PbrtLocation where;           // of the Shape
    };
    std::vector<Interface> interfaces_;  // per entry of `media`
};

}  // namespace tetglow
