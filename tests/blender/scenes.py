"""The Blender scenes the add-on is checked on, built from Python (Z up). Each uses only what
Blender's glTF exporter also writes (camera, lights, meshes, node materials), so the same scene
can go through bpy.ops.export_scene.gltf."""
import math

import bpy
from mathutils import Vector


def empty_scene(size):
    bpy.ops.wm.read_homefile(use_empty=True)
    scene = bpy.context.scene
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    return scene


def world(colour):
    w = bpy.data.worlds.new('world')
    w.use_nodes = True
    bg = w.node_tree.nodes['Background']
    bg.inputs['Color'].default_value = tuple(colour) + (1.0,)
    bg.inputs['Strength'].default_value = 1.0
    bpy.context.scene.world = w


def link(name, data):
    ob = bpy.data.objects.new(name, data)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def look(ob, position, target):
    ob.location = Vector(position)
    ob.rotation_mode = 'QUATERNION'
    ob.rotation_quaternion = (Vector(target) - Vector(position)).to_track_quat('-Z', 'Y')


def camera(position, target, lens=50.0):
    cd = bpy.data.cameras.new('camera')
    cd.lens = lens
    ob = link('camera', cd)
    look(ob, position, target)
    bpy.context.scene.camera = ob
    return ob


def light(kind, name, position, target, power, colour=(1, 1, 1), **kw):
    ld = bpy.data.lights.new(name, kind)
    ld.energy = power
    ld.color = colour
    if kind in ('POINT', 'SPOT'):
        ld.shadow_soft_size = 0.0
    if kind == 'SUN':
        ld.angle = 0.0
    for k, v in kw.items():
        setattr(ld, k, v)
    ob = link(name, ld)
    look(ob, position, target)
    return ob


def material(name):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.remove(nt.nodes['Principled BSDF'])
    m.cycles.homogeneous_volume = True       # exact free flights in Cycles, as tetglow's
    m.cycles.volume_sampling = 'MULTIPLE_IMPORTANCE'
    return m, nt, nt.nodes['Material Output']


def node(nt, kind, out=None, socket='Surface', **inputs):
    n = nt.nodes.new(kind)
    for k, v in inputs.items():
        n.inputs[k].default_value = tuple(v) + (1.0,) if isinstance(v, tuple) and len(v) == 3 else v
    if out is not None:
        nt.links.new(n.outputs[0], out.inputs[socket])
    return n


def sphere(name, radius, location=(0, 0, 0), subdivisions=3, mat=None):
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=subdivisions, radius=radius, location=location)
    ob = bpy.context.active_object
    ob.name = name
    if mat is not None:
        ob.data.materials.append(mat)
    return ob


def floor(z, size, colour):
    bpy.ops.mesh.primitive_plane_add(size=size, location=(0, 0, z))
    ob = bpy.context.active_object
    ob.name = 'floor'
    m, nt, out = material('floor')
    node(nt, 'ShaderNodeBsdfDiffuse', out, Color=colour, Roughness=0.0)
    ob.data.materials.append(m)
    return ob


def glowing_volume(size=48):
    """(a) A sphere of glowing Principled Volume under a point light."""
    scene = empty_scene(size)
    world((0.02, 0.02, 0.03))
    camera((0, -5.5, 1.2), (0, 0, 0))
    light('POINT', 'lamp', (2.5, -2.5, 3.5), (0, 0, 0), 900.0, (1.0, 0.9, 0.8))
    m, nt, out = material('glow')
    node(nt, 'ShaderNodeVolumePrincipled', out, 'Volume', Color=(0.8, 0.6, 0.4), Density=1.2,
         Anisotropy=0.3, **{'Absorption Color': (0.6, 0.4, 0.2), 'Emission Color': (0.2, 0.5, 1.0),
                            'Emission Strength': 0.4})
    sphere('glow', 1.0, mat=m)
    return scene


