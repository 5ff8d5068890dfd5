#!/usr/bin/env python3
# Issue 19 item 12: the table "surface, reference ± noise, ours at each setting" from
# build/bin/radiosity_reference's JSON and scripts/bench/radiosity_reference.py's (Cycles).
# Luminance-free comparison per channel: the figure is the largest |ours/ref − 1| over R, G, B
# (B's per channel are independent solves, so each must be within the tolerance).
#   radiosity_reference_table.py ours.json ref.json [ref2.json ...]  (prints Markdown)
import json
import math
import sys

ours = json.load(open(sys.argv[1]))
refs = [json.load(open(p)) for p in sys.argv[2:]]
ref = refs[0]
names = [s["name"] for s in ours["surfaces"]]


def worst(a, b):
    return max((a[c] / b[c] - 1.0 for c in range(3)), key=abs)


print("| surface | reference B (R, G, B) ± noise (std. error) | noise, % |" +
      "".join(" %s: %s %d, %d patches |" % (s["name"], s["method"], s["res_or_k"], s["patches"]) for s in ours["settings"]))
print("|---|---|---|" + "---|" * len(ours["settings"]))
tot = [0] * len(ours["settings"])
for r in ref["surfaces"]:
    i = names.index(r["name"])
    B, se = r["B"], r["stderr"]
    noise = max(100.0 * se[c] / B[c] for c in range(3))
    cells = []
    for k, s in enumerate(ours["settings"]):
        d = worst(s["means"][i], B)
        tot[k] = max(tot[k], abs(d))
        cells.append("%+.2f%%%s" % (100 * d, "" if abs(d) <= 0.01 else " ✗"))
    print("| %s | %.4f, %.4f, %.4f ± %.1e, %.1e, %.1e | %.3f | %s |" % (
        r["name"], B[0], B[1], B[2], se[0], se[1], se[2], noise, " | ".join(cells)))
print("| **worst** | | | %s |" % " | ".join("%.2f%%" % (100 * t) for t in tot))
for extra in refs[1:]:
    # Another reference run (other sample count / seeds): its difference from the first,
    # against the two runs' combined standard errors.
    big = 0.0
    for r2 in extra["surfaces"]:
        r1 = next(x for x in ref["surfaces"] if x["name"] == r2["name"])
        for c in range(3):
            big = max(big, abs(r2["B"][c] / r1["B"][c] - 1.0))
    print("\nReference at %d samples × %d seeds against %d × %d: largest difference %.3f%%." % (
        extra["samples"], extra["seeds"], ref["samples"], ref["seeds"], 100 * big))
