#include "scene/PbrtOptions.h"

#include <bit>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "scene/PbrtTransform.h"

namespace tetglow {
namespace {

using Class = PbrtParamClass;

// An error naming the parameter when it is given at all.
void reject(PbrtParams& p, const std::string& name, Class cls, const std::string& why) {
    if (const PbrtParam* given = p.find(name, cls)) p.fail(*given, why);
}

struct Film {
    int width = 1280, height = 720;  // pbrt-v3's defaults (core/film.cpp)
    std::string filename = "pbrt.exr";
};

Film readFilm(PbrtCall* call) {
    Film f;
    if (!call) return f;
    if (call->type != "image")
        pbrtError(call->where, "Film \"" + call->type + "\" is not supported (supported: image)");
    PbrtParams& p = call->params;
    f.width = p.getInt("xresolution", f.width);
    f.height = p.getInt("yresolution", f.height);
    for (const char* name : {"xresolution", "yresolution"})
        if (const PbrtParam* r = p.find(name, Class::Integer);
            r && (r->numbers[0] < 1 || r->numbers[0] > kMaxResolution))
            p.fail(*r, "must be in 1.." + std::to_string(kMaxResolution));
    f.filename = p.getString("filename", f.filename);
    const std::vector<double> crop = p.getFloats("cropwindow");
    if (!crop.empty() && crop != std::vector<double>{0, 1, 0, 1})
        p.fail(*p.find("cropwindow", Class::Float), "cropping is not supported");
    reject(p, "pixelbounds", Class::Integer, "cropping is not supported");
    reject(p, "maxsampleluminance", Class::Float, "clamping samples is not supported");
    if (p.getFloat("scale", 1) != 1) p.fail(*p.find("scale", Class::Float), "only 1 is supported");
    p.find("diagonal", Class::Float);  // the sensor size of the "realistic" camera only
    return f;
}

CameraDesc readCamera(PbrtCall* call, const glm::dmat4& cameraToWorld, const Film& film, const PbrtLocation& where) {
    CameraDesc c;
    c.width = film.width;
    c.height = film.height;
    PbrtParams none;
    PbrtParams& p = call ? call->params : none;
    const PbrtLocation at = call ? call->where : where;
    if (call && call->type != "perspective")
        pbrtError(at, "Camera \"" + call->type + "\" is not supported (supported: perspective)");
    c.fov = p.getFloat("fov", 90);
    if (const double half = p.getFloat("halffov", -1); half > 0) c.fov = 2 * half;
    if (!(c.fov > 0 && c.fov < 180)) pbrtError(at, "Camera: the field of view must be in (0, 180) degrees");
    if (p.getFloat("lensradius", 0) != 0)
        p.fail(*p.find("lensradius", Class::Float), "depth of field is not supported (only 0)");
    p.find("focaldistance", Class::Float);
    p.find("shutteropen", Class::Float);
    p.find("shutterclose", Class::Float);
    if (const PbrtParam* ratio = p.find("frameaspectratio", Class::Float);
        ratio && std::abs(ratio->numbers[0] - double(film.width) / film.height) > 1e-6 * ratio->numbers[0])
        p.fail(*ratio, "only the film's own aspect ratio is supported");
    reject(p, "screenwindow", Class::Float, "a screen window is not supported");

    const glm::dmat3 frame(cameraToWorld);  // columns: image x, image y, view direction
    if (!isAffine(cameraToWorld) || !isSimilarity(frame))
        pbrtError(at, "Camera: the camera transform must be rotations, translations, uniform scales and mirrors");
    c.position = glm::dvec3(cameraToWorld * glm::dvec4(0, 0, 0, 1));
    c.lookAt = c.position + glm::normalize(frame[2]);
    c.up = glm::normalize(frame[1]);
    // LookAt alone gives image x = cross(up, view): a left-handed frame; a mirror undoes it.
    c.handedness = glm::dot(frame[0], glm::cross(frame[2], frame[1])) > 0 ? Handedness::Right : Handedness::Left;
    return c;
}

// pbrt-v3's samplers: only how many samples each takes per pixel matters to tetglow.
int samplesPerPixel(PbrtCall& call) {
    PbrtParams& p = call.params;
    p.find("dimensions", Class::Integer);
    p.find("jitter", Class::Bool);
    // In 64 bits: 65536 x 65537 samples must not wrap.
    if (call.type == "stratified")
        return int(std::min<int64_t>(int64_t(p.getInt("xsamples", 4)) * p.getInt("ysamples", 4), kMaxSpp + 1));
    if (call.type == "random") return p.getInt("pixelsamples", 4);
    const int n = p.getInt("pixelsamples", 16);
    if (call.type == "halton") return n;
    // These round up to a power of two (samplers/sobol.cpp, zerotwosequence.cpp, maxmin.cpp).
    if (call.type == "sobol" || call.type == "02sequence" || call.type == "lowdiscrepancy" || call.type == "maxmindist")
        return n > 0 && n <= kMaxSpp ? int(std::bit_ceil(unsigned(n))) : n;
    pbrtError(call.where,
              "Sampler \"" + call.type +
                  "\" is not supported (supported: halton, sobol, random, stratified, 02sequence, maxmindist)");
}

IntegratorDesc readIntegrator(PbrtCall* sampler, PbrtCall* integrator, std::vector<std::string>& warnings) {
    IntegratorDesc d;
    d.type = IntegratorType::VolPath;
    d.spp = 16;  // pbrt-v3's default sampler: "halton", 16 per pixel
    if (sampler) {
        d.spp = samplesPerPixel(*sampler);
        d.sppGiven = true;
        if (d.spp < 1 || d.spp > kMaxSpp)
            pbrtError(sampler->where, "Sampler: the number of samples per pixel must be in 1.." +
                                          std::to_string(kMaxSpp) + ", got " + std::to_string(d.spp));
        const int seed = sampler->params.getInt("seed", 0);
        if (seed < 0) sampler->params.fail(*sampler->params.find("seed", Class::Integer), "must not be negative");
        d.seed = uint64_t(seed);
        sampler->params.reportUnused(warnings);
        pbrtWarn(warnings, sampler->where,
                 "Sampler \"" + sampler->type + "\": tetglow draws its own random numbers; only the count, " +
                     std::to_string(d.spp) + " samples per pixel, is used",
                 "note");
    }
    int maxDepth = 5;  // pbrt-v3's default
    if (integrator) {
        if (integrator->type != "volpath" && integrator->type != "path")
            pbrtError(integrator->where,
                      "Integrator \"" + integrator->type + "\" is not supported (supported: volpath, path)");
        PbrtParams& p = integrator->params;
        maxDepth = p.getInt("maxdepth", maxDepth);
        // tetglow counts one more event than pbrt-v3 (below): the top of int's range would wrap.
        if (maxDepth < 0 || maxDepth >= kMaxDepth)
            p.fail(*p.find("maxdepth", Class::Integer), "must be in 0.." + std::to_string(kMaxDepth - 1));
        reject(p, "pixelbounds", Class::Integer, "cropping is not supported");
        p.find("rrthreshold", Class::Float);
        p.find("lightsamplestrategy", Class::String);  // only the noise
        p.reportUnused(warnings);
    }
    // pbrt-v3 scatters at most maxdepth times; tetglow's max_depth counts the event that ends
    // the path too.
    d.maxDepth = maxDepth + 1;
    return d;
}

void checkFilter(PbrtCall* filter, std::vector<std::string>& warnings) {
    if (!filter) return;
    PbrtParams& p = filter->params;
    const bool box = filter->type == "box" && p.getFloat("xwidth", 0.5) == 0.5 && p.getFloat("ywidth", 0.5) == 0.5;
    if (!box)
        pbrtWarn(warnings, filter->where,
                 "PixelFilter \"" + filter->type +
                     "\": tetglow averages the samples in each pixel (pbrt-v3's \"box\" of width 0.5), so the image is "
                     "a little sharper than pbrt-v3's");
}

// pbrt-v3's "path" ignores media: it sees glass boundaries as glass and index-matched ones not at all.
void dropMedia(SceneDesc& scene, const PbrtLocation& where, std::vector<std::string>& warnings) {
    if (scene.media.empty()) return;
    pbrtWarn(warnings, where,
             "Integrator \"path\" ignores the " + std::to_string(scene.media.size()) +
                 " media, as pbrt-v3 does; use \"volpath\" to render them");
    for (MediumDesc& m : scene.media)
        if (m.boundaryMaterial.type == MaterialType::Dielectric)
            scene.surfaces.push_back({m.name, std::move(m.boundary), m.boundaryMaterial});
    scene.media.clear();
}

}  // namespace

void applyPbrtOptions(PbrtOptions& o, SceneDesc& scene, std::vector<std::string>& warnings) {
    PbrtCall* film = o.film ? &*o.film : nullptr;
    const Film f = readFilm(film);
    scene.camera = readCamera(o.camera ? &*o.camera : nullptr, o.cameraToWorld, f, o.worldBegin);
    if (o.camera) o.camera->params.reportUnused(warnings);
    scene.output = f.filename;
    if (std::filesystem::path(f.filename).extension() != ".exr") {
        scene.output = std::filesystem::path(f.filename).replace_extension(".exr").string();
        pbrtWarn(warnings, film->where, "Film: tetglow writes OpenEXR: " + scene.output + " instead of " + f.filename);
    }
    if (film) film->params.reportUnused(warnings);
    scene.integrator =
        readIntegrator(o.sampler ? &*o.sampler : nullptr, o.integrator ? &*o.integrator : nullptr, warnings);
    checkFilter(o.filter ? &*o.filter : nullptr, warnings);
    if (!o.integrator || o.integrator->type == "path")
        dropMedia(scene, o.integrator ? o.integrator->where : o.worldBegin, warnings);
}

}  // namespace tetglow
