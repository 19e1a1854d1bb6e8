#include "cli/BoundaryReport.h"

#include "cli/NumberText.h"

namespace tetglow::cli {

namespace {

std::string region(double offset) { return offset > 0 ? numberText("shell %.0e diag.", offset) : "bounding box"; }

std::string rate(size_t errors, size_t n) {
    if (errors == 0) return "0";
    return numberText("%.3g%%", 100.0 * double(errors) / double(n)) + " (" + std::to_string(errors) + ")";
}

// Mean over the regions of each method's time per query (every region has as many points).
std::vector<double> meanTimes(const std::vector<ClassificationRow>& rows) {
    std::vector<double> mean(rows.front().methods.size(), 0.0);
    for (const auto& row : rows)
        for (size_t k = 0; k < mean.size(); ++k) mean[k] += row.methods[k].secondsPerQuery / double(rows.size());
    return mean;
}

std::string csvQuoted(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

}  // namespace

void printText(std::FILE* out, const MediumReport& r) {
    const auto& rows = r.comparison.classification;
    const auto& chords = r.comparison.chords;
    std::fprintf(out, "== %s: %zu tets, %zu boundary triangles, bounding-box diagonal %.4g ==\n\n", r.name.c_str(),
                 r.tets, r.triangles, r.diagonal);

    std::fprintf(out, "Inside/outside: error rate against the tets (exact), %zu points per region\n",
                 rows.front().scored);
    std::fprintf(out, "%-22s %-9s", "region", "inside");
    for (const auto& m : rows.front().methods) std::fprintf(out, " %-18s", m.method.c_str());
    std::fprintf(out, "\n");
    for (const auto& row : rows) {
        std::fprintf(out, "%-22s %-9s", region(row.offset).c_str(),
                     numberText("%.1f%%", 100.0 * double(row.inside) / double(row.scored)).c_str());
        for (const auto& m : row.methods) std::fprintf(out, " %-18s", rate(m.errors, row.scored).c_str());
        std::fprintf(out, "\n");
    }

    std::fprintf(out, "\nTime per query, ns (one thread; tets: located from the start grid, no hint)\n%-22s", "region");
    for (const auto& m : rows.front().methods) std::fprintf(out, " %-10s", m.method.c_str());
    std::fprintf(out, "\n");
    for (const auto& row : rows) {
        std::fprintf(out, "%-22s", region(row.offset).c_str());
        for (const auto& m : row.methods) std::fprintf(out, " %-10.0f", 1e9 * m.secondsPerQuery);
        std::fprintf(out, "\n");
    }
    const std::vector<double> mean = meanTimes(rows);
    std::fprintf(out, "%-22s", "mean");
    for (double t : mean) std::fprintf(out, " %-10.0f", 1e9 * t);
    std::fprintf(out, "\n%-22s", "relative to tets");
    for (double t : mean) std::fprintf(out, " %-10.3g", t / mean.front());
    std::fprintf(out, "\n\n");

    std::fprintf(
        out,
        "Optical depth along %zu random lines across the bounding box: %zu cross the medium, mean exact depth %.4g\n",
        chords.lines, chords.crossing, r.sigmaT * chords.meanLength);
    std::fprintf(out, "(sigma_t %.4g per unit: %s%s; the march: 1 parity ray per step)\n", r.sigmaT,
                 r.sigmaSource.c_str(), r.homogeneous ? "" : ", at density 1: the per-vertex density is left out");
    std::fprintf(out, "%-14s %-10s %-12s %-12s %-12s %-10s %-10s %s\n", "method", "step", "mean |err|", "max |err|",
                 "bias", "relative", "us/ray", "x tets");
    const double tetTime = chords.methods.front().secondsPerRay;
    for (const auto& m : chords.methods)
        std::fprintf(out, "%-14s %-10s %-12.4g %-12.4g %-12.4g %-10.4g %-10.3g %.3g\n", m.method.c_str(),
                     m.step > 0 ? numberText("%.4g", m.step).c_str() : "-", r.sigmaT * m.meanAbsError,
                     r.sigmaT * m.maxAbsError, r.sigmaT * m.meanError, m.relativeError, 1e6 * m.secondsPerRay,
                     m.secondsPerRay / tetTime);
    std::fprintf(out, "\n");
}

nlohmann::json toJson(const MediumReport& r) {
    nlohmann::json classification = nlohmann::json::array();
    for (const auto& row : r.comparison.classification) {
        nlohmann::json methods = nlohmann::json::array();
        for (const auto& m : row.methods)
            methods.push_back({{"method", m.method},
                               {"errors", m.errors},
                               {"error_rate", double(m.errors) / double(row.scored)},
                               {"ns_per_query", 1e9 * m.secondsPerQuery}});
        classification.push_back({{"region", row.offset > 0 ? "shell" : "box"},
                                  {"offset_diagonals", row.offset},
                                  {"points", row.scored},
                                  {"inside", row.inside},
                                  {"methods", methods}});
    }
    nlohmann::json depth = nlohmann::json::array();
    for (const auto& m : r.comparison.chords.methods)
        depth.push_back({{"method", m.method},
                         {"step", m.step},
                         {"mean_abs_error", r.sigmaT * m.meanAbsError},
                         {"max_abs_error", r.sigmaT * m.maxAbsError},
                         {"bias", r.sigmaT * m.meanError},
                         {"relative_error", m.relativeError},
                         {"us_per_ray", 1e6 * m.secondsPerRay}});
    const auto& chords = r.comparison.chords;
    return {{"name", r.name},
            {"tets", r.tets},
            {"triangles", r.triangles},
            {"diagonal", r.diagonal},
            {"classification", classification},
            {"optical_depth",
             {{"sigma_t", r.sigmaT},
              {"homogeneous", r.homogeneous},
              {"lines", chords.lines},
              {"crossing", chords.crossing},
              {"mean_depth", r.sigmaT * chords.meanLength},
              {"methods", depth}}}};
}

std::string csvHeader() {
    return "medium,test,offset_diagonals,step,method,queries,errors,error_rate,mean_abs_error,max_abs_error,bias,"
           "relative_error,"
           "seconds_per_query\n";
}

std::string csvRows(const MediumReport& r) {
    std::string csv;
    const std::string name = csvQuoted(r.name);
    auto number = [](double v) { return numberText("%.9g", v); };
    for (const auto& row : r.comparison.classification)
        for (const auto& m : row.methods)
            csv += name + ",classification," + number(row.offset) + ",," + m.method + "," + std::to_string(row.scored) +
                   "," + std::to_string(m.errors) + "," + number(double(m.errors) / double(row.scored)) + ",,,,," +
                   number(m.secondsPerQuery) + "\n";
    for (const auto& m : r.comparison.chords.methods)
        csv += name + ",optical_depth,," + number(m.step) + "," + m.method + "," +
               std::to_string(r.comparison.chords.lines) + ",,," + number(r.sigmaT * m.meanAbsError) + "," +
               number(r.sigmaT * m.maxAbsError) + "," + number(r.sigmaT * m.meanError) + "," + number(m.relativeError) +
               "," + number(m.secondsPerRay) + "\n";
    return csv;
}

}  // namespace tetglow::cli
