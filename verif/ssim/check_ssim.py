#!/usr/bin/env python3
"""The project's SSIM (cmodel/image/ssim.hpp) against scikit-image's, a ground truth that shares no
code with it: skimage.metrics.structural_similarity(a, b, channel_axis=2, gaussian_weights=True,
sigma=1.5, use_sample_covariance=False, data_range=255) (Debian's python3-skimage).

  synthetic  pairs made here, through cig_ssim_png: identical (the project's must be exactly 1),
             noise of three strengths (SSIM falls as noise grows, in both), edges shifted by a
             pixel or two, two constant images, an image against its negative (SSIM < 0), the
             smallest images with a window position (11 x 11, 11 x 37); a 10 x 30 image, smaller
             than the window, refused by both
  engines    scenes/airfield.json frame 0 channel 1 rendered by float, segment and quadtree
             (cig render); `cig compare --report` of segment and quadtree: the report's ssim is
             the same as cig_ssim_png's on the rendered PNGs (its psnr matches them, so they are
             the images compare saw), within TOLERANCE of skimage's; the table prints it

Tolerance. Both sides evaluate the same formula in IEEE double from exact inputs (8-bit values,
their products <= 255^2 exact); they differ only in rounding: the order of the separable filter
(cig: along x then y; scipy.ndimage: y then x, pairing symmetric taps), the weights (each an exp
and a division, a few ulp) and the mean's summation. A worst-case bound, u = 2^-53:
  * a filtered moment (11 + 11 multiply-adds, the weights' own error) is within e = 26 u of its
    exact value relative to its largest input, so the two sides differ by 2e: 2e*255 for a mean,
    2e*255^2 for E[x^2], E[xy];
  * so ux*uy within 2*255*(2e*255), a variance E[x^2] - ux^2 within 2e*255^2 + 2*255*(2e*255)
    (+ a few u*255^2 for its own roundings);
  * S = A1 A2 / (B1 B2) with |A1| <= B1 and |A2| <= B2 (Cauchy-Schwarz) changes by at most
    (dA1 + dB1)/B1 + (dA2 + dB2)/B2, and B1 >= C1 = (0.01*255)^2, B2 >= C2 = (0.03*255)^2;
  * the mean of S keeps that bound, plus summation error (rows + columns, or log2 n, times u,
    values <= 1): under 1e-12.
That gives TOLERANCE below (about 6e-10); the measured differences are far smaller.

usage: check_ssim.py CASE CIG SSIM_PNG WORKDIR"""
import glob
import json
import math
import os
import shutil
import subprocess
import sys

try:
    import numpy as np
    from PIL import Image
    from skimage.metrics import structural_similarity
except ImportError as e:
    print(f"FAIL: {e}: the ground truth is Debian's python3-skimage (tools/deps.sh installs it)")
    sys.exit(1)

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
U = 2.0 ** -53
L = 255.0
C1, C2 = (0.01 * L) ** 2, (0.03 * L) ** 2


def tolerance():
    e = 26 * U                              # one side's filtered moment, relative to its largest input
    d_mean, d_m2 = 2 * e * L, 2 * e * L * L  # the two sides' difference: a mean, a second moment
    d_prod = 2 * L * d_mean + 2 * U * L * L  # ux * uy
    d_var = d_m2 + d_prod + 2 * U * L * L    # E[x^2] - ux^2, E[xy] - ux uy
    d_a1 = d_b1 = 2 * d_prod + 2 * U * L * L
    d_a2 = d_b2 = 2 * d_var + 2 * U * L * L
    return (d_a1 + d_b1) / C1 + (d_a2 + d_b2) / C2 + 8 * U + 1e-12


TOLERANCE = tolerance()
failures = []
worst = [0.0]


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True)


def skimage_ssim(a, b):
    """Mean, then R, G, B."""
    kw = dict(gaussian_weights=True, sigma=1.5, use_sample_covariance=False, data_range=255)
    channels = [structural_similarity(a[..., c], b[..., c], **kw) for c in range(3)]
    return structural_similarity(a, b, channel_axis=2, **kw), channels


