// `render --reference REF.exr`: after each pass, the image's error against a reference (printed,
// and a CSV row: pass, seconds, noise estimate, relative MSE against the reference), so that any
// render is a chart of accuracy against time.
#pragma once
#include <fstream>
#include <string>

#include "render/Image.h"
#include "render/Renderer.h"

namespace tetglow::cli {

class ReferenceLog {
public:
    // InputError naming the file if the reference cannot be read or its size is not width x height.
    ReferenceLog(const std::string& referencePath, const std::string& csvPath, int width, int height);
    void pass(const PassReport& report);

private:
    Image reference_;
    std::string csvPath_;
    std::ofstream csv_;
};

// "out/x.exr" -> "out/x.csv".
std::string errorLogPath(const std::string& exrPath);

}  // namespace tetglow::cli
