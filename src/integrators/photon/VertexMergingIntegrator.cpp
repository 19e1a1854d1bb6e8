#include "integrators/photon/VertexMergingIntegrator.h"

#include <cstdlib>

#include <tbb/parallel_for.h>

#include "integrators/DirectLighting.h"
#include "integrators/PathStep.h"
#include "integrators/photon/OctahedralDirection.h"
#include "integrators/photon/PhotonIntegrator.h"
#include "media/PhotonWalk.h"
#include "media/Roulette.h"
#include "media/SpectralPath.h"
#include "render/Material.h"

namespace tetglow {

namespace {

constexpr uint64_t kMergeStream = uint64_t(1) << 61;
constexpr uint64_t kBlock = 1024;

// The transmittance of the mean extinction: the geometric mean of the channels'.
double grayTransmittance(const RGB& tr) {
    if (!(minComponent(tr) > 0)) return 0;
    return std::exp((std::log(tr[0]) + std::log(tr[1]) + std::log(tr[2])) / 3);
}

}  // namespace

VertexMergingIntegrator::VertexMergingIntegrator(const Scene& scene, const IntegratorDesc& desc)
    : scene_(scene), desc_(desc), cameraMedium_(scene.mediumAt(scene.camera().position())) {
    for (const auto& light : scene.lights())
        if (!light->isDelta() && light.get() != scene.environment()) {
            light_ = light.get();
            break;
        }
    merging_ = light_ && !std::getenv("TETGLOW_MERGE_OFF");
    if (light_) {
        const PhotonEmission e = light_->emitPhoton({0.5, 0.5}, {0.5, 0.5});
        area_ = average(light_->power()) / (kPi * average(light_->emitted(-e.ray.d, 0)));
    }
}

VertexMergingIntegrator::~VertexMergingIntegrator() = default;

double VertexMergingIntegrator::lightEnd(const glm::dvec3& x1, const VolumeState& at, const glm::dvec3& x0,
                                         double phase) const {
    const glm::dvec3 toLight = x0 - x1;
    const double distance = glm::length(toLight);
    const glm::dvec3 wi = toLight / distance;
    const double pdf = lightPdf(scene_, *light_, x1, wi, x0, 0);
    if (!(pdf > 0)) return 0;
    const RGB tr = transmittance(scene_, Ray{x1, wi}, distance - scene_.rayEpsilon(), at);
    return grayTransmittance(tr) * phase / (area_ * kPi * pdf);
}

void VertexMergingIntegrator::tracePhoton(uint64_t index, uint64_t pass, std::vector<Photon>& photons,
                                          std::vector<LightEnd>& ends) const {
    Rng rng(desc_.seed, index, kMergeStream + pass);
    const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
    const PhotonEmission e = light_->emitPhoton({u0, u1}, {u2, u3});
    const RGB flux = e.flux / double(desc_.photons);
    const glm::dvec3 x0 = e.ray.o;
    SpectralPath path = SpectralPath::pick(rng.uniform());
    Ray ray = e.ray;
    VolumeState state = scene_.mediumAt(ray.o);
    int depth = 0, vertices = 0;
    double l = 0, interior = 0, previousSigma = 0;
    glm::dvec3 previousDirection(0);
    const HenyeyGreenstein* previousPhase = nullptr;
    for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
        std::optional<Intersection> hit;
        WalkExit exit;
        if (state.inside()) {
            const RegionMedia& medium = *scene_.volumes()[state.volume].media;
            const int volume = state.volume;
            const WalkResult walk = photonWalk(
                medium, ray, state.start, flux, path, rng, desc_.maxDepth - depth,
                [&](const Ray& r) {
                    hit = scene_.intersect(r, state);
                    return hit ? hit->t : INFINITY;
                },
                [&](const PhotonEvent& event) {
                    const RegionOptics& optics = medium.at(event.tet);
                    const double sigma = average(optics.sigmaT) * medium.density(event.tet, event.position);
                    if (++vertices == 1) {
                        l = lightEnd(event.position, {volume, WalkStart::inside(event.tet)}, x0, 1);
                    } else {
                        const double phase = previousPhase->eval(glm::dot(previousDirection, event.direction));
                        if (vertices == 2)
                            l *= phase;
                        else
                            interior += previousSigma / phase;
                        photons.push_back({glm::vec3(event.position), glm::vec3(event.power),
                                           packDirection(glm::vec3(event.direction)), 0});
                        ends.push_back({float(l), float(interior)});
                    }
                    previousDirection = event.direction;
                    previousSigma = sigma;
                    previousPhase = &optics.phase;
                });
            depth += walk.events;
            if (walk.absorbed) return;
            ray = walk.ray;
            exit = walk.exit;
        } else {
            hit = scene_.intersect(ray);
        }
        // Only paths through media and index-matched boundaries are merged.
        if (endStretch(scene_, hit, exit, ray, state) != StretchEnd::Crossed) return;
    }
}

