"""tetglow's own note on how it repairs a medium's open mesh (`tetglow tetrahedralize` prints it;
the result is cached, so the render that follows reuses it)."""
import os
import subprocess


def notes(binary, folder, open_media):
    """One line per repaired object: "object 'X': tetglow repaired its mesh: ..."."""
    out = []
    for name, rel in open_media:
        r = subprocess.run([binary, 'tetrahedralize', os.path.join(folder, rel)], capture_output=True, text=True)
        lines = [x.split(None, 1)[1] for x in r.stdout.splitlines() if x.startswith('repaired')]
        if r.returncode != 0:
            lines = [(r.stderr.strip().splitlines() or ['exit code %d' % r.returncode])[-1]]
        out += ["object '%s': tetglow repaired its mesh: %s" % (name, x) for x in lines]
    return out
