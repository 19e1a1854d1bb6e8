// How evenly the error lies over an image: compare()'s relative MSE per tile of pixels, the unit
// adaptive sampling plans its passes by (render/AdaptiveSampling.h).
#pragma once
#include <vector>

#include "render/Image.h"

namespace tetglow {

// compare(test, reference).relMse of each size x size tile, row-major from the top-left, the last
// row and column of tiles cut by the image's edge. InputError as compare's.
std::vector<double> tileRelMse(const Image& test, const Image& reference, int size);

}  // namespace tetglow
