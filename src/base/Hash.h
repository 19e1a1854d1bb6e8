// FNV-1a, 64 bits: the tet cache's key (mesh + switches) and the checksum of each entry.
#pragma once
#include <cstddef>
#include <cstdint>

namespace tetglow {

inline constexpr uint64_t kFnvOffset = 14695981039346656037ull;

inline uint64_t fnv1a(uint64_t h, const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

}  // namespace tetglow
