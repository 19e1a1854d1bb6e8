// `tetglow compare-boundary`'s results as text tables, one JSON object, or CSV rows.
#pragma once
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "evidence/BoundaryComparison.h"

namespace tetglow::cli {

// One medium and what was measured on it.
struct MediumReport {
    std::string name;
    size_t tets = 0, triangles = 0;
    double diagonal = 0;
    double sigmaT = 1;  // per unit: optical depth = sigmaT * length
    std::string sigmaSource = "a mesh alone: optical depth = length";
    bool homogeneous = true;  // false: a per-vertex density, left out of the optical depth
    BoundaryComparison comparison;
};

void printText(std::FILE* out, const MediumReport& report);
nlohmann::json toJson(const MediumReport& report);
// The CSV header line, and the rows of one medium.
std::string csvHeader();
std::string csvRows(const MediumReport& report);

}  // namespace tetglow::cli
