#include "scene/PbrtWorld.h"

#include <algorithm>

#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "scene/MediaNesting.h"
#include "scene/PbrtShapes.h"
#include "scene/PbrtTransform.h"

namespace tetglow {
namespace {

using Class = PbrtParamClass;

RGB color(PbrtParams& p, const std::string& name, const RGB& fallback) {
    const RGB c = p.getSpectrum(name, fallback);
    if (c.x < 0 || c.y < 0 || c.z < 0) p.fail(*p.find(name, Class::Spectrum), "must not be negative");
    return c;
}

// Where a material reads a parameter: the Shape's own parameters first, then the material's
// (pbrt-v3's TextureParams). Textures are not supported.
class MaterialLookup {
public:
    MaterialLookup(PbrtParams& first, PbrtParams* second) : first_(first), second_(second) {}
    PbrtParams& from(const std::string& name, Class cls) {
        for (PbrtParams* p : {&first_, second_})
            if (const PbrtParam* texture = p ? p->find(name, Class::Texture) : nullptr)
                p->fail(*texture, "textures are not supported");
        return first_.find(name, cls) || !second_ ? first_ : *second_;
    }

private:
    PbrtParams& first_;
    PbrtParams* second_;
};

MaterialDesc readMaterial(const std::string& type, const PbrtLocation& where, MaterialLookup p) {
    MaterialDesc m;
    // pbrt-v3 gives "" and "none" no BSDF; "interface" is pbrt-v4's name for the same.
    if (type.empty() || type == "none" || type == "interface") {
        m.type = MaterialType::Interface;
        return m;
    }
    p.from("bumpmap", Class::Float);  // a constant bump map does not bend normals
    if (type == "matte") {
        m.type = MaterialType::Diffuse;
        PbrtParams& kd = p.from("Kd", Class::Spectrum);
        m.reflectance = color(kd, "Kd", RGB(0.5));
        if (m.reflectance.x > 1 || m.reflectance.y > 1 || m.reflectance.z > 1)
            kd.fail(*kd.find("Kd", Class::Spectrum), "a reflectance above 1 is not supported");
        PbrtParams& sigma = p.from("sigma", Class::Float);
        if (sigma.getFloat("sigma", 0) != 0)
            sigma.fail(*sigma.find("sigma", Class::Float),
                       "Oren-Nayar roughness is not supported (only 0: Lambertian)");
        return m;
    }
    if (type == "glass") {
        m.type = MaterialType::Dielectric;
        for (const char* name : {"Kr", "Kt"}) {
            PbrtParams& k = p.from(name, Class::Spectrum);
            if (k.getSpectrum(name, RGB(1)) != RGB(1))
                k.fail(*k.find(name, Class::Spectrum), "only 1 (clear glass) is supported");
        }
        // pbrt-v3 reads "eta", and "index" when there is no "eta".
        PbrtParams& eta = p.from("eta", Class::Float);
        const char* name = eta.find("eta", Class::Float) ? "eta" : "index";
        PbrtParams& holder = p.from(name, Class::Float);
        m.ior = holder.getFloat(name, 1.5);
        if (!(m.ior > 0)) holder.fail(*holder.find(name, Class::Float), "must be positive");
        for (const char* rough : {"uroughness", "vroughness"}) {
            PbrtParams& r = p.from(rough, Class::Float);
            if (r.getFloat(rough, 0) != 0)
                r.fail(*r.find(rough, Class::Float), "rough glass is not supported (only 0)");
        }
        p.from("remaproughness", Class::Bool);
        return m;
    }
    pbrtError(where, "Material \"" + type + "\" is not supported (supported: matte, glass, \"\", none, interface)");
}

// pbrt-v3 puts a MediumInterface's inside medium behind each triangle's normal; tetglow's
// media fill closed meshes, so every normal must point out of the mesh.
void requireOutward(const TriangleMesh& mesh, const PbrtLocation& where, const std::string& medium) {
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (!edges.insert({t[k], t[(k + 1) % 3]}).second)
                pbrtError(where, "Shape: the triangles around medium \"" + medium +
                                     "\" are not wound consistently, so pbrt-v3 would put the medium on different "
                                     "sides of different triangles");
    if (signedVolume(mesh) < 0)
        pbrtError(where, "Shape: the normals around medium \"" + medium +
                             "\" point inwards (after ReverseOrientation, mirroring and \"N\"), so pbrt-v3 would put "
                             "the medium outside the mesh; tetglow's media fill the inside");
}

}  // namespace

void PbrtWorld::lightSource(PbrtCall& c, const glm::dmat4& lightToWorld) {
    PbrtParams& p = c.params;
    LightDesc l;
    const glm::dvec3 origin(lightToWorld * glm::dvec4(0, 0, 0, 1));
    const glm::dmat3 linear(lightToWorld);
    const RGB scale = color(p, "scale", RGB(1));
    if (!isAffine(lightToWorld)) pbrtError(c.where, "LightSource: a projective transform is not supported");
    if (c.type == "point") {
        l.type = LightType::Point;
        l.intensity = color(p, "I", RGB(1)) * scale;
        // pbrt-v3 (lights/point.cpp) translates by "from" after the CTM: from + CTM(origin).
        l.position = p.getPoint("from", glm::dvec3(0)) + origin;
    } else if (c.type == "spot") {
        l.type = LightType::Spot;
        l.intensity = color(p, "I", RGB(1)) * scale;
        const glm::dvec3 from = p.getPoint("from", glm::dvec3(0)), to = p.getPoint("to", glm::dvec3(0, 0, 1));
        if (from == to) pbrtError(c.where, "LightSource \"spot\": \"from\" and \"to\" must differ");
        if (!isSimilarity(linear))
            pbrtError(
                c.where,
                "LightSource \"spot\": under a non-uniform scale or shear the cone would not be round; not supported");
        l.position = glm::dvec3(lightToWorld * glm::dvec4(from, 1));
        l.lookAt = l.position + linear * glm::normalize(to - from);
        const double angle = p.getFloat("coneangle", 30), delta = p.getFloat("conedeltaangle", 5);
        if (!(angle > 0 && angle <= 90)) pbrtError(c.where, "LightSource \"spot\": \"coneangle\" must be in (0, 90]");
        // pbrt-v3's falloff starts at cos(coneangle - conedeltaangle): an angle of |coneangle -
        // conedeltaangle|, and none beyond coneangle.
        l.coneAngle = angle;
        l.coneDelta = angle - std::min(std::abs(angle - delta), angle);
    } else if (c.type == "distant") {
        l.type = LightType::Distant;
        l.irradiance = color(p, "L", RGB(1)) * scale;
        const glm::dvec3 from = p.getPoint("from", glm::dvec3(0)), to = p.getPoint("to", glm::dvec3(0, 0, 1));
        l.direction = linear * (to - from);  // the way the light travels
        if (!(glm::length(l.direction) > 0))
            pbrtError(c.where, "LightSource \"distant\": \"from\" and \"to\" must differ");
    } else if (c.type == "infinite" || c.type == "exinfinite") {
        l.type = LightType::Environment;
        l.radiance = color(p, "L", RGB(1)) * scale;
        if (const PbrtParam* map = p.find("mapname", Class::String))
            p.fail(*map, "environment maps are not supported (only a constant \"L\")");
    } else {
        pbrtError(c.where,
                  "LightSource \"" + c.type + "\" is not supported (supported: point, spot, distant, infinite)");
    }
    p.find("samples", Class::Integer);
    p.find("nsamples", Class::Integer);  // only the noise
    p.reportUnused(warnings_);
    lights.push_back(l);
}

PbrtAttributes::AreaLight PbrtWorld::areaLightSource(PbrtCall& c) {
    if (c.type != "diffuse" && c.type != "area")
        pbrtError(c.where, "AreaLightSource \"" + c.type + "\" is not supported (supported: diffuse)");
    PbrtParams& p = c.params;
    PbrtAttributes::AreaLight a;
    a.radiance = color(p, "L", RGB(1)) * color(p, "scale", RGB(1));
    a.twoSided = p.getBool("twosided", false);
    p.find("samples", Class::Integer);
    p.find("nsamples", Class::Integer);
    p.reportUnused(warnings_);
    return a;
}

void PbrtWorld::checkMaterial(PbrtCall& c) {
    readMaterial(c.type, c.where, MaterialLookup(c.params, nullptr));
    c.params.reportUnused(warnings_);
}

MaterialDesc PbrtWorld::namedMaterial(PbrtCall& c) {
    const std::string type = c.params.getString("type", "");
    if (!c.params.find("type", Class::String))
        pbrtError(c.where, "MakeNamedMaterial \"" + c.type + "\": \"string type\" is required");
    const MaterialDesc m = readMaterial(type, c.where, MaterialLookup(c.params, nullptr));
    c.params.reportUnused(warnings_);
    return m;
}

void PbrtWorld::namedMedium(PbrtCall& c) {
    PbrtParams& p = c.params;
    const std::string type = p.getString("type", "");
    if (type != "homogeneous")
        pbrtError(c.where,
                  "MakeNamedMedium \"" + c.type + "\": " +
                      (type.empty() ? "\"string type\" is required" : "type \"" + type + "\" is not supported") +
                      " (supported: homogeneous)");
    if (const PbrtParam* preset = p.find("preset", Class::String))
        p.fail(*preset, "named presets are not supported: give sigma_a and sigma_s");
    const double scale = p.getFloat("scale", 1);
    if (scale < 0) p.fail(*p.find("scale", Class::Float), "must not be negative");
    Medium m;
    // pbrt-v3's defaults (api.cpp MakeMedium), per unit length, times "scale".
    m.sigmaA = color(p, "sigma_a", RGB(.0011, .0024, .014)) * scale;
    m.sigmaS = color(p, "sigma_s", RGB(2.55, 3.21, 3.77)) * scale;
    m.g = p.getFloat("g", 0);
    if (!(std::abs(m.g) < 1)) p.fail(*p.find("g", Class::Float), "must be in (-1, 1)");
    p.reportUnused(warnings_);
    namedMedia_[c.type] = m;
}

MaterialDesc PbrtWorld::material(PbrtCall& shape, const PbrtAttributes& a) {
    if (!a.namedMaterial.empty()) {
        const auto it = a.namedMaterials.find(a.namedMaterial);
        if (it == a.namedMaterials.end())
            pbrtError(shape.where,
                      "Shape: NamedMaterial \"" + a.namedMaterial + "\" was not made by MakeNamedMaterial");
        return it->second;
    }
    if (!a.material) return readMaterial("matte", shape.where, MaterialLookup(shape.params, nullptr));
    PbrtParams params = a.material->params;  // a copy: its unused parameters were reported at Material
    return readMaterial(a.material->type, a.material->where, MaterialLookup(shape.params, &params));
}

void PbrtWorld::shape(PbrtCall& c, const glm::dmat4& objectToWorld, const PbrtAttributes& a) {
    PbrtMesh m = readPbrtMesh(c.type, c.params, c.where, objectToWorld, a.reverseOrientation, searchDir_, warnings_);
    const MaterialDesc mat = material(c, a);
    c.params.reportUnused(warnings_);
    const std::string name = c.where.str() + " (Shape \"" + c.type + "\")";
    if (m.hasNormals && mat.type != MaterialType::Interface)
        warn(c.where,
             "Shape: \"N\" only orients the triangles; tetglow shades with the flat triangle normal where pbrt-v3 "
             "interpolates N");
    for (const std::string& named : {a.insideMedium, a.outsideMedium})
        if (!named.empty() && !namedMedia_.count(named))
            pbrtError(c.where, "Shape: MediumInterface names medium \"" + named + "\", which no MakeNamedMedium made");
    // A medium fills the shape; a shape with only an outside medium is a cavity in it.
    if (!a.insideMedium.empty() || !a.outsideMedium.empty()) {
        const bool cavity = a.insideMedium.empty();
        const std::string& medium = cavity ? a.outsideMedium : a.insideMedium;
        if (a.areaLight) pbrtError(c.where, "Shape: an area light around a medium is not supported");
        if (mat.type == MaterialType::Diffuse) {
            warn(c.where, "Shape: medium \"" + medium + "\" is " + (cavity ? "around" : "inside") +
                              " an opaque \"matte\" surface: no light crosses it (as in pbrt-v3)");
            surfaces.push_back({name, std::move(m.mesh), mat});
            return;
        }
        requireOutward(m.mesh, c.where, medium);
        MediumDesc d;
        d.name = name;
        d.boundary = std::move(m.mesh);
        d.cavity = cavity;
        if (cavity)
            d.sigmaA = d.sigmaS = RGB(0);
        else {
            d.sigmaA = namedMedia_[medium].sigmaA;
            d.sigmaS = namedMedia_[medium].sigmaS;
            d.g = namedMedia_[medium].g;
        }
        d.boundaryMaterial = mat;
        media.push_back(std::move(d));
        interfaces_.push_back({a.insideMedium, a.outsideMedium, c.where});
        return;
    }
    if (a.areaLight) {
        if (!a.areaLight->twoSided && m.swapsHandedness)
            pbrtError(c.where,
                      "Shape: a one-sided area light under a mirroring transform: pbrt-v3 samples it on one side "
                      "(Triangle::Sample) "
                      "and lets rays hit it on the other (Triangle::Intersect); make it \"bool twosided\" \"true\" or "
                      "remove the mirroring");
        if (mat.type != MaterialType::Interface)
            warn(c.where,
                 "Shape: tetglow's area lights do not also reflect light, as pbrt-v3's do with their material; use "
                 "Material \"none\" to match");
        LightDesc l;
        l.type = LightType::Mesh;
        l.mesh = std::move(m.mesh);
        l.radiance = a.areaLight->radiance;
        l.twoSided = a.areaLight->twoSided;
        lights.push_back(std::move(l));
    } else if (mat.type != MaterialType::Interface) {
        surfaces.push_back({name, std::move(m.mesh), mat});
    }  // else: no material, no light, no medium: pbrt-v3 does not see it either
}

std::shared_ptr<const MediaNesting> PbrtWorld::checkNesting() const {
    const bool nestingMatters = media.size() > 1 || std::any_of(interfaces_.begin(), interfaces_.end(),
                                                                [](const Interface& i) { return !i.outside.empty(); });
    if (!nestingMatters) return nullptr;
    auto nesting = std::make_shared<const MediaNesting>(nestMedia(media));
    for (size_t i = 0; i < media.size(); ++i) {
        const int32_t p = nesting->parent[i];
        const std::string found = p < 0 ? "" : interfaces_[size_t(p)].inside;
        if (found == interfaces_[i].outside) continue;
        pbrtError(interfaces_[i].where,
                  "Shape: MediumInterface \"" + interfaces_[i].inside + "\" \"" + interfaces_[i].outside +
                      "\" says the shape lies in " +
                      (interfaces_[i].outside.empty() ? "no medium" : "medium \"" + interfaces_[i].outside + "\"") +
                      ", but it lies " +
                      (p < 0 ? "in no medium"
                             : "inside " + media[size_t(p)].name +
                                   (found.empty() ? ", a cavity" : ", medium \"" + found + "\"")) +
                      " (the nesting is found from the meshes)");
    }
    return nesting;
}

}  // namespace tetglow
