"""The Blender add-on measured: the three scenes of tests/blender/scenes.py rendered by Cycles and
by the add-on at the same size and samples (seconds each took, the comparison within noise), and
the demo fish built in Blender (200 x 200, 6 photon passes), to measure what the add-on costs above
`tetglow render` itself.

  blender -b --factory-startup --python bench/results/blender_compare.py -- \
      --tetglow build/tetglow --out OUT [--size 96] [--spp 1024] [--threads 2] [--only scenes|fish]

Prints one line per measurement (BLENDER_COMPARE {...}, BLENDER_FISH {...}) and a Markdown table.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

import bpy
from mathutils import Matrix, Vector

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
sys.path.insert(0, os.path.join(ROOT, 'tests', 'blender'))
sys.path.insert(0, os.path.join(ROOT, 'blender'))
import compare  # noqa: E402
import scenes  # noqa: E402
import tetglow  # noqa: E402
from tetglow import engine, export  # noqa: E402


def timed_render(scene, out):
    scene.render.filepath = out
    t = time.monotonic()
    bpy.ops.render.render(write_still=True)
    return time.monotonic() - t


def three_scenes(a):
    rows = []
    for name, build in scenes.SCENES.items():
        scene = build(a.size)
        scenes.cycles(scene, a.spp, threads=a.threads)
        cyc = os.path.join(a.out, name + '_cycles.exr')
        t_cycles = timed_render(scene, cyc)
        scene = build(a.size)
        scene.render.engine = 'TETGLOW'
        scene.tetglow.passes = a.spp
        scene.render.threads_mode, scene.render.threads = 'FIXED', a.threads
        scenes.exr(scene)
        tg = os.path.join(a.out, name + '_tetglow.exr')
        t_tetglow = timed_render(scene, tg)
        r = compare.compare(compare.load_exr(cyc), compare.load_exr(tg), block=a.size // 8)
        r.update(scene=name, cycles_s=t_cycles, tetglow_s=t_tetglow, agree=compare.agree(r))
        print('BLENDER_COMPARE ' + json.dumps(r))
        rows.append(r)
    print('\n| scene | Cycles s | tetglow s (add-on, export included) | mean R G B: Cycles / tetglow | ratio +- 1 sigma | blocks: mean z, std z, abs z > 4 |')
    print('|---|---|---|---|---|---|')
    for r in rows:
        print('| %s | %.1f | %.1f | %s | %s | %.2f, %.2f, %d of %d |' % (
            r['scene'], r['cycles_s'], r['tetglow_s'],
            ' '.join('%.4f/%.4f' % (x, y) for x, y in zip(r['mean_a'], r['mean_b'])),
            ' '.join('%.4f+-%.4f' % (x, y) for x, y in zip(r['ratio'], r['ratio_se'])),
            r['block_mean_z'], r['block_std_z'], r['blocks_gt4'], r['blocks']))


def fish_scene():
    """scenes/fish.json rebuilt in Blender from its meshes, in the file's own (Y-up) coordinates."""
    scene = scenes.empty_scene(200)
    scenes.world((0.001, 0.003, 0.008))
    cam = scenes.camera((0.9, 0.55, 3.3), (0.05, -0.12, 0))
    e, t = Vector((0.9, 0.55, 3.3)), Vector((0.05, -0.12, 0))
    fw = (t - e).normalized()
    r = fw.cross(Vector((0, 1, 0))).normalized()        # the file's up is +Y
    m = Matrix((r, r.cross(fw), -fw)).transposed().to_4x4()
    m.translation = e
    cam.matrix_world = m
    cam.data.sensor_fit, cam.data.angle = 'AUTO', math.radians(38)
    spot = scenes.light('SPOT', 'spot', (0.15, 3.2, 0.35), (0, -0.7, 0), 45 * 4 * math.pi, (0.25, 0.8, 1.0),
                        spot_size=math.radians(28))
    ct, cs = math.cos(math.radians(14)), math.cos(math.radians(10))
    spot.data.spot_blend, spot.data.shadow_soft_size = (cs - ct) / (1 - ct), 0.12

    def medium(name, sigma_a, sigma_s, g, emission=(0, 0, 0), glass=None):
        mat, nt, out = scenes.material(name)
        parts = []
        ss, sa = max(sigma_s), max(sigma_a)
        if ss > 0:
            parts.append(scenes.node(nt, 'ShaderNodeVolumeScatter', Color=tuple(x / ss for x in sigma_s),
                                     Density=ss, Anisotropy=g))
        if sa > 0:
            parts.append(scenes.node(nt, 'ShaderNodeVolumeAbsorption', Color=tuple(1 - x / sa for x in sigma_a),
                                     Density=sa))
        if max(emission) > 0:
            parts.append(scenes.node(nt, 'ShaderNodeEmission', Color=tuple(x / max(emission) for x in emission),
                                     Strength=max(emission)))
        acc = parts[0].outputs[0]
        for p in parts[1:]:
            add = nt.nodes.new('ShaderNodeAddShader')
            nt.links.new(acc, add.inputs[0])
            nt.links.new(p.outputs[0], add.inputs[1])
            acc = add.outputs[0]
        nt.links.new(acc, out.inputs['Volume'])
        if glass:
            scenes.node(nt, 'ShaderNodeBsdfGlass', out, IOR=glass, Roughness=0.0).distribution = 'SHARP'
        return mat

    def obj(file, name, mat):
        bpy.ops.wm.obj_import(filepath=os.path.join(ROOT, 'scenes', 'meshes', file), forward_axis='Y', up_axis='Z')
        ob = bpy.context.selected_objects[0]
        ob.name = name
        ob.data.materials.clear()
        ob.data.materials.append(mat)
    obj('fish.obj', 'body', medium('body', (0.8, 0.3, 0.05), (0.25, 0.3, 0.4), 0.3, (0.03, 0.2, 0.8), glass=1.2))
    obj('fish-photophores.obj', 'photophores', medium('photophores', (0.5,) * 3, (2,) * 3, 0.3, (100, 400, 800)))
    obj('fish-lure-core.obj', 'lure', medium('lure', (0.5,) * 3, (2,) * 3, 0.3, (2000, 5000, 7500)))
    obj('fish-eyes.obj', 'eyes', medium('eyes', (25,) * 3, (0.5,) * 3, 0.0))
    bpy.ops.mesh.primitive_cube_add(location=(0, 0.325, 0.5))
    water = bpy.context.active_object
    water.name, water.scale = 'water', (1.6, 1.075, 1.7)
    water.data.materials.append(medium('water', (0.3, 0.06, 0.04), (0.2, 0.28, 0.36), 0.3))
    bpy.ops.mesh.primitive_plane_add(size=1, location=(0, -0.7, 0.5), rotation=(math.pi / 2, 0, 0))
    fl = bpy.context.active_object
    fl.name, fl.scale = 'floor', (3.1, 3.3, 1)
    mat, nt, out = scenes.material('floor')
    scenes.node(nt, 'ShaderNodeBsdfDiffuse', out, Color=(0.55, 0.5, 0.42), Roughness=0.0)
    fl.data.materials.append(mat)
    s = scene.tetglow
    s.integrator, s.passes, s.photons, s.seed = 'photon', 6, 15000, 1
    return scene


