// The pixel samples' generator: Owen-scrambled Sobol pairs are (0,k,2)-nets, uniform and
// independent across pairs and pixels, stratify an edge better than independent numbers, and
// leave the images' expectation as it was.
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"
#include "sampling/Sampling.h"
#include "sampling/Sobol.h"

namespace tetglow::test {
namespace {

// Dimensions 2j and 2j+1 of samples first .. first + 2^k - 1 of one pixel.
std::vector<std::pair<double, double>> pairOf(uint64_t seed, uint64_t pixel, uint32_t first, int k, int j) {
    std::vector<std::pair<double, double>> points;
    for (uint32_t i = first; i < first + (1u << k); ++i) {
        Rng rng = Rng::pixelSample(seed, pixel, i);
        for (int d = 0; d < 2 * j; ++d) rng.uniform();
        const double x = rng.uniform(), y = rng.uniform();
        points.emplace_back(x, y);
    }
    return points;
}

// Every elementary interval [a 2^-s, (a+1) 2^-s) x [b 2^-(k-s), (b+1) 2^-(k-s)) holds one point.
void expectNet(const std::vector<std::pair<double, double>>& points, int k) {
    for (int s = 0; s <= k; ++s) {
        std::vector<int> count(size_t(1) << k, 0);
        for (const auto& [x, y] : points) {
            ASSERT_GE(x, 0);
            ASSERT_LT(x, 1);
            ASSERT_GE(y, 0);
            ASSERT_LT(y, 1);
            ++count[(size_t(x * (1 << s)) << (k - s)) + size_t(y * (1 << (k - s)))];
        }
        for (size_t c = 0; c < count.size(); ++c)
            ASSERT_EQ(count[c], 1) << "split " << s << " of 2^" << k << ", interval " << c;
    }
}

TEST(Sampler, EveryPairOfEveryPixelIsANetForEveryPowerOfTwo) {
    for (uint64_t pixel : {0u, 1u, 77u, 123456u})
        for (int j = 0; j < int(Rng::kSobolDimensions / 2); ++j)
            for (int k = 0; k <= 10; ++k) {
                SCOPED_TRACE("pixel " + std::to_string(pixel) + ", pair " + std::to_string(j) + ", 2^" +
                             std::to_string(k));
                expectNet(pairOf(3, pixel, 0, k, j), k);
                // Passes rendered apart (a farm's ranges) start at multiples of 2^k: nets too.
                expectNet(pairOf(3, pixel, 5u << k, k, j), k);
            }
}

// The table of the second dimension, kept with its bits reversed for the scrambles, is Sobol's:
// the product of the index with Pascal's triangle mod 2, column by column, for every bit.
TEST(Sampler, SecondDimensionIsTheProductWithPascalsTriangle) {
    auto direct = [](uint32_t index) {
        uint32_t value = 0, column = 1u << 31;
        for (int i = 0; i < 32; ++i, column ^= column >> 1)
            if ((index >> i) & 1) value ^= column;
        return value;
    };
    uint64_t state = 12345;
    for (uint32_t i = 0; i < 4096; ++i) {
        const uint32_t index = i < 2048 ? i : uint32_t(mixBits(++state));
        ASSERT_EQ(reverseBits(reversedSobolDimension1(index)), direct(index)) << "index " << index;
    }
}

// Samples of one pixel and dimension, over many pixels: each number is uniform (a single
// sample's numbers are those of an independent generator), also past the Sobol dimensions.
TEST(Sampler, EachSampleIsUniformAndItsPairsIndependent) {
    constexpr int pixels = 100000, dims = int(Rng::kSobolDimensions) + 4;
    std::vector<double> sum(dims, 0), sum2(dims, 0);
    double cross = 0;  // an integrand of dimensions 1 and 2, of two different pairs
    for (int p = 0; p < pixels; ++p) {
        Rng rng = Rng::pixelSample(11, uint64_t(p), 5);
        std::vector<double> u(dims);
        for (int d = 0; d < dims; ++d) {
            u[d] = rng.uniform();
            sum[d] += u[d];
            sum2[d] += u[d] * u[d];
        }
        cross += u[1] + u[2] < 1;
    }
    // Uniform on [0, 1): mean 1/2 (standard error 1/sqrt(12 n)), second moment 1/3 (2/sqrt(45 n)).
    for (int d = 0; d < dims; ++d) {
        EXPECT_NEAR(sum[d] / pixels, 0.5, 4 / std::sqrt(12.0 * pixels)) << "dimension " << d;
        EXPECT_NEAR(sum2[d] / pixels, 1.0 / 3, 8 / std::sqrt(45.0 * pixels)) << "dimension " << d;
    }
    EXPECT_NEAR(cross / pixels, 0.5, 4 * 0.5 / std::sqrt(double(pixels)));
}

// The area of the part of the unit square where side(q) > 0, side affine: the square clipped
// by the half-plane (Sutherland-Hodgman), then the shoelace formula.
template <class Side>
double areaBelow(Side&& side) {
    const glm::dvec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<glm::dvec2> clipped;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 a = square[i], b = square[(i + 1) % 4];
        const double sa = side(a), sb = side(b);
        if (sa > 0) clipped.push_back(a);
        if ((sa > 0) != (sb > 0)) clipped.push_back(a + (b - a) * (sa / (sa - sb)));
    }
    double twice = 0;
    for (size_t i = 0; i < clipped.size(); ++i) {
        const glm::dvec2 a = clipped[i], b = clipped[(i + 1) % clipped.size()];
        twice += a.x * b.y - a.y * b.x;
    }
    return twice / 2;
}

// The fraction of a pixel below an edge, from n samples, in many pixels: the error of
// stratified points falls as n^-3/4, the independent ones' as n^-1/2.
TEST(Sampler, StratifiesAPixelEdgeBetterThanIndependentNumbers) {
    // Any line through the centre halves the square.
    EXPECT_NEAR(areaBelow([](const glm::dvec2& q) { return 0.3 * (q.x - 0.5) - 0.8 * (q.y - 0.5); }), 0.5, 1e-12);
    constexpr int pixels = 4000, n = 64;
    double sobolError2 = 0, independentError2 = 0;
    for (int p = 0; p < pixels; ++p) {
        // An edge through the pixel at a different angle and offset in each pixel.
        Rng edge(99, uint64_t(p));
        const double angle = 2 * kPi * edge.uniform(), offset = edge.uniform() - 0.5;
        const glm::dvec2 normal(std::cos(angle), std::sin(angle));
        auto side = [&](const glm::dvec2& q) { return offset - glm::dot(normal, q - glm::dvec2(0.5)); };
        auto below = [&](double x, double y) { return side({x, y}) > 0; };
        const double exact = areaBelow(side);
        double sobol = 0, independent = 0;
        for (int i = 0; i < n; ++i) {
            Rng s = Rng::pixelSample(1, uint64_t(p), uint32_t(i));
            const double sx = s.uniform(), sy = s.uniform();
            sobol += below(sx, sy);
            Rng r(1, uint64_t(p), uint64_t(i));
            const double rx = r.uniform(), ry = r.uniform();
            independent += below(rx, ry);
        }
        sobolError2 += std::pow(sobol / n - exact, 2);
        independentError2 += std::pow(independent / n - exact, 2);
    }
    const double ratio = independentError2 / sobolError2;
    std::printf("pixel edge, %d samples: variance %.3g (independent) / %.3g (Sobol) = %.1f\n", n,
                independentError2 / pixels, sobolError2 / pixels, ratio);
    // n^-1 against about n^-3/2: 8 at 64 samples; measured 11.3.
    EXPECT_GT(ratio, 5);
}

// The passes with independent numbers (the renderer before the Sobol sampler).
Image renderIndependent(const Scene& scene, Integrator& integrator, int spp, uint64_t seed) {
    const Camera& camera = scene.camera();
    Film film(camera.width(), camera.height());
    for (int pass = 0; pass < spp; ++pass) {
        integrator.beginPass(uint64_t(pass));
        for (int y = 0; y < camera.height(); ++y)
            for (int x = 0; x < camera.width(); ++x) {
                Rng rng(seed, uint64_t(y) * camera.width() + x, uint64_t(pass));
                const double jx = rng.uniform(), jy = rng.uniform();
                film.add(x, y, integrator.radiance(camera.generateRay(x + jx, y + jy), rng));
            }
    }
    return film.image();
}

// Volpath and the photon integrator: the per-pixel differences between the two samplers'
// images average to zero within their standard error (pixels are independent of each other).
TEST(Sampler, ImagesKeepTheirMean) {
    const Scene scene(glowingSphereUnderQuad(24));
    for (const IntegratorType type : {IntegratorType::VolPath, IntegratorType::Photon}) {
        SCOPED_TRACE(type == IntegratorType::VolPath ? "volpath" : "photon");
        IntegratorDesc integ;
        integ.type = type;
        integ.photons = 20000;
        integ.seed = 5;
        const auto integrator = makeIntegrator(scene, integ);
        RenderOptions options;
        options.spp = 16;
        options.seed = 5;
        const Image sobol = render(scene, *integrator, options).image;
        const Image independent = renderIndependent(scene, *integrator, options.spp, 6);
        for (int c = 0; c < 3; ++c) {
            double sum = 0, sum2 = 0;
            const size_t n = sobol.pixels.size();
            for (size_t i = 0; i < n; ++i) {
                const double d = double(sobol.pixels[i][c]) - independent.pixels[i][c];
                sum += d;
                sum2 += d * d;
            }
            const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
            EXPECT_NEAR(mean, 0, 4 * se) << "channel " << c;
        }
    }
}

}  // namespace
}  // namespace tetglow::test