def project_ssim(tool, pa, pb):
    """(mean, [R, G, B]) from cig_ssim_png, or (None, stderr) when it refuses."""
    r = run([tool, pa, pb])
    if r.returncode != 0:
        return None, r.stderr.strip()
    v = [float(x) for x in r.stdout.split()]
    return v[3], v[:3]


def write_png(path, a):
    Image.fromarray(a, "RGB").save(path)


def read_png(path):
    return np.asarray(Image.open(path).convert("RGB"))


def agree(name, ours, theirs, channels_ours, channels_theirs):
    diff = max([abs(ours - theirs)] + [abs(x - y) for x, y in zip(channels_ours, channels_theirs)])
    worst[0] = max(worst[0], diff)
    print(f"{name}: cig {ours:.12f}, skimage {theirs:.12f}, max |difference| (mean, R, G, B) {diff:.3g}")
    if not diff <= TOLERANCE:
        fail(f"{name}: cig's SSIM {ours!r} (R, G, B {channels_ours}) against skimage's {theirs!r} "
             f"({channels_theirs}): {diff:.3g} > {TOLERANCE:.3g}")


def pair(work, tool, name, a, b):
    pa, pb = os.path.join(work, name + "_a.png"), os.path.join(work, name + "_b.png")
    write_png(pa, a)
    write_png(pb, b)
    ours, channels = project_ssim(tool, pa, pb)
    if ours is None:
        fail(f"{name}: cig_ssim_png refused a {a.shape[1]} x {a.shape[0]} pair: {channels}")
        return float("nan")
    theirs, theirs_channels = skimage_ssim(a, b)
    agree(name, ours, theirs, channels, theirs_channels)
    return ours


def smooth(h, w):
    y, x = np.mgrid[0:h, 0:w].astype(float)
    rgb = [128 + 90 * np.sin(x / 7.0 + c) * np.cos(y / 11.0 - c) for c in range(3)]
    return np.clip(np.stack(rgb, axis=2), 0, 255).astype(np.uint8)


