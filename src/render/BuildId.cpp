#include "render/BuildId.h"

#include <elf.h>
#include <link.h>

#include <cstdio>

namespace tetglow {
namespace {

// The NT_GNU_BUILD_ID note of the first object dl_iterate_phdr lists: the executable itself.
int findBuildId(dl_phdr_info* info, size_t, void* data) {
    auto& id = *static_cast<std::string*>(data);
    for (int i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& segment = info->dlpi_phdr[i];
        if (segment.p_type != PT_NOTE) continue;
        const char* p = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
        const char* end = p + segment.p_memsz;
        auto aligned = [](size_t n) { return (n + 3) & ~size_t(3); };
        while (p + sizeof(ElfW(Nhdr)) <= end) {
            const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(p);
            const char* name = p + sizeof(ElfW(Nhdr));
            const auto* desc = reinterpret_cast<const unsigned char*>(name + aligned(note->n_namesz));
            if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 && std::string(name, 3) == "GNU") {
                for (size_t k = 0; k < note->n_descsz; ++k) {
                    char hex[3];
                    std::snprintf(hex, sizeof hex, "%02x", desc[k]);
                    id += hex;
                }
                return 1;
            }
            p = reinterpret_cast<const char*>(desc) + aligned(note->n_descsz);
        }
    }
    return 1;  // only the executable
}

}  // namespace

const std::string& buildId() {
    static const std::string id = [] {
        std::string s;
        dl_iterate_phdr(findBuildId, &s);
        return s.empty() ? std::string("none") : s;
    }();
    return id;
}

}  // namespace tetglow
