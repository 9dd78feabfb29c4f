#!/usr/bin/env python3
# Usage: upper_arm_side.py DATASET TRACK. See tracker/gomez/GOMEZ.md.
# What a correct front/back choice for the upper arms would give: where the tracked upper arm's
# depth offset has the wrong sign (|dz true| > 40 mm), the elbow is moved along its own ray to the
# mirrored depth about the shoulder and the wrist along its ray by the same depth change.
import sys
from bone_length import load, cam, tocam, norm, sub
ds, tr = sys.argv[1], sys.argv[2]
K, R, t = cam(ds + '/calibration/opencv.yaml')
G, T = load(ds + '/gt/joints3d.csv'), load(tr + '/joints3d.csv')
b = a = 0.0; n = 0
for f in sorted(T):
    if f not in G: continue
    for s in 'lr':
        gs, ge, gw = (tocam(G[f][s+j], R, t) for j in ('_shoulder', '_elbow', '_radiocarpal'))
        ts, te, tw = (tocam(T[f][s+j], R, t) for j in ('_shoulder', '_elbow', '_radiocarpal'))
        b += norm(sub(te, ge)) + norm(sub(tw, gw))
        dzg, dzt = ge[2]-gs[2], te[2]-ts[2]
        if abs(dzg) > 0.04 and dzg*dzt < 0:
            z2 = ts[2] - dzt; ne = [x*z2/te[2] for x in te]
            zw = tw[2] + (z2 - te[2]); nw = [x*zw/tw[2] for x in tw]
            te, tw = ne, nw
        a += norm(sub(te, ge)) + norm(sub(tw, gw)); n += 2
print(f'elbows+wrists mean 3D error {1000*b/n:.1f} -> {1000*a/n:.1f} mm with the upper arms on the right side')
