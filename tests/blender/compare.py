"""Whether two renders of one scene agree within their own noise: the per-block z-test of
shared/peers' cycles_checks (z = mean difference / its standard error over each block's pixels,
~N(0, 1) when both renders are unbiased), plus each channel's mean ratio with its error."""
import numpy as np


def load_exr(path):
    import bpy
    img = bpy.data.images.load(path)
    w, h = img.size
    a = np.empty(w * h * 4, dtype=np.float32)
    img.pixels.foreach_get(a)
    bpy.data.images.remove(img)
    return a.reshape(h, w, 4)[::-1, :, :3].astype(np.float64)


def block_z(a, b, block=8):
    h, w, _ = a.shape
    g = (a - b).mean(2)
    ny, nx = h // block, w // block
    gb = g[:ny * block, :nx * block].reshape(ny, block, nx, block).transpose(0, 2, 1, 3).reshape(ny * nx, -1)
    se = gb.std(1, ddof=1) / np.sqrt(gb.shape[1])
    level = np.abs(b.mean(2)[:ny * block, :nx * block].reshape(ny, block, nx, block).mean((1, 3))).ravel()
    noisy = se > 1e-7 + 1e-5 * level
    z = gb.mean(1)[noisy] / se[noisy]
    quiet = np.abs(gb.mean(1)[~noisy]).max() if (~noisy).any() else 0.0
    return z, quiet


def compare(a, b, block=8):
    ma, mb = a.reshape(-1, 3).mean(0), b.reshape(-1, 3).mean(0)
    d = (a - b).reshape(-1, 3)
    se = d.std(0, ddof=1) / np.sqrt(len(d))
    z, quiet = block_z(a, b, block)
    return {'mean_a': ma.tolist(), 'mean_b': mb.tolist(), 'ratio': (ma / mb).tolist(),
            'ratio_se': (se / mb).tolist(), 'global_z': (d.mean(0) / np.maximum(se, 1e-30)).tolist(),
            'block_mean_z': float(z.mean()), 'block_std_z': float(z.std()),
            'blocks_gt4': int((np.abs(z) > 4).sum()), 'blocks': int(z.size), 'quiet_max_diff': float(quiet)}


def agree(r):
    """Both unbiased: the block z's mean near 0, their spread near 1, no channel's mean off by
    more than 4.5 of its own sigma."""
    return (abs(r['block_mean_z']) < 0.9 and r['block_std_z'] < 1.8 and r['blocks_gt4'] <= 1
            and max(abs(z) for z in r['global_z']) < 4.5 and r['quiet_max_diff'] < 1e-4)
