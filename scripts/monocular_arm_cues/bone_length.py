#!/usr/bin/env python3
# Usage: bone_length.py DATASET TRACK (a one-camera dataset and its monocular track). Per arm bone,
# the tracked depth offset between its ends against the truth's; see tracker/gomez/GOMEZ.md.
# Does the bone-length cue (|dz| = sqrt(L^2 - l^2), sign from the pose) separate the truth from the
# tracked pose? Per arm bone: the tracked depth offset between its ends against the truth's.
import csv, math, re, sys
from collections import defaultdict
def load(p):
    d = defaultdict(dict)
    for r in csv.DictReader(open(p)):
        d[int(r['frame'])][r['joint']] = (float(r['x']), float(r['y']), float(r['z']))
    return d
def cam(p):
    t = open(p).read()
    def mat(name):
        m = re.search(r'\s' + name + r': !!opencv-matrix.*?data: \[(.*?)\]', t, re.S)
        return [float(x) for x in m.group(1).replace('\n', ' ').split(',')]
    return mat('K'), mat('R'), mat('t')
def tocam(X, R, t):
    return [sum(R[3*i+j]*X[j] for j in range(3)) + t[i] for i in range(3)]
def proj(Xc, K):
    return (K[0]*Xc[0]/Xc[2] + K[2], K[4]*Xc[1]/Xc[2] + K[5])
def norm(a): return math.sqrt(sum(x*x for x in a))
def sub(a, b): return [x-y for x, y in zip(a, b)]
def dot(a, b): return sum(x*y for x, y in zip(a, b))
if __name__ == '__main__':
    ds, tr = sys.argv[1], sys.argv[2]
    K, R, t = cam(ds + '/calibration/opencv.yaml')
    G, T = load(ds + '/gt/joints3d.csv'), load(tr + '/joints3d.csv')
    bones = [(s+'_shoulder', s+'_elbow') for s in 'lr'] + [(s+'_elbow', s+'_radiocarpal') for s in 'lr']
    acc = defaultdict(list)
    for f in sorted(T):
        if f not in G: continue
        for a, b in bones:
            name = ('upper' if 'shoulder' in a else 'fore')
            ga, gb = tocam(G[f][a], R, t), tocam(G[f][b], R, t)
            ta, tb = tocam(T[f][a], R, t), tocam(T[f][b], R, t)
            dzg, dzt = gb[2]-ga[2], tb[2]-ta[2]
            Lg, Lt = norm(sub(gb, ga)), norm(sub(tb, ta))
            # the cue with the true end's ray and the tracked start: the point on the ray at the
            # tracked bone length, on the tracked side (the best the cue can do given exact 2D)
            u = [gb[0]/gb[2], gb[1]/gb[2], 1.0]; n = norm(u); u = [x/n for x in u]
            up = dot(u, ta); disc = up*up - dot(ta, ta) + Lt*Lt
            if disc < 0: s = up
            else:
                r = math.sqrt(disc); c1, c2 = up - r, up + r
                z1, z2 = c1*u[2]-ta[2], c2*u[2]-ta[2]
                s = c1 if (z1 - dzt)**2 < (z2 - dzt)**2 else c2
            dzc = s*u[2] - ta[2]
            lg = math.dist(proj(ga, K), proj(gb, K)); lt = math.dist(proj(ta, K), proj(tb, K))
            ratio = math.sqrt(max(0, 1 - (dzg/Lg)**2))  # how much of the bone lies across the ray
            k = name
            acc[k+' |dz err| mm'].append(abs(dzt-dzg)*1000)
            acc[k+' |dz err| cue(true 2D) mm'].append(abs(dzc-dzg)*1000)
            wrong = abs(dzg) > 0.04 and dzg*dzt < 0
            acc[k+' sign wrong %'].append(100.0 if wrong else 0.0)
            acc[k+' |dz err| on sign-wrong mm (share of sum %)'].append(abs(dzt-dzg)*1000 if wrong else 0.0)
            acc[k+' |L err| mm'].append(abs(Lt-Lg)*1000)
            acc[k+' |l err| px'].append(abs(lt-lg))
            acc[k+' across-ray bones (l/L>0.9) %'].append(100.0 if ratio > 0.9 else 0.0)
            if ratio > 0.9: acc[k+' |dz err| where l/L>0.9 mm'].append(abs(dzt-dzg)*1000)
            else: acc[k+' |dz err| where l/L<=0.9 mm'].append(abs(dzt-dzg)*1000)
        for s in 'lr':
            acc['shoulder along-ray-ish |z err| mm'].append(abs(tocam(T[f][s+'_shoulder'], R, t)[2]-tocam(G[f][s+'_shoulder'], R, t)[2])*1000)
            acc['wrist |z err| mm'].append(abs(tocam(T[f][s+'_radiocarpal'], R, t)[2]-tocam(G[f][s+'_radiocarpal'], R, t)[2])*1000)
    for k in sorted(acc):
        v = acc[k]
        if 'share' in k:
            tot = sum(acc[k.split(' |')[0]+' |dz err| mm'])
            print(f'{k}: {100*sum(v)/tot:.0f}')
        else:
            print(f'{k}: {sum(v)/len(v):.1f}')
