#include "cli/ReferenceLog.h"

#include <cstdio>
#include <filesystem>

#include "base/Error.h"
#include "render/ImageIO.h"

namespace tetglow::cli {

ReferenceLog::ReferenceLog(const std::string& referencePath, const std::string& csvPath, int width, int height)
    : reference_(readExr(referencePath)), csvPath_(csvPath) {
    if (reference_.width != width || reference_.height != height)
        throw InputError(referencePath + ": the reference is " + std::to_string(reference_.width) + "x" +
                         std::to_string(reference_.height) + ", the render " + std::to_string(width) + "x" +
                         std::to_string(height));
    csv_.open(csvPath);
    if (!csv_) throw InputError(csvPath + ": cannot write");
    csv_.precision(9);
    csv_ << "pass,seconds,noise_estimate,rel_mse_vs_reference\n";
}

void ReferenceLog::pass(const PassReport& r) {
    const double error = compare(r.film.image(), reference_).relMse;
    std::fprintf(stderr, "pass %d, %.2f s: relative MSE %.4g against the reference\n", r.passes, r.seconds, error);
    csv_ << r.passes << ',' << r.seconds << ',';
    if (r.noise) csv_ << *r.noise;
    csv_ << ',' << error << '\n' << std::flush;
    if (!csv_) throw InputError(csvPath_ + ": cannot write");
}

std::string errorLogPath(const std::string& exrPath) {
    return std::filesystem::path(exrPath).replace_extension(".csv").string();
}

}  // namespace tetglow::cli
