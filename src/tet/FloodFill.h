// Connected components by flood fill, for the graphs of a mesh's elements (a surface's triangles
// across their edges, a tet mesh's tets across their faces).
#pragma once
#include <cstdint>
#include <vector>

namespace tetglow {

constexpr uint32_t kUnreached = UINT32_MAX;

// The component of each of `count` elements, numbered in the order they are found: each
// unreached element, in index order, starts one (begin(id) is called first), which grows depth
// first. expand(t, id, reach) looks at element t's neighbours and calls reach(n) for each one
// joined to t; reach returns false, and does nothing, for one already reached.
template <class Begin, class Expand>
std::vector<uint32_t> floodFill(size_t count, Begin&& begin, Expand&& expand) {
    std::vector<uint32_t> component(count, kUnreached);
    std::vector<uint32_t> stack;
    uint32_t components = 0;
    for (uint32_t start = 0; start < count; ++start) {
        if (component[start] != kUnreached) continue;
        const uint32_t id = components++;
        begin(id);
        component[start] = id;
        stack.push_back(start);
        while (!stack.empty()) {
            const uint32_t t = stack.back();
            stack.pop_back();
            expand(t, id, [&](uint32_t n) {
                if (component[n] != kUnreached) return false;
                component[n] = id;
                stack.push_back(n);
                return true;
            });
        }
    }
    return component;
}

}  // namespace tetglow