void VertexMergingIntegrator::beginPass(uint64_t pass, const std::atomic<bool>*) {
    if (!merging_) return;
    radius_ = desc_.radius * PhotonIntegrator::radiusScale(pass, PhotonIntegrator::balancedAlpha(3), 3);
    volume_ = 4.0 / 3 * kPi * radius_ * radius_ * radius_;
    const uint64_t blocks = (desc_.photons + kBlock - 1) / kBlock;
    std::vector<std::vector<Photon>> photons(blocks);
    std::vector<std::vector<LightEnd>> ends(blocks);
    tbb::parallel_for(uint64_t(0), blocks, [&](uint64_t b) {
        for (uint64_t i = b * kBlock; i < std::min(desc_.photons, (b + 1) * kBlock); ++i)
            tracePhoton(i, pass, photons[b], ends[b]);
    });
    std::vector<Photon> all;
    ends_.clear();
    for (uint64_t b = 0; b < blocks; ++b) {
        all.insert(all.end(), photons[b].begin(), photons[b].end());
        ends_.insert(ends_.end(), ends[b].begin(), ends[b].end());
    }
    map_ = all.empty() ? nullptr : std::make_unique<PhotonMap>(std::move(all));
}

RGB VertexMergingIntegrator::merge(const glm::dvec3& p, const glm::dvec3& d, const HenyeyGreenstein& phase,
                                   double sigma, double interior) const {
    if (!map_) return RGB(0);
    thread_local std::vector<Neighbour> near;
    map_->withinRadius(glm::vec3(p), float(radius_), near);
    const double n = double(desc_.photons);
    RGB sum(0);
    for (const Neighbour& nb : near) {
        const Photon& photon = map_->photons()[nb.index];
        const LightEnd& end = ends_[nb.index];
        const double f = phase.eval(glm::dot(glm::dvec3(unpackDirection(photon.direction)), -d));
        if (!(f > 0)) continue;
        const double ratio = n * volume_ * end.l;
        const double total = 1 + ratio * (end.interior + sigma / f + interior);
        // phase x power / V, times the weight ratio sigma / f / total.
        sum += RGB(photon.power.x, photon.power.y, photon.power.z) * (n * end.l * sigma / total);
    }
    return sum;
}

RGB VertexMergingIntegrator::direct(const glm::dvec3& p, const glm::dvec3& d, const HenyeyGreenstein& phase,
                                    const VolumeState& here, double interior, Rng& rng) const {
    const LightChoice choice = chooseLight(scene_.lights(), p, true, rng.uniform());
    const double u0 = rng.uniform(), u1 = rng.uniform();
    if (!choice.light) return RGB(0);
    const LightSample ls = choice.light->sample(p, {u0, u1});
    if (ls.pdf <= 0 || isBlack(ls.L)) return RGB(0);
    const double f = phase.eval(glm::dot(d, ls.wi));
    const double tMax = std::isfinite(ls.distance) ? ls.distance - scene_.rayEpsilon() : INFINITY;
    const RGB tr = transmittance(scene_, Ray{p, ls.wi}, tMax, here);
    if (isBlack(tr)) return RGB(0);
    const double pdf = ls.pdf * choice.pmf;
    double weight = ls.delta ? 1 : powerHeuristic(pdf, f);
    if (merging_ && interior > 0 && choice.light == light_) {
        const double l = grayTransmittance(tr) * f / (area_ * kPi * pdf);
        weight /= 1 + double(desc_.photons) * volume_ * l * interior;
    }
    return f * tr * ls.L * (weight / pdf);
}

