"""The render settings stored in each scene (scene.tetglow)."""
import bpy


class TetglowRenderSettings(bpy.types.PropertyGroup):
    integrator: bpy.props.EnumProperty(
        name='Integrator', default='volpath',
        items=[('volpath', 'Path tracer', 'Unbiased volumetric path tracer (volpath)'),
               ('photon', 'Photon mapping', 'Progressive volumetric photon mapping: lights seen through glass')])
    passes: bpy.props.IntProperty(name='Passes', default=64, min=1, max=1048576,
                                  description='Samples per pixel (photon: passes); the cap when a noise target is set')
    noise: bpy.props.FloatProperty(name='Noise target', default=0.0, min=0.0, precision=4,
                                   description='Stop once the estimated relative MSE is at most this (0: off)')
    photons: bpy.props.IntProperty(name='Photons', default=100000, min=1,
                                   description='Photon paths traced per pass')
    time_cap: bpy.props.FloatProperty(name='Time cap', default=0.0, min=0.0, unit='TIME_ABSOLUTE',
                                      description='Stop starting passes after this many seconds (0: no cap)')
    max_depth: bpy.props.IntProperty(name='Max depth', default=64, min=1, max=1048576,
                                     description='Scattering and surface events per path')
    seed: bpy.props.IntProperty(name='Seed', default=0, min=0)
