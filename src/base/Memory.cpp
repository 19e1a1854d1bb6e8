#include "base/Memory.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/Error.h"

namespace tetglow {
namespace {

constexpr const char* kLimitVariable = "TETGLOW_MEMORY_LIMIT";

// $TETGLOW_MEMORY_LIMIT in bytes, or 0 when it is not set.
double limitFromEnvironment() {
    const char* text = std::getenv(kLimitVariable);
    if (!text || !*text) return 0;
    char* end = nullptr;
    double bytes = std::strtod(text, &end);
    const std::string unit = end;
    const std::string units = "KMGT";
    if (unit.size() == 1 && units.find(unit[0]) != std::string::npos)
        bytes *= std::pow(1024.0, double(units.find(unit[0]) + 1));
    else if (!unit.empty())
        bytes = -1;
    if (!(bytes > 0) || !std::isfinite(bytes))
        throw InputError(std::string(kLimitVariable) + " '" + text +
                         "': expected a number of bytes > 0, with an optional K, M, G or T");
    if (bytes > physicalMemory())
        throw InputError(std::string(kLimitVariable) + " '" + text + "' is more than this machine's " +
                         gigabytes(physicalMemory()) + " of memory");
    return bytes;
}

}  // namespace

double physicalMemory() { return double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE)); }

double memoryLimit() {
    const double set = limitFromEnvironment();
    return set > 0 ? set : physicalMemory();
}

std::string memoryLimitText() {
    const double set = limitFromEnvironment();
    return set > 0 ? "the " + gigabytes(set) + " of " + kLimitVariable
                   : "this machine's " + gigabytes(physicalMemory()) + " of memory";
}

std::string gigabytes(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
    return text;
}

void checkMemory(double bytes, const std::string& what) {
    if (bytes <= memoryLimit()) return;
    throw InputError(what + " needs about " + gigabytes(bytes) + ", more than " + memoryLimitText());
}

}  // namespace tetglow