RGB VertexMergingIntegrator::radiance(const Ray& cameraRay, Rng& rng) const {
    RGB L(0);
    Ray ray = cameraRay;
    VolumeState state = cameraMedium_;
    SpectralPath path = SpectralPath::pick(rng.uniform());
    int depth = 0;
    bool specular = true, mergeable = true, lastInMedium = false;
    double lastPdf = 0;
    glm::dvec3 lastPoint = ray.o;
    // Sum of sigma / phase over the eye's medium vertices so far, and before the last one.
    double interior = 0, interiorBefore = 0;
    double logTr = 0;  // of the mean extinction since the last vertex
    for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
        auto hit = scene_.intersect(ray, state);
        FreeFlight flight;
        if (state.inside()) {
            const RegionMedia& medium = *scene_.volumes()[state.volume].media;
            const double tMax = hit ? hit->t : INFINITY;
            flight = medium.sampleFlight(ray, state.start, tMax, path.hero, rng.uniform(), path.r, true);
            L += path.beta * flight.glow;
            const double gray = grayTransmittance(flight.transmittance);
            logTr += gray > 0 ? std::log(gray) : -INFINITY;
            if (!flight.scattered) {
                path.pass(flight.transmittance);
            } else {
                const RegionOptics& optics = medium.at(flight.tet);
                path.interact(flight.transmittance, optics.sigmaT * flight.density);
                L += path.weight() * flight.density * optics.params.emission;
                const glm::dvec3 p = ray.at(flight.t);
                const double sigma = average(optics.sigmaT) * flight.density;
                if (merging_ && mergeable) L += path.weight() * merge(p, ray.d, optics.phase, sigma, interior);
                path.beta *= flight.density * optics.params.sigmaS;
                if (++depth >= desc_.maxDepth) break;
                const VolumeState here{
                    state.volume, flight.located ? WalkStart::inside(flight.tet) : WalkStart::inRegion(flight.tet)};
                if (!scene_.sealed(state.volume))
                    L += path.weight() * direct(p, ray.d, optics.phase, here, mergeable ? interior : -1, rng);
                const double u0 = rng.uniform(), u1 = rng.uniform();
                const glm::dvec3 wi = optics.phase.sample(ray.d, {u0, u1});
                const double f = optics.phase.eval(glm::dot(ray.d, wi));
                interiorBefore = interior;
                interior += sigma / f;
                specular = false;
                lastInMedium = true;
                lastPdf = f;
                lastPoint = p;
                logTr = 0;
                ray = {p, wi};
                state = here;
                if (!path.alive()) break;
                const double keep = eyePathSurvival(path.weight(), depth, rng);
                if (keep == 0) break;
                path.beta /= keep;
                continue;
            }
        }
        const StretchEnd end = endStretch(scene_, hit, flight.exit, ray, state);
        if (end == StretchEnd::Crossed) continue;
        if (end == StretchEnd::Escaped) {
            if (const Light* env = scene_.environment()) {
                const double w =
                    specular ? 1 : powerHeuristic(lastPdf, lightPdf(scene_, *env, lastPoint, ray.d, ray.o + ray.d, 0));
                L += path.weight() * env->emitted(ray.d, 0) * w;
            }
            break;
        }
        if (end == StretchEnd::Emitter) {
            const Light& light = *scene_.lights()[hit->index];
            double w = 1;
            if (!specular) {
                const double pdf = lightPdf(scene_, light, lastPoint, ray.d, hit->p, hit->triangle);
                w = powerHeuristic(lastPdf, pdf);
                if (merging_ && mergeable && lastInMedium && &light == light_ && pdf > 0) {
                    const double l = std::exp(logTr) * lastPdf / (area_ * kPi * pdf);
                    w /= 1 + double(desc_.photons) * volume_ * l * interiorBefore;
                }
            }
            L += path.weight() * light.emitted(ray.d, hit->triangle) * w;
            break;
        }
        const MaterialDesc& material = scene_.material(*hit);
        mergeable = false;
        lastInMedium = false;
        if (++depth >= desc_.maxDepth) break;
        if (!isSpecular(material)) {
            const VolumeState here = scene_.afterHit(*hit, ray.d, state);
            L += path.weight() * sampleDirect(
                                     scene_, hit->p, rng, true,
                                     [&](const glm::dvec3& wi) {
                                         return Scattering{evaluateMaterial(material, ray.d, hit->n, wi),
                                                           materialPdf(material, ray.d, hit->n, wi)};
                                     },
                                     [&](const Ray& r, double t) { return transmittance(scene_, r, t, here); });
        }
        const double u0 = rng.uniform(), u1 = rng.uniform();
        const BsdfSample bs = sampleMaterial(material, ray.d, hit->n, {u0, u1});
        path.beta *= bs.weight;
        specular = bs.specular;
        lastPdf = bs.pdf;
        lastPoint = hit->p;
        logTr = 0;
        leaveSurface(scene_, *hit, bs.direction, ray, state);
        if (!path.alive()) break;
        const double keep = eyePathSurvival(path.weight(), depth, rng);
        if (keep == 0) break;
        path.beta /= keep;
    }
    return L;
}

}  // namespace tetglow
