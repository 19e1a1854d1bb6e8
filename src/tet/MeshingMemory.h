// The memory a tetrahedralization takes, estimated from the triangle count before any of it is
// allocated: validation and repair in this process (the BVHs, the winding numbers, the
// adjacency) and TetGen in its child (ChildProcess.h, bounded at half of memoryLimit()). A mesh
// that would not fit is refused in a moment, instead of minutes of work that end in the child's
// limit or the kernel's out-of-memory killer.
#pragma once
#include <cstddef>

namespace tetglow {

struct MeshingMemory {
    double here = 0;    // bytes this process holds while validating, repairing and assembling
    double tetgen = 0;  // bytes TetGen's child takes beyond what it shares with this process
};

MeshingMemory meshingMemory(size_t triangles);

// InputError "2000000 triangles need about 16 GB to tetrahedralize (2 GB here, 14 GB in
// TetGen), more than ..." when TetGen's share exceeds its child's limit or the whole exceeds
// memoryLimit().
void checkMeshingMemory(size_t triangles);

}  // namespace tetglow
