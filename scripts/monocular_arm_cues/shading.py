#!/usr/bin/env python3
# Usage: [FIT_FRAMES=N] shading.py DATASET TRACK; the scene's light is that of
# scenes/monocular_gestures.yaml unless LIGHT=fit. See tracker/gomez/GOMEZ.md.
# Does Lambert shading tell an arm bone from its depth flip (dz -> -dz, the projection kept)?
# Per bone: the mean grey of its pixels (the render's parts labels) against a cylinder's
# predicted Lambert mean for the true direction and for the flipped one (a per-bone affine fit).
import math, os, subprocess, sys
sys.path.insert(0, __import__('os').path.dirname(__file__))
from bone_length import load, cam, tocam, norm, sub, dot
ds, tr = sys.argv[1], sys.argv[2]
K, R, t = cam(ds + '/calibration/opencv.yaml')
G, T = load(ds + '/gt/joints3d.csv'), load(tr + '/joints3d.csv')
FIT = int(os.environ.get('FIT_FRAMES', '100000'))
def light_cam(Lw):
    n = norm(Lw); return [sum(R[3*i+j]*Lw[j] for j in range(3))/n for i in range(3)]
labels = {24: ('l_shoulder', 'l_elbow'), 25: ('l_elbow', 'l_radiocarpal'),
          29: ('r_shoulder', 'r_elbow'), 30: ('r_elbow', 'r_radiocarpal')}
def ppm(p):
    b = subprocess.run(['convert', p, 'ppm:-'], capture_output=True).stdout
    parts = b.split(b'\n', 3); return parts[3]
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def pred(a, mid, Lc):
    a = [x/norm(a) for x in a]; v = [-x for x in mid]; v = [x/norm(v) for x in v]
    e1 = cross(a, [0, 0, 1] if abs(a[2]) < 0.9 else [1, 0, 0]); e1 = [x/norm(e1) for x in e1]
    e2 = cross(a, e1); sw = sv = 0.0
    for k in range(72):
        p = 2*math.pi*k/72; nn = [math.cos(p)*x + math.sin(p)*y for x, y in zip(e1, e2)]
        w = max(0.0, dot(nn, v)); sw += w; sv += w*max(0.0, dot(nn, Lc))
    return sv/sw
rows = []
for f in sorted(G)[::2]:
    if f not in T: continue
    rgb = ppm(f'{ds}/cam00/rgb/{f:06d}.png'); lab = ppm(f'{ds}/cam00/parts/{f:06d}.png')
    sums = {k: [0.0, 0] for k in labels}
    for i in range(0, len(lab), 3):
        k = lab[i]
        if k in sums:
            sums[k][0] += (rgb[i] + rgb[i+1] + rgb[i+2]) / 3.0; sums[k][1] += 1
    for k, (a, b) in labels.items():
        if sums[k][1] < 30: continue
        ga, gb = tocam(G[f][a], R, t), tocam(G[f][b], R, t)
        ta, tb = tocam(T[f][a], R, t), tocam(T[f][b], R, t)
        d = sub(gb, ga); mid = [(x+y)/2 for x, y in zip(ga, gb)]
        dflip = [d[0], d[1], -d[2]]; dt = sub(tb, ta)
        rows.append((k, sums[k][0]/sums[k][1], d, dflip, dt, mid))
def affine(xs, ys):
    m = len(xs); mx, my = sum(xs)/m, sum(ys)/m
    A = sum((x-mx)*(y-my) for x, y in zip(xs, ys)) / max(1e-9, sum((x-mx)**2 for x in xs))
    return A, my - A*mx
def fit_error(Lc):
    e = 0.0
    for k in labels:
        rs = [r for r in rows if r[0] == k][:FIT]
        xs = [pred(r[2], r[5], Lc) for r in rs]; ys = [r[1] for r in rs]; A, B = affine(xs, ys)
        e += sum((y - A*x - B)**2 for x, y in zip(xs, ys)) if A > 0 else 1e18
    return e
# LIGHT=fit: the light's direction from the first FIT_FRAMES sampled frames (a 10 degree grid)
# instead of the scene's
Lc = light_cam([0.3, 1.0, 0.4])
if os.environ.get('LIGHT') == 'fit':
    grid = [[math.cos(math.radians(el))*math.sin(math.radians(az)), math.sin(math.radians(el)),
             math.cos(math.radians(el))*math.cos(math.radians(az))]
            for el in range(-30, 91, 10) for az in range(0, 360, 10)]
    Lw = min(grid, key=lambda L: fit_error(light_cam(L))); Lc = light_cam(Lw)
    print('light (world, towards it): ' + ' '.join(f'{x:.2f}' for x in Lw))
rows = [(k, g, pred(d, mid, Lc), pred(df, mid, Lc), pred(dt, mid, Lc), d[2], dt[2])
        for k, g, d, df, dt, mid in rows]
for k in labels:
    rs = [r for r in rows if r[0] == k]
    A, B = affine([r[2] for r in rs[:FIT]], [r[1] for r in rs[:FIT]])
    res = [abs(r[1] - (A*r[2] + B)) for r in rs]; m = len(rs)
    deep = [r for r in rs if abs(r[5]) > 0.04]
    sep = sum(1 for r in deep if abs(r[1]-(A*r[2]+B)) < abs(r[1]-(A*r[3]+B)))
    gap = sum(abs(A*(r[2]-r[3])) for r in deep) / max(1, len(deep))
    wrong = [r for r in deep if r[5]*r[6] < 0]
    sepw = sum(1 for r in wrong if abs(r[1]-(A*r[2]+B)) < abs(r[1]-(A*r[4]+B)))
    print(f'{labels[k][0]}: frames {m} slope {A:.0f} fit residual {sum(res)/m:.1f} grey; '
          f'|dz|>40mm {len(deep)}: truth nearer than its flip {sep}, mean flip gap {gap:.1f} grey; '
          f'tracked sign wrong {len(wrong)}: truth nearer than tracked {sepw}')
