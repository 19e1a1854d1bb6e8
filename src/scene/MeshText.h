// What the text mesh readers (OBJ, OFF) share: where a line is, for messages, and how a number reads.
#pragma once
#include <cstdlib>
#include <string>

namespace tetglow {

// "path:line: ", the start of a message about that line.
inline std::string atLine(const std::string& path, size_t line) { return path + ":" + std::to_string(line) + ": "; }

// Parses one OBJ/OFF number; "nan" and "inf" parse so that validation can name them.
inline bool parseNumber(const std::string& tok, double& out) {
    if (tok.empty()) return false;
    char* end = nullptr;
    out = std::strtod(tok.c_str(), &end);
    return end && *end == '\0';
}

}  // namespace tetglow
