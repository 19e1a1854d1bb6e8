#include "photon/PhotonIntegrator.h"
#include "media/FreeFlight.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "base/Memory.h"
#include "integrators/DirectLighting.h"
#include "photon/OctahedralDirection.h"
#include "sampling/Equiangular.h"
#include "scene/Material.h"
#include "scene/UnsampledLight.h"

namespace tetglow {

namespace {

// Photons in a k-NN ball or a disc never reach this far: at worst a sparse map gets a blurry
// estimate instead of one lookup that spans the whole scene.
constexpr double kMaxRadiusFraction = 0.2;  // of the medium's (or the scene's) bounding-box diagonal
// What one stored photon costs at the peak of a pass: itself in the tracer's blocks and again
// when they are joined, then in its map with the k-d tree, the beam BVH and its ball's volume.
constexpr double kBytesPerStoredPhoton = 160;
// A domain whose longest mean free path is shorter than this fraction of its bounding-box
// diagonal is optically dense: the photon density changes within a mean free path of its
// boundary (where the eye sees it) and within sqrt(max depth) mean free paths (where a truncated
// walk stops), both far below any kernel radius a pass's photons fill. The eye path walks it
// unmeasured: the photons read it 25 to 50% (at 1e-4, 80%) dark, a bias that halving the radius
// hardly changes and the walk's noise hid from the pilot.
constexpr double kDenseMeanFreePath = 0.02;

// The smallest extinction (any channel, any tet) of the domain's media, times its diagonal.
double opticalSize(const Scene& scene, const std::vector<int>& media, double diagonal) {
    double smallest = INFINITY;
    for (int m : media) {
        const MediumPlace& sm = scene.media()[size_t(m)];
        const Volume& volume = *scene.volumes()[sm.volume].volume;
        const TetMesh& mesh = volume.mesh();
        const RGB& sigmaT = volume.region(sm.region).sigmaT;
        const double least = std::min({sigmaT[0], sigmaT[1], sigmaT[2]});
        for (uint32_t t = mesh.regionTets[sm.region]; t < mesh.regionTets[sm.region + 1]; ++t)
            for (uint32_t v : mesh.tets[t]) smallest = std::min(smallest, least * volume.density(t, mesh.vertices[v]));
    }
    return smallest * diagonal;
}

// Whether a surface or a medium boundary of the scene refracts or reflects specularly (a
// dielectric): light from a light that reaches a diffuse surface through one is a caustic, which
// from a light of zero size only photons find.
bool hasDielectric(const Scene& scene) {
    auto dielectric = [](const MaterialDesc& m) { return m.type == MaterialType::Dielectric; };
    const auto& surfaces = scene.desc().surfaces;
    return std::any_of(surfaces.begin(), surfaces.end(), [&](const auto& s) { return dielectric(s.material); }) ||
           std::any_of(scene.volumes().begin(), scene.volumes().end(), [&](const SceneVolume& v) {
               return std::any_of(v.materials.begin(), v.materials.end(), dielectric);
           });
}

// Where the pilot cannot judge: a scene with a dielectric surface or boundary. Light can reach a
// medium there along a specular chain (a caustic: from a light of zero size, a small light or a
// glowing medium behind glass), which the walk finds by chance only, rarely and bright; a pilot
// of thousands of paths does not see that tail (on the demo fish it measured the walk's error in
// the water 13 times below the photons' and the walk rendered 3,000 times the error with
// fireflies). Photons stay there unless the medium is dense (warnings() tells the user where
// the walk then misses light).
bool unmeasurable(const Scene& scene) { return hasDielectric(scene); }

}  // namespace

PhotonIntegrator::PhotonIntegrator(const Scene& scene, const IntegratorDesc& desc)
    : scene_(scene),
      desc_(desc),
      cameraMedium_(scene.volumeAt(scene.camera().position())),
      source_(scene),
      domains_(photonDomains(scene)),
      volpath_(scene, desc.maxDepth) {
    // The render's time limit runs from here (the render starts next): no photon pass traces past it.
    if (desc.timeLimit > 0)
        deadline_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                           std::chrono::duration<double>(desc.timeLimit));
    // A pass stores about one photon per path, checked now; as a path can store up to max depth
    // photons, their number is also bounded while they are traced (maxStored).
    checkMemory(double(desc.photons) * sizeof(Photon),
                std::to_string(desc.photons) + " photon paths per pass (a 32-byte photon each)");
    Bounds3 all;
    for (size_t d = 0; d < domains_.media.size(); ++d) {
        const TetMesh& mesh = scene.volumes()[size_t(domains_.volume[d])].volume->mesh();
        Bounds3 box;
        for (const auto& triangle : domains_.boundary[d])
            for (uint32_t v : triangle) box.extend(mesh.vertices[v]);
        regionBoundaries_.push_back(std::make_unique<SurfaceBVH>(mesh.vertices, domains_.boundary[d]));
        balls_.emplace_back(*regionBoundaries_.back());
        MediumPhotons photons;
        photons.maxRadius = float(kMaxRadiusFraction * box.diagonal());
        DomainChoice choice;
        choice.media = domains_.media[d];
        choice.passes = uint64_t(std::max(1, desc.spp));
        photons.walked = opticalSize(scene, domains_.media[d], box.diagonal()) * kDenseMeanFreePath > 1;
        choice.measured =
            !photons.walked && !unmeasurable(scene) && scene.volumes()[size_t(domains_.volume[d])].volume->scatters();
        choice.walked = photons.walked;
        choices_.push_back(std::move(choice));
        media_.push_back(std::move(photons));
        all.extend(box);
    }
    for (const auto& s : scene.desc().surfaces) all.extend(bounds(s.mesh));
    surfaceMaxRadius_ = float(kMaxRadiusFraction * (all.empty() ? 1.0 : all.diagonal()));
    for (const auto& light : scene.lights())
        if (auto focus = light->focus()) foci_.push_back(*focus);
    storeUnwalked();
}

