"""A material's node tree as tetglow terms: the volume (sigma_a, sigma_s, g, emission) and the
surface (diffuse, dielectric, interface or an emitter), as Cycles renders the same nodes.

Whatever has no tetglow equivalent (a texture driving an input, a node not listed here) becomes
a warning naming the object and the node; the input's own value is used in its place.
"""
import math

from . import sockets


class Volume:
    """Homogeneous coefficients per world unit; g is the sigma_s-weighted mean of the closures'."""

    def __init__(self, sigma_a=(0, 0, 0), sigma_s=(0, 0, 0), emission=(0, 0, 0), g=0.0):
        self.sigma_a = [float(x) for x in sigma_a]
        self.sigma_s = [float(x) for x in sigma_s]
        self.emission = [float(x) for x in emission]
        self.g = float(g)

    def scattering(self):
        return sum(self.sigma_s) / 3

    def added(self, other, warn):
        """Both closures in one place: coefficients add, as in Cycles' volume stack."""
        ws, wo = self.scattering(), other.scattering()
        if ws > 0 and wo > 0 and abs(self.g - other.g) > 1e-6:
            warn('two scattering closures with anisotropy %g and %g: one Henyey-Greenstein lobe '
                 'with their mean weighted by scattering' % (self.g, other.g))
        g = (self.g * ws + other.g * wo) / (ws + wo) if ws + wo > 0 else 0.0
        add = lambda a, b: [x + y for x, y in zip(a, b)]
        return Volume(add(self.sigma_a, other.sigma_a), add(self.sigma_s, other.sigma_s),
                      add(self.emission, other.emission), g)

    def scaled(self, f):
        return Volume([f * x for x in self.sigma_a], [f * x for x in self.sigma_s],
                      [f * x for x in self.emission], self.g)

    def empty(self):
        return max(self.sigma_a + self.sigma_s + self.emission) <= 0


class Surface:
    """kind: 'diffuse' (reflectance), 'dielectric' (ior), 'interface', 'emitter' (radiance)."""

    def __init__(self, kind, reflectance=None, ior=None, radiance=None):
        self.kind, self.reflectance, self.ior, self.radiance = kind, reflectance, ior, radiance


