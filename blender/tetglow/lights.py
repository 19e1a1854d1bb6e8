"""Blender lights and world as tetglow lights, in Cycles 3.4's units (measured against Cycles:
docs/BLENDER.md).

Point and spot: radiant intensity I = Power / (4 pi) W/sr (on the spot's axis); a spot's radius
makes tetglow's spot a disk of that radius. Sun: irradiance
= Strength W/m^2 on a surface facing it. Area: radiance L = Power / (4 A), one-sided along the
light's -Z. World: the Background colour x strength, a constant environment.
"""
import math


def _rgb(colour, scale):
    return [float(scale) * float(c) for c in colour[:3]]


def _axes(matrix):
    m = matrix.to_3x3()
    return m.col[0], m.col[1], m.col[2]


def convert_light(ob, matrix, warn):
    """A tetglow light dict (or None) for one evaluated light object at matrix."""
    ld = ob.data
    name = ob.name
    pos = list(matrix.translation)
    x, y, z = _axes(matrix)
    axis = (-z).normalized()
    if ld.use_nodes and ld.node_tree is not None and any(
            n.bl_idname not in ('ShaderNodeEmission', 'ShaderNodeOutputLight') for n in ld.node_tree.nodes):
        warn("light '%s': its node tree is not carried; using its colour and power" % name)
    if ld.type in ('POINT', 'SPOT'):
        if ld.type == 'POINT' and ld.shadow_soft_size > 0:
            warn("light '%s': radius %g is not carried: a point of radius 0" % (name, ld.shadow_soft_size))
        light = {'type': 'point', 'position': pos, 'intensity': _rgb(ld.color, ld.energy / (4 * math.pi))}
        if ld.type == 'SPOT':
            half = math.degrees(ld.spot_size) / 2
            cos_total = math.cos(ld.spot_size / 2)
            cos_start = min(cos_total + (1 - cos_total) * ld.spot_blend, 1.0)
            delta = min(max(half - math.degrees(math.acos(cos_start)), 0.0), half)
            light.update({'type': 'spot', 'look_at': [p + a for p, a in zip(pos, axis)],
                          'cone_angle': min(half, 90.0), 'cone_delta': delta})
            if cos_total < 0.99:
                warn("light '%s': spot profile approximated: Cycles 3.4 also multiplies by the cosine "
                     "off the axis (%.2f at the cone's edge) and blends by a smoothstep" % (name, cos_total))
            if ld.shadow_soft_size > 0:     # tetglow: a disk facing the axis; Cycles: one facing the point lit
                light['radius'] = ld.shadow_soft_size
        return light
    if ld.type == 'SUN':
        if ld.angle > math.radians(1):
            warn("light '%s': sun angle %.2g degrees is not carried: a distant light" % (name, math.degrees(ld.angle)))
        return {'type': 'distant', 'direction': list(axis), 'irradiance': _rgb(ld.color, ld.energy)}
    if ld.type == 'AREA':
        sx = ld.size * x.length
        sy = (ld.size_y if ld.shape in ('RECTANGLE', 'ELLIPSE') else ld.size) * y.length
        if getattr(ld, 'spread', math.pi) < math.pi - 1e-6:
            warn("light '%s': spread %.3g degrees is not carried: 180" % (name, math.degrees(ld.spread)))
        ux, uy = x.normalized(), y.normalized()
        if ld.shape in ('SQUARE', 'RECTANGLE'):
            area = sx * sy
            # edge0 x edge1 = -Z: the side Blender's area light emits on.
            corner = matrix.translation - ux * (sx / 2) + uy * (sy / 2)
            light = {'type': 'quad', 'corner': list(corner), 'edge0': list(ux * sx), 'edge1': list(-uy * sy)}
        else:
            area = math.pi * sx * sy / 4
            shape = {'type': 'disk', 'center': [0, 0, 0], 'normal': [0, 0, -1], 'radius': 0.5, 'sides': 64}
            cols = (ux * sx, uy * sy, z.normalized())     # local -Z (the disk's normal) -> axis
            shape['transform'] = [{'matrix': [v for i in range(3) for v in (cols[0][i], cols[1][i], cols[2][i], pos[i])]
                                   + [0, 0, 0, 1]}]
            light = {'type': 'mesh', 'shape': shape}
        light['radiance'] = _rgb(ld.color, ld.energy / (4 * area))
        return light
    warn("light '%s': type %s is not supported; dropped" % (name, ld.type))
    return None


def convert_world(world, warn):
    """The environment radiance of a world, or None when black."""
    if world is None:
        return None
    colour = list(world.color[:3])
    if world.use_nodes and world.node_tree is not None:
        out = next((n for n in world.node_tree.nodes if n.bl_idname == 'ShaderNodeOutputWorld'
                    and n.is_active_output), None) or next(
            (n for n in world.node_tree.nodes if n.bl_idname == 'ShaderNodeOutputWorld'), None)
        node = out.inputs['Surface'].links[0].from_node if out and out.inputs['Surface'].is_linked else None
        if node is None:
            return None
        if node.bl_idname != 'ShaderNodeBackground':
            warn("world '%s', node '%s': %s is not supported; the environment is black"
                 % (world.name, node.name, node.bl_idname))
            return None
        for s in ('Color', 'Strength'):
            if node.inputs[s].is_linked:
                warn("world '%s', node '%s': input '%s' is driven by node '%s', which tetglow cannot "
                     "carry; using the input's own value" % (world.name, node.name, s,
                                                            node.inputs[s].links[0].from_node.name))
        colour = _rgb(node.inputs['Color'].default_value, node.inputs['Strength'].default_value)
    if max(colour) <= 0:
        return None
    return {'type': 'environment', 'radiance': [max(c, 0.0) for c in colour]}
