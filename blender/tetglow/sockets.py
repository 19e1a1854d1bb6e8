"""Shader node sockets whose names differ between Blender 3.x and 4.x.

Blender 4.0 renamed several Principled BSDF inputs; each entry lists the 4.x name first, then
the 3.x one, and the first the node has is read.
"""

PRINCIPLED_BSDF = {
    'transmission': ('Transmission Weight', 'Transmission'),
    'emission_color': ('Emission Color', 'Emission'),
    'subsurface': ('Subsurface Weight', 'Subsurface'),
    'specular': ('Specular IOR Level', 'Specular'),
    'coat': ('Coat Weight', 'Clearcoat'),
    'sheen': ('Sheen Weight', 'Sheen'),
}


def find(node, names):
    """The first input of node named in names (a tuple of spellings), or None."""
    for n in names:
        s = node.inputs.get(n)
        if s is not None:
            return s
    return None
