#include "base/Memory.h"

#include <unistd.h>

#include <cstdio>

#include "base/Error.h"

namespace tetglow {

double physicalMemory() { return double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE)); }

void checkMemory(double bytes, const std::string& what) {
    const double available = physicalMemory();
    if (bytes <= available) return;
    char text[128];
    std::snprintf(text, sizeof text, " needs about %.3g GB, more than this machine's %.3g GB of memory", bytes / 1e9,
                  available / 1e9);
    throw InputError(what + text);
}

}  // namespace tetglow
