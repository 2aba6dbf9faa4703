"""The table of a benchmark that renders one scene with Cycles and rtpro in RUNS interleaved runs,
shared by cycles_subdivision_benchmark.sh and cycles_hair_benchmark.sh. Reads, in OUT:
cycles-rR.exr and cycles-rR.log ("cycles_render_seconds S"), rtpro-rR.exr and rtpro-rR.json
(--stats-json), rtpro.log ("rtpro_seconds S" per run: the whole process) and compare.json (`rtpro
compare cycles-r1.exr rtpro-r1.exr --json`); and, when present, cycles-alpha.exr and
rtpro-coverage.exr (each renderer's coverage of every pixel, 0 to 1) for the silhouettes.

usage: python3 peer_report.py OUT RUNS TITLE
"""
import json
import os
import re
import statistics
import subprocess
import sys

out, runs, title = sys.argv[1], int(sys.argv[2]), sys.argv[3]


def means(name):
    text = subprocess.run(["iinfo", "--stats", f"{out}/{name}.exr"], check=True, capture_output=True, text=True).stdout
    return [float(v) for v in re.search(r"Stats Avg: ([^(]+)", text).group(1).split()][:3]


def mean_of(name, *ops):
    """The mean of the image oiiotool makes of `ops`, kept as NAME.exr."""
    subprocess.run(["oiiotool", *ops, "-o", f"{out}/{name}.exr"], check=True)
    return means(name)[0]


def spread(xs):
    return f"{statistics.median(xs):.2f} ({min(xs):.2f}-{max(xs):.2f})"


cycles_s = [float(re.search(r"cycles_render_seconds ([\d.]+)", open(f"{out}/cycles-r{r}.log").read()).group(1))
            for r in range(1, runs + 1)]
rtpro_s = [float(s) for s in re.findall(r"rtpro_seconds ([\d.]+)", open(f"{out}/rtpro.log").read())]
phases = [sum(json.load(open(f"{out}/rtpro-r{r}.json"))["seconds"][k] for k in ("load", "build", "render"))
          for r in range(1, runs + 1)]
c, r = means("cycles-r1"), means("rtpro-r1")
rel = json.load(open(f"{out}/compare.json"))["rel_mse"]
print(f"{title}, {runs} interleaved runs")
print("| | Cycles | rtpro | rtpro / Cycles |")
print("|---|---|---|---|")
print("| mean R, G, B | " + ", ".join(f"{v:.4f}" for v in c) + " | " + ", ".join(f"{v:.4f}" for v in r) + " | " +
      ", ".join(f"{y / x:.4f}" for x, y in zip(c, r)) + " |")
print(f"| seconds, median (min-max) | {spread(cycles_s)} | {spread(rtpro_s)} | "
      f"{statistics.median(rtpro_s) / statistics.median(cycles_s):.2f} |")
print(f"| rtpro's load + build + render alone | | {spread(phases)} | "
      f"{statistics.median(phases) / statistics.median(cycles_s):.2f} |")
print(f"\nrelMSE of rtpro against Cycles (both at the same samples): {rel:.3g}")
if os.path.exists(f"{out}/cycles-alpha.exr") and os.path.exists(f"{out}/rtpro-coverage.exr"):
    a, b = f"{out}/cycles-alpha.exr", f"{out}/rtpro-coverage.exr"
    iou = mean_of("min", a, b, "--min") / mean_of("max", a, b, "--max")
    binary = ["--subc", "0.5", "--mulc", "1e9", "--clamp:min=0:max=1"]  # 1 where covered by more than half
    inside = [f"{out}/cycles-inside.exr", f"{out}/rtpro-inside.exr"]
    mean_of("cycles-inside", a, *binary), mean_of("rtpro-inside", b, *binary)
    either = mean_of("either", *inside, "--max")
    differ = mean_of("one-only", *inside, "--absdiff") / either
    print(f"silhouette: soft IoU (sum of min / sum of max coverage) {iou:.4f}; of the pixels either covers by more "
          f"than half, {differ * 100:.2f}% are covered so by one only")
print(f"images and logs: {out}")