void PhotonIntegrator::storeUnwalked() {
    storedMedia_.assign(scene_.media().size(), 1);
    for (size_t d = 0; d < media_.size(); ++d)
        if (media_[d].walked)  // the eye path walks the domain: a pass stores no photons there
            for (int m : domains_.media[d]) storedMedia_[size_t(m)] = 0;
    tracing_ =
        hasDielectric(scene_) || std::any_of(media_.begin(), media_.end(), [](const auto& m) { return !m.walked; });
    walksAny_ = std::any_of(media_.begin(), media_.end(), [](const auto& m) { return m.walked; });
}

PhotonIntegrator::~PhotonIntegrator() = default;

IntegratorStats PhotonIntegrator::stats() const {
    IntegratorStats out;
    out.biased = tracing_;
    char line[512];
    for (const DomainChoice& c : choices_) {
        if (!c.measured) continue;
        std::string names;
        for (int m : c.media) names += (names.empty() ? "" : "+") + scene_.media()[size_t(m)].name;
        const std::string pays = c.walksPayFrom ? "pay from " + std::to_string(c.walksPayFrom) + " passes"
                                                : "do not pay within 65536 passes";
        std::snprintf(line, sizeof line,
                      "photons: %s %s: predicted relative MSE at %llu passes %.3g with photons, %.3g walked (%d of the "
                      "pilot's %d probes met it); walks %s",
                      names.c_str(), c.walked ? "walked" : "photons", (unsigned long long)c.passes, c.photonMse,
                      c.walkMse, c.probes, kPilotProbes, pays.c_str());
        out.lines.push_back(line);
    }
    if (!tracing_) {
        out.lines.push_back(
            "photons: none traced: every medium is walked and no surface is a dielectric, so paths carry all the "
            "light, as in volpath");
    } else {
        out.tracingSeconds = stats_.tracingSeconds;
        std::snprintf(line, sizeof line,
                      "photons: %llu paths traced, %llu stored in media, %llu on surfaces, %.1f MB of maps per pass",
                      (unsigned long long)stats_.paths, (unsigned long long)stats_.volumePhotons,
                      (unsigned long long)stats_.surfacePhotons, stats_.bytes / 1e6);
        out.lines.push_back(line);
    }
    if (stats_.pilotSeconds > 0) {
        std::snprintf(line, sizeof line, "time: photon pilot %.2f s (before the render)", stats_.pilotSeconds);
        out.lines.push_back(line);
    }
    return out;
}

