// One number written by a printf pattern, for the command's reports and progress lines.
#pragma once
#include <cstdio>
#include <string>

namespace tetglow::cli {

inline std::string numberText(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace tetglow::cli
