"""The 'tetglow' render engine: F12 and `blender -b FILE -E TETGLOW -f N` export the evaluated
scene to a temporary folder, run `tetglow render` on it and load its EXR into the result."""
import os
import shutil
import tempfile
import time

import bpy

from . import camera, export, preferences, process, repair


# Seconds of the last render's stages (export, tetglow's own run, the whole render call), shown
# in the status line and read by bench/results/blender_compare.py.
last_timing = {}


def command(binary, scene_json, out_exr, settings, threads):
    argv = [binary, 'render', scene_json, '-o', out_exr, '--threads', str(threads)]
    if settings.noise > 0:
        argv += ['--noise', repr(settings.noise)]
    return argv


class TetglowRenderEngine(bpy.types.RenderEngine):
    bl_idname = 'TETGLOW'
    bl_label = 'tetglow'
    bl_use_preview = False
    bl_use_eevee_viewport = True

    def render(self, depsgraph):
        scene = depsgraph.scene
        w, h = camera.resolution(scene)
        binary = preferences.find_binary(bpy.context)
        if binary is None:
            self.fail(preferences.missing_message(bpy.context))
            return
        folder = tempfile.mkdtemp(prefix='tetglow-')
        try:
            self._render_in(depsgraph, binary, folder, w, h)
        finally:
            shutil.rmtree(folder, ignore_errors=True)

    def fail(self, message):
        self.report({'ERROR'}, message)
        if hasattr(self, 'error_set'):
            self.error_set(message)

    def _render_in(self, depsgraph, binary, folder, w, h):
        scene = depsgraph.scene
        self.update_stats('', 'tetglow: exporting the scene')
        t0 = time.monotonic()
        path = os.path.join(folder, 'scene.json')
        open_media = []
        try:
            export.write(depsgraph, scene.tetglow, path, lambda m: self.report({'WARNING'}, m), open_media)
        except (ValueError, OSError) as e:
            self.fail('tetglow: %s' % e)
            return
        self.update_stats('', 'tetglow: scene exported in %.2f s' % (time.monotonic() - t0))
        for note in repair.notes(binary, folder, open_media):
            self.report({'WARNING'}, note)
        t_export = time.monotonic() - t0
        out = os.path.join(folder, 'render.exr')
        t1 = time.monotonic()
        run = process.Render(command(binary, path, out, scene.tetglow, scene.render.threads), folder)
        tail = []
        while True:
            if self.test_break():
                run.stop()
                return
            line = run.next_line(0.1)
            if line is None:
                break
            if not line:
                continue
            tail = (tail + [line])[-5:]
            p = process.parse_progress(line)
            if p is not None:
                done, planned, fraction, noise = p
                self.update_progress(fraction)
                self.update_stats('', 'tetglow: pass %d%s%s' % (
                    done, ' of %d' % planned if planned else '',
                    ', noise %.3g (relative MSE)' % noise if noise is not None else ''))
            elif process.is_warning(line):
                self.report({'WARNING'}, line)
        code = run.proc.wait()
        t_tetglow = time.monotonic() - t1
        if code != 0 or not os.path.isfile(out):
            errors = [t for t in tail if 'error' in t] or tail or ['exit code %d' % code]
            self.fail(errors[-1])
            return
        result = self.begin_result(0, 0, w, h)
        result.layers[0].load_from_file(out)
        self.end_result(result)
        last_timing.update(export_s=t_export, tetglow_s=t_tetglow, total_s=time.monotonic() - t0)
        self.update_stats('', 'tetglow: export %.2f s, tetglow render %.2f s, in all %.2f s' % (
            t_export, t_tetglow, last_timing['total_s']))
