"""What a glTF file cannot say about a scene, as custom properties that Blender's glTF exporter
writes to `extras` (with its "Custom Properties" option): `tetglow` on each volume material (the
medium's sigma_a, sigma_s, g and emission, as the add-on maps them, the volumes around it
included) and on the scene (resolution, environment). `tetglow render scene.glb` reads them
(docs/FORMAT.md, glTF 2.0 scenes)."""
import tempfile

from . import camera, export, lights


def write(depsgraph, settings, warn):
    """Sets the properties on the scene's (original) materials and scene."""
    media = []
    with tempfile.TemporaryDirectory() as folder:
        export.build(depsgraph, settings, folder, warn, media_out=media)
    seen = {}
    for mat, m in media:
        if mat is None:
            continue
        keys = {k: m[k] for k in ('sigma_a', 'sigma_s', 'g', 'emission')}
        original = mat.original
        if original.name in seen and seen[original.name] != keys:
            warn("material '%s' fills media with different coefficients (one is nested in another): "
                 "its extras hold the first" % original.name)
            continue
        seen[original.name] = keys
        original['tetglow'] = keys
    scene = depsgraph.scene.original
    extras = {'resolution': list(camera.resolution(scene))}
    env = lights.convert_world(scene.world, warn)
    if env is not None:
        extras['environment'] = env['radiance']
    scene['tetglow'] = extras