std::vector<std::string> PhotonIntegrator::warnings() const {
    std::vector<std::string> lines;
    if (!hasDeltaLight(scene_)) return lines;
    std::vector<bool> named(scene_.volumes().size(), false);
    for (size_t d = 0; d < media_.size(); ++d) {
        const auto v = size_t(domains_.volume[d]);
        if (!media_[d].walked || !scene_.sealed(int(v)) || !scene_.volumes()[v].volume->scatters() || named[v])
            continue;
        named[v] = true;
        lines.push_back(scene_.volumes()[v].name +
                        " lies inside a dielectric boundary and is optically dense: photon mapping walks it as volpath "
                        "does, which cannot carry light from a point, spot or distant light through that boundary, so "
                        "that light is missing from it; an area light or the environment reaches it");
    }
    return lines;
}

double PhotonIntegrator::radiusScale(uint64_t pass, double alpha, int dim) {
    double shrink = 1;
    for (uint64_t i = 1; i <= pass; ++i) shrink *= (i + alpha) / (i + 1);
    return std::pow(shrink, 1.0 / dim);
}

void PhotonIntegrator::beginPass(uint64_t pass, const std::atomic<bool>* cancel) {
    if (!chosen_) choose(cancel);
    if (!chosen_ || !tracing_) return;
    markChainPixels();
    const auto start = std::chrono::steady_clock::now();
    loadPhotons(desc_.seed, pass, pass, 1, deadline_, cancel);
    stats_.tracingSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void PhotonIntegrator::loadPhotons(uint64_t seed, uint64_t pass, uint64_t radiusPass, double radiusFactor,
                                   std::optional<std::chrono::steady_clock::time_point> deadline,
                                   const std::atomic<bool>* cancel) {
    const auto maxStored = uint64_t(physicalMemory() / kBytesPerStoredPhoton);
    TracedPhotons traced = tracePhotons(
        scene_, source_,
        {desc_.photons, desc_.maxDepth, seed, pass, desc_.finalGather, maxStored, deadline, cancel, storedMedia_});
    // k-NN balls are three-dimensional kernels, beam discs and surface discs two-dimensional.
    auto scale = [&](int dim) {
        return radiusScale(radiusPass, desc_.alpha > 0 ? desc_.alpha : balancedAlpha(dim), dim);
    };
    volumeScale_ = radiusFactor * scale(desc_.estimate == PhotonEstimate::Beam ? 2 : 3);
    surfaceScale_ = scale(2);
    size_t bytes = 0;
    for (size_t m = 0; m < media_.size(); ++m) {
        MediumPhotons& mp = media_[m];
        mp.beams.reset();
        mp.map.reset();
        std::vector<Photon> photons;  // the domain's media's, in medium order
        for (int medium : domains_.media[m]) {
            auto& stored = traced.volume[size_t(medium)];
            if (photons.empty())
                photons = std::move(stored);
            else
                photons.insert(photons.end(), stored.begin(), stored.end());
        }
        stats_.volumePhotons += photons.size();
        if (photons.empty()) continue;
        mp.map = std::make_unique<PhotonMap>(std::move(photons));
        if (desc_.estimate == PhotonEstimate::Beam) {
            if (desc_.radius > 0)
                mp.map->setRadii(float(desc_.radius * volumeScale_));
            else
                mp.map->assignRadii(desc_.k, mp.maxRadius, float(volumeScale_));
            mp.beams = std::make_unique<PhotonDiscs>(mp.map->photons());
            bytes += mp.beams->bytes();
            const auto& photons = mp.map->photons();
            mp.largestRadius = 0;
            for (const Photon& photon : photons) mp.largestRadius = std::max(mp.largestRadius, double(photon.radius));
            mp.invBallVolume.resize(photons.size());
            tbb::parallel_for(tbb::blocked_range<size_t>(0, photons.size()), [&](const auto& range) {
                for (size_t i = range.begin(); i != range.end(); ++i) {
                    const double r = photons[i].radius;
                    const double volume = desc_.boundaryCorrection
                                              ? balls_[m].inside(glm::dvec3(photons[i].position), r)
                                              : 4 * kPi / 3 * r * r * r;
                    mp.invBallVolume[i] = float(1 / volume);
                }
            });
            bytes += mp.invBallVolume.size() * sizeof(float);
        }
        bytes += mp.map->bytes();
    }
    stats_.surfacePhotons += traced.surface.size();
    surface_ = traced.surface.empty() ? nullptr : std::make_unique<PhotonMap>(std::move(traced.surface));
    if (surface_) bytes += surface_->bytes();
    caustic_ = traced.caustic.empty() ? nullptr : std::make_unique<PhotonMap>(std::move(traced.caustic));
    if (caustic_) bytes += caustic_->bytes();
    stats_.paths += traced.paths;
    stats_.energy.add(traced.energy);
    stats_.bytes = std::max(stats_.bytes, bytes);
}

RGB PhotonIntegrator::radiance(const Ray& cameraRay, Rng& rng) const {
    if (!tracing_) return volpath_.radiance(cameraRay, rng);
    // The eye path first: the numbers it draws first are the ones stratified over the passes.
    const int pixel = chainPixel(cameraRay);
    const RGB L = eyePath(cameraRay, rng, -1, nullptr, pixel >= 0 ? EyeLight::AllButChains : EyeLight::All);
    return pixel >= 0 ? L + splitChainLight(pixel, rng) : L;
}

int PhotonIntegrator::domainOf(int v, uint32_t tet) const {
    const SceneVolume& volume = scene_.volumes()[v];
    return domains_.ofMedium[size_t(volume.regionMedium[size_t(volume.volume->mesh().region(tet))])];
}

RGB PhotonIntegrator::emittedAlong(int v, const ColumnProfile& column) const {
    const Volume& volume = *scene_.volumes()[v].volume;
    const auto& pieces = column.pieces();
    RGB L(0);
    for (size_t i = 0; i < pieces.size(); ++i) {
        const Medium& medium = volume.at(pieces[i].tet);
        if (!(maxComponent(medium.params.emission) > 0)) continue;
        const double piece = (i + 1 < pieces.size() ? pieces[i + 1].columnIn : column.total()) - pieces[i].columnIn;
        L += emittedOver(medium, pieces[i].depthIn, piece);
    }
    return L;
}

RGB PhotonIntegrator::emittedOver(const Medium& medium, const RGB& depthIn, double column) {
    // The integral of emission * density * transmittance over the piece is
    // emission * tr(piece start) * (1 - tr(piece)) / sigma_t.
    const RGB trIn = exp(-depthIn);
    RGB L;
    for (int c = 0; c < 3; ++c) {
        const double sigma = medium.sigmaT[c];
        L[c] = medium.params.emission[c] * trIn[c] * (sigma > 0 ? -std::expm1(-sigma * column) / sigma : column);
    }
    return L;
}

RGB PhotonIntegrator::scatteredAlong(int v, const Ray& ray, const ColumnProfile& column, Rng& rng) const {
    if (!scene_.volumes()[v].volume->scatters() || column.pieces().empty()) return RGB(0);
    if (desc_.estimate == PhotonEstimate::KnnMarch) return marchKnn(v, ray, column, rng);
    return directAlong(v, ray, column, rng) + beamEstimate(v, ray, column);
}

RGB PhotonIntegrator::marchKnn(int v, const Ray& ray, const ColumnProfile& column, Rng& rng) const {
    const Volume& volume = *scene_.volumes()[v].volume;
    const double u = rng.uniform();
    RGB L(0);
    // Each exact piece is split into equal steps no longer than the step size, one jittered
    // sample per step: the parity baseline's march, without its boundary error.
    for (const ColumnProfile::Piece& piece : column.pieces()) {
        const RGB sigmaS = volume.at(piece.tet).params.sigmaS;
        if (isBlack(sigmaS)) continue;
        const int n = std::max(1, int(std::ceil((piece.tOut - piece.tIn) / desc_.stepSize)));
        const double h = (piece.tOut - piece.tIn) / n;
        for (int i = 0; i < n; ++i) {
            const double t = piece.tIn + (i + u) * h;
            const glm::dvec3 p = ray.at(t);
            const RGB scattered =
                sigmaS * volume.density(piece.tet, p) * directInMedium(scene_, v, p, ray.d, piece.tet, rng) +
                knnEstimate(v, piece.tet, p, ray.d);
            L += column.transmittance(t) * h * scattered;
        }
    }
    return L;
}

double PhotonIntegrator::gather(const PhotonMap& map, const glm::dvec3& p, double scale, float maxRadius,
                                std::vector<Neighbour>& near) const {
    if (desc_.radius > 0) {
        const double r = desc_.radius * scale;
        map.withinRadius(glm::vec3(p), float(r), near);
        return r;
    }
    map.knn(glm::vec3(p), desc_.k, near, maxRadius * maxRadius);
    // Fewer than k within reach: the ball is the largest allowed.
    return scale * (near.size() == size_t(desc_.k) ? std::sqrt(double(near.back().distance2)) : double(maxRadius));
}

RGB PhotonIntegrator::knnEstimate(int v, uint32_t tet, const glm::dvec3& p, const glm::dvec3& d) const {
    const int m = domainOf(v, tet);
    const MediumPhotons& mp = media_[m];
    if (!mp.map) return RGB(0);
    thread_local std::vector<Neighbour> near;
    const double r = gather(*mp.map, p, volumeScale_, mp.maxRadius, near);
    const HenyeyGreenstein& phase = scene_.volumes()[v].volume->at(tet).phase;
    const auto& photons = mp.map->photons();
    RGB sum(0);
    for (const Neighbour& n : near) {
        if (n.distance2 > r * r) break;  // nearest first
        const Photon& photon = photons[n.index];
        // Light travelled along the photon's direction and leaves towards the eye (-d).
        sum += RGB(photon.power) * phase.eval(-glm::dot(glm::dvec3(unpackDirection(photon.direction)), d));
    }
    if (isBlack(sum)) return sum;
    const double volume = desc_.boundaryCorrection ? balls_[m].inside(p, r) : 4 * kPi / 3 * r * r * r;
    return sum / volume;
}

RGB PhotonIntegrator::beamEstimate(int v, const Ray& ray, const ColumnProfile& column) const {
    const auto& pieces = column.pieces();
    RGB L(0);
    // Each run of pieces in one domain sees that domain's photons only. Each photon's ball
    // kernel is integrated along the run: the transmittance integrated over the ball's chord
    // within [begin, end], over the ball's volume (inside its domain, with boundary correction).
    // Unlike the disc kernel 1 / (pi r^2), which assumes the whole chord lies in the medium, this
    // stays right where the ball reaches past the run's ends, however large the radius, and
    // where the transmittance changes within the ball.
    for (size_t first = 0, last; first < pieces.size(); first = last) {
        const int m = domainOf(v, pieces[first].tet);
        for (last = first + 1; last < pieces.size() && domainOf(v, pieces[last].tet) == m;) ++last;
        const MediumPhotons& mp = media_[m];
        if (!mp.beams) continue;
        const HenyeyGreenstein& phase = scene_.volumes()[v].volume->at(pieces[first].tet).phase;
        const auto& photons = mp.map->photons();
        const double begin = pieces[first].tIn, end = pieces[last - 1].tOut;
        mp.beams->query(
            ray.o, ray.d, begin - mp.largestRadius, end + mp.largestRadius,
            [&](uint32_t i, double t, double distance2) {
                const Photon& photon = photons[i];
                const double half = std::sqrt(std::max(0.0, double(photon.radius) * photon.radius - distance2));
                const double a = std::max(begin, t - half), b = std::min(end, t + half);
                if (b <= a) return;
                const double f = phase.eval(-glm::dot(glm::dvec3(unpackDirection(photon.direction)), ray.d));
                L += column.transmitted(a, b) * RGB(photon.power) * (f * mp.invBallVolume[i]);
            });
    }
    return L;
}

RGB PhotonIntegrator::directAlong(int v, const Ray& ray, const ColumnProfile& column, Rng& rng) const {
    if (scene_.lights().empty() || scene_.sealed(v)) return RGB(0);
    const Volume& volume = *scene_.volumes()[v].volume;
    // The distance follows one channel's transmittance, truncated to the stretch; the channels
    // with extinction share the sample by one-sample MIS, so no channel's weight blows up.
    const RGB depth = column.depth();
    int channels[3], count = 0;
    for (int c = 0; c < 3; ++c)
        if (depth[c] > 0) channels[count++] = c;
    if (count == 0) return RGB(0);
    // The focused lights whose cones the stretch passes through.
    constexpr int kMaxFoci = 8;
    std::optional<Equiangular> towards[kMaxFoci];
    int foci = 0;
    for (const LightFocus& focus : foci_) {
        if (foci == kMaxFoci) break;
        auto span = std::make_optional(std::make_pair(column.begin(), column.end()));
        if (focus.cone) span = focus.cone->clip(ray, span->first, span->second);
        if (span) towards[foci++].emplace(ray.o, ray.d, focus.centre, span->first, span->second);
    }
    const RGB trEnd = exp(-depth);
    const double u = rng.uniform(), share = foci ? 0.5 : 1;
    std::optional<ColumnProfile::Event> event;
    if (u < share) {
        const int hero = channels[std::min(count - 1, int(u / share * count))];
        event = column.atDepth(hero, -std::log1p(-rng.uniform() * (1 - trEnd[hero])));
    } else {
        event = column.at(towards[std::min(foci - 1, int((u - share) / (1 - share) * foci))]->sample(rng.uniform()));
    }
    if (!event) return RGB(0);
    const Medium& medium = volume.at(event->tet);
    const RGB tr = column.transmittance(event->t);
    double pdf = 0;  // per unit column: the mean over the channels of sigma_t tr / (1 - tr(end))
    for (int i = 0; i < count; ++i) {
        const int c = channels[i];
        pdf += medium.sigmaT[c] * tr[c] / (1 - trEnd[c]) / count;
    }
    const glm::dvec3 p = ray.at(event->t);
    if (foci) {
        // The equiangular pdf is per unit length: per unit column it is that over the density.
        const double density = volume.density(event->tet, p);
        if (!(density > 0)) return RGB(0);
        double focused = 0;
        for (int i = 0; i < foci; ++i) focused += towards[i]->pdf(event->t) / foci;
        pdf = share * pdf + (1 - share) * focused / density;
    }
    const RGB weight = tr * medium.params.sigmaS / pdf;
    return weight * directInMedium(scene_, v, p, ray.d, event->tet, rng);
}

RGB PhotonIntegrator::caustics(const PhotonMap* map, const Intersection& hit, const glm::dvec3& d,
                               const MaterialDesc& material) const {
    if (!map) return RGB(0);
    thread_local std::vector<Neighbour> near;
    const double r = gather(*map, hit.p, surfaceScale_, surfaceMaxRadius_, near);
    const double side = glm::dot(d, hit.n);
    RGB sum(0);
    for (const Neighbour& n : near) {
        if (n.distance2 > r * r) break;
        const Photon& photon = map->photons()[n.index];
        // Only photons that arrived on the side the eye sees.
        if (glm::dot(glm::dvec3(unpackDirection(photon.direction)), hit.n) * side <= 0) continue;
        // Cone filter (Jensen 1996): weight 1 - dist / r, normalised by pi r^2 / 3.
        sum += RGB(photon.power) * (1 - std::sqrt(double(n.distance2)) / r);
    }
    return material.reflectance / kPi * sum * (3 / (kPi * r * r));
}

}  // namespace tetglow