def fish(a):
    """The add-on's cost: F12's wall time minus `tetglow render` of the same exported scene."""
    scene = fish_scene()
    scene.render.engine = 'TETGLOW'
    scene.render.threads_mode, scene.render.threads = 'FIXED', a.threads
    scenes.exr(scene)
    folder = os.path.join(a.out, 'fish')
    os.makedirs(folder, exist_ok=True)
    warnings = []
    t = time.monotonic()
    export.write(bpy.context.evaluated_depsgraph_get(), scene.tetglow, os.path.join(folder, 'scene.json'),
                 warnings.append)
    t_export = time.monotonic() - t
    cmd = [a.tetglow, 'render', os.path.join(folder, 'scene.json'), '-o', os.path.join(folder, 'direct.exr'),
           '--threads', str(a.threads)]
    direct = []
    for k in range(a.repeat):
        t = time.monotonic()
        subprocess.run(cmd, check=True, capture_output=True)
        direct.append(time.monotonic() - t)
    addon, stages = [], []
    for k in range(a.repeat):
        addon.append(timed_render(scene, os.path.join(folder, 'addon%d.exr' % k)))
        stages.append(dict(engine.last_timing))
    # What the add-on adds, free of the render's own spread: F12's wall time minus the wall time
    # of the tetglow process it ran (export, repair notes, start, reading, loading the EXR).
    r = {'export_s': t_export, 'tetglow_render_s': direct, 'addon_render_s': addon, 'addon_stages': stages,
         'overhead_s': [w - st['tetglow_s'] for w, st in zip(addon, stages)], 'warnings': warnings}
    print('BLENDER_FISH ' + json.dumps(r))


def main():
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument('--tetglow', required=True)
    p.add_argument('--out', required=True)
    p.add_argument('--size', type=int, default=96)
    p.add_argument('--spp', type=int, default=1024)
    p.add_argument('--threads', type=int, default=2)
    p.add_argument('--repeat', type=int, default=3)
    p.add_argument('--only', choices=['scenes', 'fish'])
    a = p.parse_args(argv)
    a.tetglow = os.path.abspath(a.tetglow)
    os.environ['PATH'] = os.path.dirname(a.tetglow) + os.pathsep + os.environ.get('PATH', '')
    os.makedirs(a.out, exist_ok=True)
    tetglow.register()
    if a.only != 'fish':
        three_scenes(a)
    if a.only != 'scenes':
        fish(a)


main()