def blocks(h, w):
    y, x = np.mgrid[0:h, 0:w]
    a = np.zeros((h, w, 3), np.uint8)
    a[..., 0] = np.where((x // 9 + y // 13) % 2 == 0, 40, 220)
    a[..., 1] = np.where(x > w // 3, 180, 30)
    a[..., 2] = np.where((x - w // 2) ** 2 + (y - h // 2) ** 2 < (h // 3) ** 2, 250, 60)
    return a


def shifted(a, dx, dy):
    """a moved right by dx and down by dy, the first rows and columns repeated."""
    b = np.roll(a, (dy, dx), axis=(0, 1))
    b[:dy] = b[dy]
    b[:, :dx] = b[:, dx:dx + 1]
    return b


def case_synthetic(cig, tool, work):
    rng = np.random.RandomState(2004)
    noisy = rng.randint(0, 256, (48, 64, 3)).astype(np.uint8)
    pa = os.path.join(work, "identical.png")
    write_png(pa, noisy)
    ours, channels = project_ssim(tool, pa, pa)
    if ours != 1.0 or channels != [1.0, 1.0, 1.0]:
        fail(f"identical: cig's SSIM is {ours!r} (R, G, B {channels}), not exactly 1")
    pair(work, tool, "identical", noisy, noisy.copy())

    base = smooth(96, 128)
    by_noise = []
    for sd in (4, 16, 48):
        b = np.clip(base + rng.normal(0, sd, base.shape), 0, 255).astype(np.uint8)
        by_noise.append((sd, pair(work, tool, f"noise_sd{sd}", base, b), skimage_ssim(base, b)[0]))
    for (sd0, ours0, theirs0), (sd1, ours1, theirs1) in zip(by_noise, by_noise[1:]):
        if not (ours1 < ours0 and theirs1 < theirs0):
            fail(f"noise sd {sd0} -> {sd1}: SSIM cig {ours0} -> {ours1}, skimage {theirs0} -> {theirs1}: not lower")

    edges = blocks(80, 112)
    for dx, dy in ((1, 0), (0, 1), (2, 1)):
        pair(work, tool, f"shift_{dx}_{dy}", edges, shifted(edges, dx, dy))
    pair(work, tool, "constant", np.full((32, 40, 3), (100, 50, 200), np.uint8),
         np.full((32, 40, 3), (110, 40, 180), np.uint8))
    negative = pair(work, tool, "negative", noisy, 255 - noisy)
    if not negative < 0:
        fail(f"an image against its negative: SSIM {negative}, expected below 0")
    pair(work, tool, "window_11x11", noisy[:11, :11], smooth(11, 11))
    pair(work, tool, "window_11x37", noisy[:11, :37], edges[:11, :37])

    small_a, small_b = noisy[:10, :30], edges[:10, :30]
    pa, pb = os.path.join(work, "small_a.png"), os.path.join(work, "small_b.png")
    write_png(pa, small_a)
    write_png(pb, small_b)
    ours, why = project_ssim(tool, pa, pb)
    if ours is not None or "smaller than the 11 x 11 window" not in why:
        fail(f"10 x 30: cig_ssim_png gave {ours!r} ({why!r}); expected a refusal naming the window")
    try:
        skimage_ssim(small_a, small_b)
        fail("10 x 30: skimage computed an SSIM; the check's premise (it refuses) no longer holds")
    except ValueError:
        print(f"10 x 30: both refuse ({why})")


def case_engines(cig, tool, work):
    scene = os.path.join(SOURCE, "scenes", "airfield.json")
    images = {}
    for engine in ("float", "segment", "quadtree"):
        out = os.path.join(work, engine)
        r = run([cig, "render", scene, "--frame", "0", "--channel", "1", "--engine", engine, "--out", out])
        found = glob.glob(os.path.join(out, "frame_0000_ch1_*.png"))
        if r.returncode != 0 or len(found) != 1:
            fail(f"cig render --engine {engine}: exit {r.returncode}, images {found}: {r.stderr[-1000:]}")
            return
        images[engine] = found[0]
    ref = read_png(images["float"])
    for engine in ("segment", "quadtree"):
        report = os.path.join(work, f"compare_{engine}.json")
        r = run([cig, "compare", scene, "--frame", "0", "--channel", "1", "--engine", engine, "--report", report])
        if r.returncode != 0:
            fail(f"cig compare --engine {engine}: exit {r.returncode}: {r.stderr[-1000:]}")
            continue
        with open(report) as f:
            row = json.load(f)["rows"][0]
        got = read_png(images[engine])
        mse = np.mean((got.astype(float) - ref.astype(float)) ** 2)
        psnr = 99.0 if mse == 0 else 10 * math.log10(255.0 ** 2 / mse)
        if abs(psnr - row["psnr"]) > 1e-9:
            fail(f"{engine}: compare's PSNR {row['psnr']} is not the rendered PNGs' {psnr}: other images")
        ours, channels = project_ssim(tool, images[engine], images["float"])
        if row["ssim"] != ours:
            fail(f"{engine}: compare's ssim {row['ssim']!r} is not cig_ssim_png's {ours!r} on the same images")
        theirs, theirs_channels = skimage_ssim(got, ref)
        agree(f"airfield frame 0 channel 1, {engine} vs float", row["ssim"], theirs, channels, theirs_channels)
        header, line = r.stdout.splitlines()[1:3]
        column = header.split().index("SSIM")
        if line.split()[column] != f"{row['ssim']:.4f}":
            fail(f"{engine}: the table's SSIM column shows {line.split()[column]}, the report {row['ssim']}")


def main():
    if len(sys.argv) != 5 or sys.argv[1] not in ("synthetic", "engines"):
        print(__doc__)
        return 2
    case, cig, tool, work = sys.argv[1:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    print(f"tolerance {TOLERANCE:.3g}")
    {"synthetic": case_synthetic, "engines": case_engines}[case](cig, tool, work)
    print(f"max |difference| from skimage: {worst[0]:.3g}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
