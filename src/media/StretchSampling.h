// A point for next-event estimation on every stretch through a homogeneous region, not only where
// the free flight interacts: the free-flight pdf conditioned on an interaction before the stretch
// ends. In an optically thin part most flights pass through; each still brings back direct light
// (as Cycles' volume segments do).
#pragma once
#include <algorithm>
#include <cmath>

#include "base/Spectrum.h"

namespace tetglow {

// The coefficient c per channel for which c * exp(-sigma x) is the conditioned pdf at x in
// [0, length): sigma / (1 - exp(-sigma length)), 1 / length where the stretch is optically empty.
inline double interactionWithin(double sigma, double length) {
    const double depth = sigma * length;
    return depth > 1e-12 ? sigma / -std::expm1(-depth) : 1 / length;
}
inline RGB interactionWithin(const RGB& sigma, double length) {
    // As exp(RGB): a channel equal to an earlier one takes its value.
    const double x = interactionWithin(sigma.x, length),
                 y = sigma.y == sigma.x ? x : interactionWithin(sigma.y, length);
    return {x, y, sigma.z == sigma.x ? x : sigma.z == sigma.y ? y : interactionWithin(sigma.z, length)};
}

// The distance in [0, length) with that pdf for extinction sigma.
inline double distanceWithin(double sigma, double length, double u) {
    const double depth = sigma * length;
    return depth > 1e-12 ? std::min(-std::log1p(u * std::expm1(-depth)) / sigma, length) : u * length;
}

}  // namespace tetglow