class NodeReader:
    """Reads one material for one object; warnings go to warn(message) with both names."""

    def __init__(self, object_name, material_name, warn):
        self.object_name, self.material_name, self._warn = object_name, material_name, warn

    def warn(self, node, text):
        self._warn("object '%s', material '%s', node '%s': %s" % (
            self.object_name, self.material_name, node.name, text))

    def value(self, node, socket):
        """The socket's own value; a link into it is not followed (warned)."""
        if socket.is_linked:
            src = socket.links[0].from_node
            self.warn(node, "input '%s' is driven by node '%s' (%s), which tetglow cannot carry; "
                      "using the input's own value" % (socket.name, src.name, src.bl_idname))
        v = socket.default_value
        try:
            return [float(x) for x in v][:3]
        except TypeError:
            return float(v)

    def input(self, node, name):
        return self.value(node, node.inputs[name])

    @staticmethod
    def source(socket):
        """The node feeding a shader socket, through reroutes; None when unlinked."""
        while socket.is_linked:
            link = socket.links[0]
            if not link.is_valid or link.is_muted:
                return None
            node = link.from_node
            if node.bl_idname != 'NodeReroute':
                return node
            socket = node.inputs[0]
        return None

    # --- volumes -------------------------------------------------------------------------------

    def volume(self, node):
        t = node.bl_idname
        if t == 'ShaderNodeVolumePrincipled':
            c = [max(x, 0.0) for x in self.input(node, 'Color')]
            d = max(self.input(node, 'Density'), 0.0)
            a = [math.sqrt(max(x, 0.0)) for x in self.input(node, 'Absorption Color')]
            es = self.input(node, 'Emission Strength')
            ec = self.input(node, 'Emission Color')
            if self.input(node, 'Blackbody Intensity') > 0:
                self.warn(node, 'blackbody emission is not carried')
            # Cycles: scattering color x density; absorption (1 - color)(1 - sqrt(absorption color))
            # x density; emission strength x colour, not x density.
            return Volume([d * max(1 - ci, 0) * max(1 - ai, 0) for ci, ai in zip(c, a)],
                          [d * ci for ci in c], [es * x for x in ec],
                          self.input(node, 'Anisotropy'))
        if t == 'ShaderNodeVolumeScatter':
            c = self.input(node, 'Color')
            d = max(self.input(node, 'Density'), 0.0)
            if 'phase' in node.bl_rna.properties and node.phase != 'HENYEY_GREENSTEIN':
                self.warn(node, "phase '%s' is not carried: Henyey-Greenstein" % node.phase)
            return Volume(sigma_s=[d * max(x, 0.0) for x in c], g=self.input(node, 'Anisotropy'))
        if t == 'ShaderNodeVolumeAbsorption':
            c = self.input(node, 'Color')
            d = max(self.input(node, 'Density'), 0.0)
            return Volume(sigma_a=[d * max(1 - x, 0.0) for x in c])
        if t == 'ShaderNodeEmission':
            s = self.input(node, 'Strength')
            return Volume(emission=[s * max(x, 0.0) for x in self.input(node, 'Color')])
        if t == 'ShaderNodeAddShader':
            parts = [self.source(node.inputs[i]) for i in (0, 1)]
            vols = [self.volume(p) for p in parts if p is not None]
            return self._sum(node, vols)
        if t == 'ShaderNodeMixShader':
            f = min(max(self.value(node, node.inputs[0]), 0.0), 1.0)
            parts = [(1 - f, self.source(node.inputs[1])), (f, self.source(node.inputs[2]))]
            vols = [self.volume(p).scaled(w) for w, p in parts if p is not None]
            return self._sum(node, vols)
        self.warn(node, 'volume node %s is not supported; this part of the volume is dropped' % t)
        return Volume()

    def _sum(self, node, vols):
        out = Volume()
        for v in vols:
            out = out.added(v, lambda text: self.warn(node, text))
        return out

    # --- surfaces ------------------------------------------------------------------------------

    def surface(self, node):
        t = node.bl_idname
        if t == 'ShaderNodeBsdfDiffuse':
            if self.input(node, 'Roughness') > 0:
                self.warn(node, 'roughness (Oren-Nayar) is not carried: Lambertian')
            return Surface('diffuse', reflectance=self._albedo(self.input(node, 'Color')))
        if t == 'ShaderNodeBsdfGlass':
            self._smooth_white(node)
            return Surface('dielectric', ior=self.input(node, 'IOR'))
        if t == 'ShaderNodeBsdfTransparent':
            if min(self.input(node, 'Color')) < 1:
                self.warn(node, 'a tinted Transparent BSDF is not carried: index-matched')
            return Surface('interface')
        if t == 'ShaderNodeEmission':
            s = self.input(node, 'Strength')
            return Surface('emitter', radiance=[s * max(x, 0.0) for x in self.input(node, 'Color')])
        if t == 'ShaderNodeBsdfPrincipled':
            return self._principled(node)
        self.warn(node, 'surface node %s is not supported; rendered as a grey diffuse surface' % t)
        return Surface('diffuse', reflectance=[0.8, 0.8, 0.8])

    def _principled(self, node):
        ec = sockets.find(node, sockets.PRINCIPLED_BSDF['emission_color'])
        es = node.inputs.get('Emission Strength')
        radiance = [0.0] * 3
        if ec is not None:
            s = self.value(node, es) if es is not None else 1.0
            radiance = [s * max(x, 0.0) for x in self.value(node, ec)]
        if max(radiance) > 0:
            self.warn(node, 'emission makes it an area light, which absorbs: its BSDF is dropped')
            return Surface('emitter', radiance=radiance)
        for key in ('subsurface', 'coat', 'sheen'):
            s = sockets.find(node, sockets.PRINCIPLED_BSDF[key])
            if s is not None and self.value(node, s) > 0:
                self.warn(node, "'%s' is not carried" % s.name)
        if self.input(node, 'Metallic') > 0:
            self.warn(node, "'Metallic' is not carried")
        if node.inputs.get('Alpha') is not None and self.input(node, 'Alpha') < 1:
            self.warn(node, "'Alpha' below 1 is not carried: opaque")
        t = self.value(node, sockets.find(node, sockets.PRINCIPLED_BSDF['transmission']))
        if t >= 0.5:
            if t < 1:
                self.warn(node, 'transmission %g is carried as 1: smooth glass' % t)
            if self.input(node, 'Roughness') > 0:
                self.warn(node, 'roughness is not carried: smooth glass')
            return Surface('dielectric', ior=self.input(node, 'IOR'))
        if t > 0:
            self.warn(node, 'transmission %g is carried as 0: diffuse' % t)
        spec = sockets.find(node, sockets.PRINCIPLED_BSDF['specular'])
        if spec is not None and self.value(node, spec) > 0:
            self.warn(node, "the specular layer ('%s' %g) is not carried: diffuse base color only"
                      % (spec.name, self.value(node, spec)))
        return Surface('diffuse', reflectance=self._albedo(self.input(node, 'Base Color')))

    def _smooth_white(self, node):
        if self.input(node, 'Roughness') > 0 and node.distribution != 'SHARP':
            self.warn(node, 'roughness is not carried: smooth glass')
        if min(self.input(node, 'Color')) < 1:
            self.warn(node, 'a tinted glass colour is not carried: clear glass')

    @staticmethod
    def _albedo(c):
        return [min(max(x, 0.0), 1.0) for x in c]


def material_output(tree):
    """The active Material Output node used by Cycles."""
    outs = [n for n in tree.nodes if n.bl_idname == 'ShaderNodeOutputMaterial' and n.target in ('ALL', 'CYCLES')]
    active = [n for n in outs if n.is_active_output]
    return (active or outs or [None])[0]


def read_material(material, object_name, warn):
    """(Surface or None for an unlinked surface, Volume or None) of a material as Cycles sees it."""
    if material is None:
        return Surface('diffuse', reflectance=[0.8, 0.8, 0.8]), None
    if not material.use_nodes or material.node_tree is None:
        return Surface('diffuse', reflectance=NodeReader._albedo(material.diffuse_color[:3])), None
    out = material_output(material.node_tree)
    if out is None:
        return None, None
    r = NodeReader(object_name, material.name, warn)
    s, v = r.source(out.inputs['Surface']), r.source(out.inputs['Volume'])
    if out.inputs['Displacement'].is_linked:
        r.warn(out, 'displacement is not carried')
    surface = r.surface(s) if s is not None else None
    volume = r.volume(v) if v is not None else None
    return surface, (None if volume is None or volume.empty() else volume)
