#include "render/TileError.h"

#include <algorithm>

namespace tetglow {
namespace {

Image crop(const Image& image, int x0, int y0, int width, int height) {
    Image tile(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) tile.at(x, y) = image.at(x0 + x, y0 + y);
    return tile;
}

}  // namespace

std::vector<double> tileRelMse(const Image& test, const Image& reference, int size) {
    compare(test, reference);  // the whole images' checks, with their messages
    std::vector<double> errors;
    for (int y = 0; y < test.height; y += size)
        for (int x = 0; x < test.width; x += size) {
            const int w = std::min(size, test.width - x), h = std::min(size, test.height - y);
            errors.push_back(compare(crop(test, x, y, w, h), crop(reference, x, y, w, h)).relMse);
        }
    return errors;
}

}  // namespace tetglow
