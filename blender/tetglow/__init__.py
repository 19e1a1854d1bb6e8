"""tetglow for Blender: a render engine that exports the evaluated scene and runs `tetglow
render`, and File > Export > tetglow scene. The mapping from Blender's nodes and lights to
tetglow's scene is in docs/BLENDER.md."""

bl_info = {
    'name': 'tetglow',
    'author': 'tetglow authors',
    'version': (0, 1, 0),
    'blender': (3, 4, 0),
    'location': 'Render Properties > Render Engine; File > Export > tetglow scene',
    'description': 'Render participating media inside meshes with tetglow (exact boundaries, photon mapping)',
    'category': 'Render',
}

import bpy

from . import engine, operators, preferences, properties, ui

CLASSES = (preferences.TetglowPreferences, properties.TetglowRenderSettings, engine.TetglowRenderEngine,
           operators.EXPORT_SCENE_OT_tetglow, operators.SCENE_OT_tetglow_gltf_extras, ui.RENDER_PT_tetglow)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)
    bpy.types.Scene.tetglow = bpy.props.PointerProperty(type=properties.TetglowRenderSettings)
    bpy.types.TOPBAR_MT_file_export.append(operators.menu_entry)
    ui.register()


def unregister():
    ui.unregister()
    bpy.types.TOPBAR_MT_file_export.remove(operators.menu_entry)
    del bpy.types.Scene.tetglow
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
