"""Evaluated Blender geometry as world-space triangle arrays, and OBJ files of them."""
import numpy as np


def triangles(ob):
    """(P, T, material index per triangle) of an evaluated object in its own space, or None
    when it has no triangles (modifiers, curves and text are already applied by evaluation)."""
    try:
        me = ob.to_mesh()
    except RuntimeError:
        return None
    if me is None:
        return None
    try:
        me.calc_loop_triangles()
        nt, nv = len(me.loop_triangles), len(me.vertices)
        if nt == 0:
            return None
        P = np.empty(nv * 3, dtype=np.float32)     # foreach_get needs the property's own type
        me.vertices.foreach_get('co', P)
        T = np.empty(nt * 3, dtype=np.int32)
        me.loop_triangles.foreach_get('vertices', T)
        M = np.empty(nt, dtype=np.int32)
        me.loop_triangles.foreach_get('material_index', M)
        return P.reshape(-1, 3).astype(np.float64), T.reshape(-1, 3).astype(np.int64), M
    finally:
        ob.to_mesh_clear()


def place(P, T, matrix):
    """P, T in world space: a mirroring matrix reverses the windings, so outward stays outward."""
    M = np.array(matrix, dtype=np.float64)
    W = P @ M[:3, :3].T + M[:3, 3]
    return W, (T[:, ::-1] if np.linalg.det(M[:3, :3]) < 0 else T)


def compact(P, T):
    """Only the vertices the triangles use."""
    used, inv = np.unique(T.ravel(), return_inverse=True)
    return P[used], inv.reshape(-1, 3)


def open_edges(T):
    """Edges not shared by exactly two triangles: 0 for a closed manifold surface."""
    E = np.sort(np.concatenate([T[:, [0, 1]], T[:, [1, 2]], T[:, [2, 0]]]), axis=1)
    _, counts = np.unique(E, axis=0, return_counts=True)
    return int((counts != 2).sum())


def write_obj(path, P, T):
    with open(path, 'w') as f:
        np.savetxt(f, P, fmt='v %.9g %.9g %.9g')
        np.savetxt(f, T + 1, fmt='f %d %d %d')


def inside(point, bvh, diagonal):
    """Whether point lies inside the closed surface in bvh, by the parity of a ray's crossings."""
    from mathutils import Vector
    d = Vector((0.5773, 0.5779, 0.5768)).normalized()
    o, crossings, eps = Vector(point), 0, 1e-7 * diagonal
    while crossings < 10000:
        hit = bvh.ray_cast(o, d)
        if hit[0] is None:
            break
        crossings += 1
        o = hit[0] + d * eps
    return crossings % 2 == 1


def bvh_of(P, T):
    from mathutils.bvhtree import BVHTree
    return BVHTree.FromPolygons(P.tolist(), T.tolist(), all_triangles=True)
