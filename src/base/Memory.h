// Sizes the user chooses (pixels, photons, triangles) are checked against the memory tetglow may
// use before they are allocated, so that a request too large is a clear error and not
// std::bad_alloc, an out-of-memory kill, or minutes of work that end in one.
#pragma once
#include <string>

namespace tetglow {

// The machine's physical memory in bytes.
double physicalMemory();

// The memory tetglow may use in bytes: $TETGLOW_MEMORY_LIMIT when set (bytes, or a number with a
// K, M, G or T suffix, powers of 1024), else the machine's physical memory. A limit that is not
// such a number, or is above the physical memory, is an InputError naming the variable.
double memoryLimit();

// What memoryLimit() is, for messages: "this machine's 7.8 GB of memory" or "the 1.07 GB of
// TETGLOW_MEMORY_LIMIT".
std::string memoryLimitText();

// "12.3 GB"
std::string gigabytes(double bytes);

// InputError "<what> needs about 12.3 GB, more than this machine's 7.8 GB of memory" when
// `bytes` exceed memoryLimit().
void checkMemory(double bytes, const std::string& what);

}  // namespace tetglow
