"""An evaluated Blender scene as a tetglow JSON scene with its meshes as OBJ files beside it."""
import json
import os
import re

import numpy as np

from . import camera, geometry, lights, shaders

GEOMETRY_TYPES = {'MESH', 'CURVE', 'SURFACE', 'META', 'FONT'}


def integrator(settings):
    out = {'type': settings.integrator, 'spp': settings.passes, 'max_depth': settings.max_depth,
           'seed': settings.seed}
    if settings.integrator == 'photon':
        out['photons'] = settings.photons
    if settings.time_cap > 0:
        out['time'] = settings.time_cap
    return out


class Part:
    """The triangles of one object that share one material, in world space."""

    def __init__(self, name, P, T, surface, volume, material):
        self.name, self.P, self.T, self.surface, self.volume = name, P, T, surface, volume
        self.material = material
        self.lo, self.hi = P.min(0), P.max(0)


def _parts(depsgraph, warn):
    cache = {}
    for inst in depsgraph.object_instances:
        ob = inst.object
        if ob.type not in GEOMETRY_TYPES:
            continue
        name = (inst.parent.name + '/' if inst.is_instance and inst.parent else '') + ob.name
        key = (ob.original.name if ob.original else ob.name, ob.data.name if ob.data else '')
        if key not in cache or not inst.is_instance:
            cache[key] = geometry.triangles(ob)
        tri = cache[key]
        if tri is None:
            continue
        P, T, M = tri
        W, T = geometry.place(P, T, inst.matrix_world)
        slots = [s.material for s in ob.material_slots] or [None]
        for k in np.unique(M):
            mat = slots[min(int(k), len(slots) - 1)]
            surface, volume = shaders.read_material(mat, name, warn)
            if surface is None and volume is None:
                warn("object '%s': material '%s' has neither a surface nor a volume shader; "
                     "it is invisible, as in Cycles" % (name, mat.name if mat else ''))
                continue
            Pk, Tk = geometry.compact(W, T[M == k])
            label = name if len(slots) == 1 else '%s/%s' % (name, mat.name if mat else k)
            yield Part(label, Pk, Tk, surface, volume, mat)


def _nest(media, warn):
    """Each medium's coefficients plus those of every medium around it: Cycles adds the volumes
    that overlap, tetglow's nested media each fill their own region."""
    bvhs = [None] * len(media)
    for i, a in enumerate(media):
        total = a.volume
        for j, b in enumerate(media):
            if i == j or np.any(a.lo < b.lo) or np.any(a.hi > b.hi):
                continue
            if bvhs[j] is None:
                bvhs[j] = geometry.bvh_of(b.P, b.T)
            if geometry.inside(a.P[0], bvhs[j], float(np.linalg.norm(b.hi - b.lo))):
                total = total.added(b.volume, lambda t: warn("object '%s' inside '%s': %s" % (a.name, b.name, t)))
        a.effective = total


def _mesh_shape(folder, part, index):
    stem = re.sub(r'[^A-Za-z0-9_.-]+', '_', part.name)[:48] or 'mesh'
    rel = 'meshes/%d_%s.obj' % (index, stem)
    geometry.write_obj(os.path.join(folder, rel), part.P, part.T)
    return {'type': 'mesh', 'file': rel}


def _name(s):
    b = ''.join(c for c in s if c >= ' ').encode('utf-8')[:64]
    return b.decode('utf-8', 'ignore') or 'object'


def _g(v, name, warn):
    if abs(v) >= 0.999:
        warn("object '%s': anisotropy %g carried as %g (tetglow takes (-1, 1))" % (name, v, 0.999 if v > 0 else -0.999))
    return max(min(v, 0.999), -0.999)


def build(depsgraph, settings, folder, warn, open_media=None, media_out=None):
    """Writes the meshes under folder/meshes and returns the scene as a dict; the (object, mesh
    file) of each medium whose mesh is not closed go to open_media, for tetglow's repair note,
    and (material, medium dict) of every medium to media_out."""
    scene = depsgraph.scene
    os.makedirs(os.path.join(folder, 'meshes'), exist_ok=True)
    if scene.camera is None:
        raise ValueError("scene '%s' has no camera" % scene.name)
    cam_ob = scene.camera.evaluated_get(depsgraph)
    out = {'camera': camera.convert_camera(scene, cam_ob, warn), 'integrator': integrator(settings),
           'lights': [], 'surfaces': [], 'media': []}
    for inst in depsgraph.object_instances:
        if inst.object.type == 'LIGHT':
            light = lights.convert_light(inst.object, inst.matrix_world, warn)
            if light is not None:
                out['lights'].append(light)
    env = lights.convert_world(scene.world, warn)
    if env is not None:
        out['lights'].append(env)
    parts = list(_parts(depsgraph, warn))
    media = []
    for p in parts:
        if p.volume is not None:
            if p.surface is not None and p.surface.kind in ('diffuse', 'emitter'):
                warn("object '%s': an opaque surface hides its volume (as in Cycles): a surface" % p.name)
                p.volume = None
            else:
                media.append(p)
    _nest(media, warn)
    for i, p in enumerate(parts):
        if p.volume is not None:
            v = p.effective
            shape = _mesh_shape(folder, p, i)
            edges = geometry.open_edges(p.T)
            if edges:
                warn("object '%s': its mesh is not closed (%d edges not shared by two faces): "
                     "tetglow repairs it" % (p.name, edges))
                if open_media is not None:
                    open_media.append((p.name, shape['file']))
            m = {'name': _name(p.name), 'shape': shape, 'sigma_a': v.sigma_a,
                 'sigma_s': v.sigma_s, 'g': _g(v.g, p.name, warn), 'emission': v.emission}
            if p.surface is not None and p.surface.kind == 'dielectric':
                m['boundary'] = {'type': 'dielectric', 'ior': p.surface.ior}
            out['media'].append(m)
            if media_out is not None:
                media_out.append((p.material, m))
        elif p.surface.kind == 'emitter':
            if max(p.surface.radiance) > 0:
                out['lights'].append({'type': 'mesh', 'shape': _mesh_shape(folder, p, i),
                                      'radiance': p.surface.radiance, 'two_sided': True})
        elif p.surface.kind == 'diffuse':
            out['surfaces'].append({'shape': _mesh_shape(folder, p, i),
                                    'material': {'type': 'diffuse', 'reflectance': p.surface.reflectance}})
        elif p.surface.kind == 'dielectric':
            out['surfaces'].append({'shape': _mesh_shape(folder, p, i),
                                    'material': {'type': 'dielectric', 'ior': p.surface.ior}})
        # an 'interface' surface without a volume is invisible: nothing to carry
    return out


def write(depsgraph, settings, path, warn, open_media=None):
    """Exports to path (a .json), its meshes in a 'meshes' folder beside it; returns the dict."""
    folder = os.path.dirname(os.path.abspath(path))
    scene = build(depsgraph, settings, folder, warn, open_media)
    scene['output'] = os.path.splitext(os.path.basename(path))[0] + '.exr'    # `farm` and `render` without -o
    with open(path, 'w') as f:
        json.dump(scene, f, indent=1)
    return scene
