// Sizes the user chooses (pixels, photons) are checked against the machine before they are
// allocated, so that a request too large is a clear error and not std::bad_alloc.
#pragma once
#include <string>

namespace tetglow {

// The machine's physical memory in bytes.
double physicalMemory();

// InputError "<what> needs about 12.3 GB, more than this machine's 7.8 GB of memory" when
// `bytes` exceed the physical memory.
void checkMemory(double bytes, const std::string& what);

}  // namespace tetglow
