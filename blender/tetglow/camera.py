"""The scene camera as tetglow's: position, look_at, up, the field of view across the shorter
image axis (from lens, sensor and sensor fit, as Blender frames it) and the resolution with its
percentage applied."""
import math


def resolution(scene):
    r = scene.render
    p = r.resolution_percentage / 100.0
    return max(1, int(r.resolution_x * p)), max(1, int(r.resolution_y * p))


def convert_camera(scene, cam_ob, warn):
    cd = cam_ob.data
    if cd.type != 'PERSP':
        warn("camera '%s': type %s is not supported; rendered as perspective" % (cam_ob.name, cd.type))
    if cd.shift_x or cd.shift_y:
        warn("camera '%s': lens shift is not carried" % cam_ob.name)
    if cd.dof.use_dof:
        warn("camera '%s': depth of field is not carried" % cam_ob.name)
    r = scene.render
    if r.pixel_aspect_x != r.pixel_aspect_y:
        warn("camera '%s': a pixel aspect other than 1 is not carried" % cam_ob.name)
    w, h = resolution(scene)
    # view_frame applies the sensor fit and the aspect: its corners span the image at depth 1.
    frame = cd.view_frame(scene=scene)
    half_x = max(abs(v.x / v.z) for v in frame)
    half_y = max(abs(v.y / v.z) for v in frame)
    fov = 2 * math.degrees(math.atan(half_x if w < h else half_y))
    m = cam_ob.matrix_world
    pos = m.translation
    rot = m.to_3x3().normalized()
    forward, up = -rot.col[2], rot.col[1]
    return {'position': list(pos), 'look_at': list(pos + forward), 'up': list(up),
            'fov': fov, 'resolution': [w, h]}
