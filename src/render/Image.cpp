#include "render/Image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tet/TriangleMesh.h"

namespace tetglow {
namespace {

bool isFinite(const glm::vec3& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

std::string sizeText(const Image& image) { return std::to_string(image.width) + "x" + std::to_string(image.height); }

void checkComparable(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height)
        throw InputError("image sizes differ: " + sizeText(test) + " (test) and " + sizeText(reference) +
                         " (reference)");
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            if (!isFinite(reference.at(x, y)))
                throw InputError("reference image has NaN or Inf at pixel (" + std::to_string(x) + ", " +
                                 std::to_string(y) + ")");
}

}  // namespace

Image::Image(int w, int h) : width(w), height(h) {
    if (w < 0 || h < 0) throw std::invalid_argument("negative image size");
    pixels.assign(static_cast<size_t>(w) * h, glm::vec3(0));
}

ImageDiff compare(const Image& test, const Image& reference) {
    checkComparable(test, reference);
    ImageDiff d;
    double sumSq = 0, sumRel = 0, sumAbs = 0;
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
            const glm::vec3& a = test.at(x, y);
            if (!isFinite(a)) {
                ++d.nonFinite;
                continue;
            }
            double pixelError = 0;
            for (int c = 0; c < 3; ++c) {
                // In double: float differences of large values would overflow when squared.
                const double b = reference.at(x, y)[c], e = a[c] - b;
                sumSq += e * e;
                sumRel += e * e / (b * b + kRelMseFloor);
                sumAbs += std::abs(e);
                pixelError = std::max(pixelError, std::abs(e));
            }
            if (pixelError > d.maxError) {
                d.maxError = pixelError;
                d.maxX = x;
                d.maxY = y;
            }
        }
    const size_t samples = 3 * (test.pixels.size() - d.nonFinite);
    if (samples == 0) return d;
    d.rmse = std::sqrt(sumSq / samples);
    d.relMse = sumRel / samples;
    d.mae = sumAbs / samples;
    return d;
}

}  // namespace tetglow
