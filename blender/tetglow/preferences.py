"""Where the tetglow binary is: an add-on preference, else 'tetglow' on PATH, else the build of
the repository the add-on runs from (blender/tetglow -> ../../build/tetglow)."""
import os
import shutil

import bpy


class TetglowPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    binary: bpy.props.StringProperty(name='tetglow binary', subtype='FILE_PATH', default='',
                                     description="Path to the tetglow program; empty: 'tetglow' on PATH, "
                                                 'else build/tetglow of the repository this add-on is in')

    def draw(self, context):
        self.layout.prop(self, 'binary')
        found = find_binary(context)
        self.layout.label(text=('Using ' + found) if found else 'tetglow not found: set the path above')


def repo_build():
    here = os.path.dirname(os.path.realpath(__file__))
    return os.path.join(here, '..', '..', 'build', 'tetglow')


def configured(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences.binary if addon else ''


def find_binary(context):
    """The binary's path, or None."""
    path = configured(context)
    if path:
        path = bpy.path.abspath(path)
        return path if os.path.isfile(path) and os.access(path, os.X_OK) else None
    found = shutil.which('tetglow')
    if found:
        return found
    local = os.path.normpath(repo_build())
    return local if os.path.isfile(local) and os.access(local, os.X_OK) else None


def missing_message(context):
    path = configured(context)
    if path:
        return "tetglow binary '%s' not found or not executable: set it in Preferences > Add-ons > tetglow" % path
    return ("tetglow binary not found ('tetglow' is not on PATH and there is no %s): set its path in "
            "Preferences > Add-ons > tetglow" % os.path.normpath(repo_build()))
