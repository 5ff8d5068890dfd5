#!/usr/bin/env python3
# Splits a callgrind profile of frame_driver (this folder) by stage (self instructions, M).
import re, subprocess, sys
stages = [
    ("shadow feelers, single", r"forEachBlocker|::occluded\(|feelerTransmittance|cachedFeeler"),
    # The eye hits' feelers as packets (ninth session): walkPacket<true, ...occludedPacket...>.
    ("shadow feelers, packets", r"walkPacket<true|occludedPacket"),
    ("eye packets (walk, set-up)", r"walkPacket|joinPacket|intersectPacket|triangleLanes|sphereLanes"),
    ("single nearest-hit walk", r"WideWalk<.*>::intersect\(|nearestFrom|Bvh::intersect\(|Scene::intersect"),
    ("exact tests, per-ray leaf set-up", r"Sphere::intersect|intersectSheared|Triangle::intersect|mtSetup|sphereSetup|finishHit|Primitive::"),
    ("shading in lanes (directLanes, traceFromPacket)", r"directLanes|traceFromPacket|shadeLanes"),
    ("shading, scalar", r"sampleLightsFrom|lightFactors|PhongModel::|pow|traceRay|spawnChildren|offsetRayOrigin|reflectDir|Tracer::trace|exp"),
    ("camera, tiles, rest", r"."),
]
def split(path):
    out = subprocess.run(["callgrind_annotate", "--threshold=100", "--auto=no", path], capture_output=True, text=True).stdout
    tot = {s: 0 for s, _ in stages}
    total = 0
    body = out.split("file:function", 1)[1]
    for line in body.splitlines():
        m = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+(.*)", line)
        if not m: continue
        n = int(m.group(1).replace(",", "")); fn = m.group(2)
        total += n
        for s, rx in stages:
            if re.search(rx, fn):
                tot[s] += n; break
    return tot, total
cols = [split(p) for p in sys.argv[1:]]
print("| stage (M instructions) | " + " | ".join(sys.argv[1:]) + " |")
for s, _ in stages:
    print(f"| {s} | " + " | ".join(f"{c[0][s]/1e6:.1f}" for c in cols) + " |")
print("| whole program | " + " | ".join(f"{c[1]/1e6:.1f}" for c in cols) + " |")