def glass_skin(size=48):
    """(b) A scattering medium inside a glass skin under an area light, over a diffuse floor."""
    scene = empty_scene(size)
    world((0.0, 0.0, 0.0))
    camera((0, -6.0, 1.8), (0, 0, -0.3))
    light('AREA', 'panel', (0.5, 0.5, 4.0), (0, 0, 0), 600.0, size=2.0)
    m, nt, out = material('skin')
    node(nt, 'ShaderNodeBsdfGlass', out, Color=(1, 1, 1), Roughness=0.0, IOR=1.4).distribution = 'SHARP'
    node(nt, 'ShaderNodeVolumeScatter', out, 'Volume', Color=(0.9, 0.8, 0.7), Density=1.5, Anisotropy=0.0)
    sphere('skin', 1.0, mat=m)
    floor(-1.0, 12.0, (0.6, 0.6, 0.6))
    return scene


def nested_core(size=48, gltf=False):
    """(c) A glowing core nested inside a scattering body, under a sun. The core glows by an
    Emission node in its volume; with gltf, by a Principled Volume's emission (density 0), which
    Cycles renders the same: Blender's glTF exporter writes any Emission node as surface
    emission."""
    scene = empty_scene(size)
    world((0.03, 0.03, 0.04))
    camera((0, -6.0, 1.0), (0, 0, 0))
    light('SUN', 'sun', (3, -2, 5), (0, 0, 0), 3.0, (1.0, 0.95, 0.9))
    body, nt, out = material('body')
    add = node(nt, 'ShaderNodeAddShader', out, 'Volume')
    sc = node(nt, 'ShaderNodeVolumeScatter', Color=(0.7, 0.8, 0.9), Density=1.0, Anisotropy=0.2)
    ab = node(nt, 'ShaderNodeVolumeAbsorption', Color=(0.8, 0.8, 0.6), Density=0.5)
    nt.links.new(sc.outputs[0], add.inputs[0])
    nt.links.new(ab.outputs[0], add.inputs[1])
    sphere('body', 1.3, mat=body)
    core, nt, out = material('core')
    if gltf:
        node(nt, 'ShaderNodeVolumePrincipled', out, 'Volume', Density=0.0,
             **{'Emission Color': (1.0, 0.5, 0.1), 'Emission Strength': 1.5})
    else:
        node(nt, 'ShaderNodeEmission', out, 'Volume', Color=(1.0, 0.5, 0.1), Strength=1.5)
    sphere('core', 0.5, location=(0.1, 0, 0.1), subdivisions=2, mat=core)
    return scene


SCENES = {'glowing_volume': glowing_volume, 'glass_skin': glass_skin, 'nested_core': nested_core}

# The scenes whose every part glTF carries (cameras, point, spot and sun lights, absorbing volumes
# and emission; through the add-on's extras, scattering): not the glass skin, whose area light and
# Glass BSDF Blender's glTF exporter does not write.
GLTF_SCENES = {'glowing_volume': glowing_volume, 'nested_core': lambda size: nested_core(size, gltf=True)}


def cycles(scene, spp, max_depth=64, threads=2):
    """Cycles set up to converge to what tetglow converges to (shared/peers conventions: no
    adaptive sampling, denoising or clamping; box pixel filter; bounces = max_depth - 2)."""
    scene.render.engine = 'CYCLES'
    c = scene.cycles
    c.device = 'CPU'
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.pixel_filter_type = 'BOX'
    c.filter_width = 1.0
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    b = max_depth - 2
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.volume_bounces = b
    c.transparent_max_bounces = 1024
    c.caustics_reflective = c.caustics_refractive = True
    c.blur_glossy = 0.0
    scene.render.threads_mode = 'FIXED'
    scene.render.threads = threads
    exr(scene)


def exr(scene):
    im = scene.render.image_settings
    im.file_format = 'OPEN_EXR'
    im.color_mode = 'RGB'
    im.color_depth = '32'
    scene.render.use_file_extension = False
    scene.view_settings.view_transform = 'Standard'
    scene.render.dither_intensity = 0.0
