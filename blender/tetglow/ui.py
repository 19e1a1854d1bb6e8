"""The render properties panel, and the standard panels shown for the tetglow engine."""
import bpy

from . import preferences


class RENDER_PT_tetglow(bpy.types.Panel):
    bl_label = 'tetglow'
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = 'render'
    COMPAT_ENGINES = {'TETGLOW'}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        s = context.scene.tetglow
        layout.prop(s, 'integrator')
        layout.prop(s, 'passes')
        layout.prop(s, 'noise')
        row = layout.row()
        row.enabled = s.integrator == 'photon'
        row.prop(s, 'photons')
        layout.prop(s, 'time_cap')
        layout.prop(s, 'max_depth')
        layout.prop(s, 'seed')
        layout.operator('scene.tetglow_gltf_extras')
        if preferences.find_binary(context) is None:
            layout.label(text='tetglow binary not found: see Preferences > Add-ons', icon='ERROR')


def shared_panels():
    """Blender's own panels (output, materials, lights, world, camera) that Cycles shows."""
    for p in bpy.types.Panel.__subclasses__():
        engines = getattr(p, 'COMPAT_ENGINES', None)
        if engines is not None and 'CYCLES' in engines and not p.__name__.startswith(
                ('CYCLES_RENDER_PT', 'CYCLES_VIEW_LAYER_PT', 'RENDER_PT_eevee')):
            yield p


def register():
    # A new set on each class: Cycles' panels share one set object through their base class,
    # and adding to it would show every Cycles panel (its sampling too) for tetglow.
    for p in list(shared_panels()):
        p.COMPAT_ENGINES = set(p.COMPAT_ENGINES) | {'TETGLOW'}


def unregister():
    for p in list(shared_panels()):
        p.COMPAT_ENGINES = set(p.COMPAT_ENGINES) - {'TETGLOW'}
