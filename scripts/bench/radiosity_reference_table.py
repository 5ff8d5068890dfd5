#!/usr/bin/env python3
# Issue 19 item 12: the table "surface, reference ± noise, ours at each setting" from
# build/bin/radiosity_reference's JSON and scripts/bench/radiosity_reference.py's (Cycles).
#   radiosity_reference_table.py ours.json ref1.json [ref2.json ...]   (prints Markdown)
# The reference leaves out each face's rim pixels (those not wholly on the face), so its mean
# misses a strip of 1 pixel along the edges, where B differs from the mean (corners): a bias
# proportional to the pixel size 1/N. With runs at several N it is removed by fitting
# B(N) = B_inf + k/N (least squares per surface and channel); the noise of B_inf is the runs'
# standard errors propagated through the fit's coefficients. The figure per setting is the
# largest |ours/ref − 1| over R, G, B (the channels are independent solves).
import json
import math
import sys

# --mc MC.json: tests/bench/radiosity_mc's brute-force path tracing, a second independent
# estimate, shown as its difference from the reference (± its own noise).
args = sys.argv[1:]
mc = None
if "--mc" in args:
    k = args.index("--mc")
    mc = json.load(open(args[k + 1]))
    del args[k:k + 2]
ours = json.load(open(args[0]))
refs = [json.load(open(p)) for p in args[1:]]
names = [s["name"] for s in ours["surfaces"]]
xs = [1.0 / r["pixels"] for r in refs]
camera = all(r.get("mode", "camera") == "camera" for r in refs)
if not camera:
    # Baked: no rim bias. The first run is the reference; the others check it (below).
    checks, refs = refs[1:], refs[:1]
    xs = xs[:1]
else:
    checks = []
if len(set(xs)) > 1:
    mx = sum(xs) / len(xs)
    sxx = sum((x - mx) ** 2 for x in xs)
    coef = [1.0 / len(xs) - mx * (x - mx) / sxx for x in xs]  # B_inf = Σ coef_i B_i
    how = "extrapolated to zero pixel size from N = %s px" % ", ".join(str(r["pixels"]) for r in refs)
else:
    coef = [1.0 / len(refs)] * len(refs)
    how = ("baked over the whole face" if not camera else "mean of the runs (one pixel size: rim bias not removed)")


def reference(name):
    runs = [next(s for s in r["surfaces"] if s["name"] == name) for r in refs]
    B = [sum(c * run["B"][ch] for c, run in zip(coef, runs)) for ch in range(3)]
    se = [math.sqrt(sum((c * run["stderr"][ch]) ** 2 for c, run in zip(coef, runs))) for ch in range(3)]
    rim = [runs[0]["B"][ch] / B[ch] - 1.0 for ch in range(3)]  # bias of the first run
    return B, se, max(rim, key=abs)


def worst(a, b):
    return max((a[c] / b[c] - 1.0 for c in range(3)), key=abs)


print("Reference: Cycles, %s; runs: %s.\n" % (how, "; ".join(
    "%d px, %d samples × %d seeds" % (r["pixels"], r["samples"], r["seeds"]) for r in refs)))
rimCol = " rim bias of the %d px run |" % refs[0]["pixels"] if camera else ""
if mc:
    rimCol += " Monte Carlo (radiosity_mc, %d paths) − reference, ± its noise |" % mc["paths"]
print("| surface | reference B (R, G, B) | noise (std. error), %% |" % () + rimCol + " " +
      " | ".join("%s: %.4g m, %s %d%s, stop %.0e, %d patches" % (
          s["name"], s["patch"], s["method"], s["res_or_k"],
          (", groups %.3g m (%d)" % (s["shooter"], s["groups"])) if s.get("groups") else "",
          s.get("tolerance", 1e-5), s["patches"]) for s in ours["settings"]) + " |")
print("|---|---|---:|" + ("---:|" if camera else "") + ("---:|" if mc else "") + "---:|" * len(ours["settings"]))
tot = [0.0] * len(ours["settings"])
noiseMax = 0.0
for name in [s["name"] for s in refs[0]["surfaces"]]:
    i = names.index(name)
    B, se, rim = reference(name)
    noise = max(100.0 * se[c] / B[c] for c in range(3))
    noiseMax = max(noiseMax, noise)
    cells = []
    for k, s in enumerate(ours["settings"]):
        d = worst(s["means"][i], B)
        tot[k] = max(tot[k], abs(d))
        cells.append("%+.2f%%%s" % (100 * d, "" if abs(d) <= 0.01 else " ✗"))
    rimCell = " %+.2f%% |" % (100 * rim) if camera else ""
    if mc:
        m = next(x for x in mc["surfaces"] if x["name"] == name)
        d = worst(m["B"], B)
        rimCell += " %+.2f%% ± %.2f |" % (100 * d, max(100 * m["stderr"][c] / m["B"][c] for c in range(3)))
    print("| %s | %.4f, %.4f, %.4f | %.2f |%s %s |" % (name, B[0], B[1], B[2], noise, rimCell, " | ".join(cells)))
print("| **worst** | | %.2f |%s %s |" % (noiseMax, (" |" if camera else "") + (" |" if mc else ""), " | ".join("%.2f%%" % (100 * t) for t in tot)))
for extra in checks:
    big, bigSigma = 0.0, 0.0
    for r2 in extra["surfaces"]:
        r1 = next(x for x in refs[0]["surfaces"] if x["name"] == r2["name"])
        for c in range(3):
            d = abs(r2["B"][c] / r1["B"][c] - 1.0)
            sig = math.hypot(r1["stderr"][c], r2["stderr"][c]) / r1["B"][c]
            big = max(big, d)
            bigSigma = max(bigSigma, d / sig if sig > 0 else 0.0)
    print("\nCheck run (%d texels, %d samples × %d seeds) against the reference: largest difference %.2f%%, "
          "at most %.1f combined standard errors." % (extra["pixels"], extra["samples"], extra["seeds"], 100 * big, bigSigma))
