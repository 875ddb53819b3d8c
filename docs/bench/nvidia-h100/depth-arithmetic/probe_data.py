"""What probe_test.cpp wrote, and the float arithmetic the fits share.

Batch b of the probe: b<b>.clip (600 triangles x 3 vertices, clip xyzw as float32), b<b>.ids
(triangle + 1 per pixel, 640x360), b<b>.depth (the D32F depth), b<b>.fragz (gl_FragCoord.z bits).
"""
import numpy as np

W, H = 640, 360
f32 = np.float32


def ulpdiff(a, b):
    """b - a in float32 ulps (both float32, same sign)."""
    return b.view(np.int32).astype(np.int64) - a.view(np.int32).astype(np.int64)


def rounded(x, mode):
    """float64 values to float32: to nearest, up, down or toward zero."""
    r = x.astype(f32)
    r64 = r.astype(np.float64)
    if mode == 'near':
        return r
    if mode == 'up':
        m = r64 < x
        r[m] = np.nextafter(r[m], f32(np.inf))
    elif mode == 'down':
        m = r64 > x
        r[m] = np.nextafter(r[m], f32(-np.inf))
    elif mode == 'trunc':
        m = np.abs(r64) > np.abs(x)
        r[m] = np.nextafter(r[m], f32(0))
    return r


def covered_pixels(directory, batch):
    """Per covered pixel: its triangle's clip positions (n, 3, 4), the pixel centre (px, py), the
    hardware depth and gl_FragCoord.z (float32)."""
    clip = np.fromfile(f'{directory}/b{batch}.clip', np.float32).reshape(-1, 3, 4)
    ids = np.fromfile(f'{directory}/b{batch}.ids', np.uint32).reshape(H, W)
    depth = np.fromfile(f'{directory}/b{batch}.depth', np.float32).reshape(H, W)
    fragz = np.fromfile(f'{directory}/b{batch}.fragz', np.uint32).reshape(H, W).view(np.float32)
    yy, xx = np.nonzero(ids)
    t = ids[yy, xx].astype(np.int64) - 1
    return clip[t], xx + 0.5, yy + 0.5, depth[yy, xx], fragz[yy, xx]


def window_positions(c, divide='div'):
    """NDC (float32, by division or by a reciprocal) and window xy in float32, as the viewport
    transform computes them: ndc * half + half."""
    if divide == 'div':
        ndc = (c[:, :, :3] / c[:, :, 3:4]).astype(f32)
    else:
        ndc = (c[:, :, :3] * (f32(1) / c[:, :, 3:4]).astype(f32)).astype(f32)
    half = np.array([W / 2, H / 2], np.float32)
    win = (ndc[:, :, :2] * half).astype(f32) + half
    return ndc, win


def snapped(win):
    """Window positions snapped to 1/256 pixel (round half to even), as float64."""
    return np.round(win.astype(np.float64) * 256) / 256
