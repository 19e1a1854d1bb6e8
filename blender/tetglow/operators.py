"""File > Export > tetglow scene: the JSON scene with its meshes beside it, for `tetglow render`
or `tetglow farm`."""
import os

import bpy
from bpy_extras.io_utils import ExportHelper

from . import export, gltf_extras, preferences, repair


class EXPORT_SCENE_OT_tetglow(bpy.types.Operator, ExportHelper):
    """Export the scene as a tetglow JSON scene with its meshes in a 'meshes' folder beside it"""
    bl_idname = 'export_scene.tetglow'
    bl_label = 'Export tetglow scene'
    filename_ext = '.json'
    filter_glob: bpy.props.StringProperty(default='*.json', options={'HIDDEN'})

    def execute(self, context):
        depsgraph = context.evaluated_depsgraph_get()
        warnings, open_media = [], []
        try:
            export.write(depsgraph, context.scene.tetglow, self.filepath, warnings.append, open_media)
        except (ValueError, OSError) as e:
            self.report({'ERROR'}, 'tetglow: %s' % e)
            return {'CANCELLED'}
        binary = preferences.find_binary(context)
        if binary is not None:
            warnings += repair.notes(binary, os.path.dirname(os.path.abspath(self.filepath)), open_media)
        for w in warnings:
            self.report({'WARNING'}, w)
        self.report({'INFO'}, 'tetglow scene written to %s' % self.filepath)
        return {'FINISHED'}


class SCENE_OT_tetglow_gltf_extras(bpy.types.Operator):
    """Store each medium's coefficients and the scene's resolution and environment as 'tetglow'
    custom properties, which File > Export > glTF 2.0 writes to extras (Include > Custom Properties)"""
    bl_idname = 'scene.tetglow_gltf_extras'
    bl_label = 'Write glTF extras'

    def execute(self, context):
        warnings = []
        gltf_extras.write(context.evaluated_depsgraph_get(), context.scene.tetglow, warnings.append)
        for w in warnings:
            self.report({'WARNING'}, w)
        return {'FINISHED'}


def menu_entry(self, context):
    self.layout.operator(EXPORT_SCENE_OT_tetglow.bl_idname, text='tetglow scene (.json)')
