// A linear RGB image, and how far one image is from another.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace tetglow {

struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;  // linear RGB, row-major from the top-left

    Image() = default;
    Image(int w, int h);  // zero-filled

    glm::vec3& at(int x, int y) { return pixels[index(x, y)]; }
    const glm::vec3& at(int x, int y) const { return pixels[index(x, y)]; }

private:
    size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
};

// Added to b^2 in relative errors, so that black pixels do not dominate.
inline constexpr double kRelMseFloor = 0.01;

// Errors of a test image against a reference, over all pixels and channels whose test pixel is finite.
struct ImageDiff {
    double rmse = 0;         // sqrt(mean of (a-b)^2)
    double relMse = 0;       // mean of (a-b)^2 / (b^2 + 0.01), b = reference: error relative to brightness
    double mae = 0;          // mean of |a-b|
    double maxError = 0;     // largest per-pixel error: max over channels of |a-b|
    int maxX = 0, maxY = 0;  // where it is (the first such pixel in row-major order)
    size_t nonFinite = 0;    // test pixels with NaN or Inf in any channel: excluded from the above, counted here
};

// InputError if the sizes differ or the reference has a NaN or Inf. With no finite test pixel the means are 0.
ImageDiff compare(const Image& test, const Image& reference);

}  // namespace tetglow
