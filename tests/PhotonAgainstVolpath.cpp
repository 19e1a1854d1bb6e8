#include "PhotonAgainstVolpath.h"

#include <cmath>
#include <cstdio>

#include "render/IntegratorFactory.h"
#include "render/Renderer.h"

namespace tetglow::test {

Image renderImage(const Scene& scene, IntegratorType integrator, uint64_t seed, int spp, uint64_t photons,
                  int threads) {
    IntegratorDesc desc;
    desc.type = integrator;
    desc.photons = photons;
    desc.seed = seed;
    auto made = makeIntegrator(scene, desc);
    RenderOptions options;
    options.spp = spp;
    options.seed = seed;
    options.threads = threads;
    return render(scene, *made, options).image;
}

double imageMean(const Image& image) {
    double sum = 0;
    for (const auto& p : image.pixels) sum += average(RGB(p));
    return sum / double(image.pixels.size());
}

double spread(const Image& a, const Image& b) {
    double sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double d = average(RGB(a.pixels[i])) - average(RGB(b.pixels[i]));
        sum += d * d;
    }
    return sum / double(a.pixels.size());
}

PhotonAgainstVolpath photonAgainstVolpath(const Scene& scene, int referenceSpp, int spp, uint64_t photons) {
    PhotonAgainstVolpath c;
    c.reference = imageMean(renderImage(scene, IntegratorType::VolPath, 1, referenceSpp, photons));
    const Image photonA = renderImage(scene, IntegratorType::Photon, 2, spp, photons),
                photonB = renderImage(scene, IntegratorType::Photon, 3, spp, photons);
    const Image volpathA = renderImage(scene, IntegratorType::VolPath, 4, spp, photons),
                volpathB = renderImage(scene, IntegratorType::VolPath, 5, spp, photons);
    c.photonMean = 0.5 * (imageMean(photonA) + imageMean(photonB));
    c.photonSpread = spread(photonA, photonB);
    c.volpathSpread = spread(volpathA, volpathB);
    // The spreads give the per-pixel variances; the reference's is volpath's at referenceSpp.
    const double pixels = double(photonA.pixels.size());
    c.sigma = std::sqrt(c.photonSpread / 4 / pixels + c.volpathSpread / 2 * spp / referenceSpp / pixels);
    std::printf("image mean: volpath %.5f, photon %.5f; spread of two renders: volpath %.4g, photon %.4g\n",
                c.reference, c.photonMean, c.volpathSpread, c.photonSpread);
    return c;
}

}  // namespace tetglow::test
