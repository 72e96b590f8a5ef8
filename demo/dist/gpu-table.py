#!/usr/bin/env python3
"""The GPU figures of one gpu-figures.sh run, read from its bench folders' summary.json, never copied by hand.

    demo/dist/gpu-table.py OUT_DIR          # Markdown tables, as docs/benchmarks.md ("On a GPU") shows them
    demo/dist/gpu-table.py --tsv OUT_DIR    # one line per bench: figures.tsv

Per bench: frame time median, p99 and max (ms), triangles and draw calls (medians), the GPU time of the largest
passes (timer queries, medians of passGpuMsMedian) and the CPU time of every system (systemCpuMsMedian). The
benches are listed in the order gpu-figures.sh runs them. Standard library only: it runs wherever Python 3 does.
"""
import json
import os
import sys

TOP_PASSES = 4


def benches(out):
    names = sorted(n for n in os.listdir(out) if n.startswith("bench-") and os.path.isfile(
        os.path.join(out, n, "summary.json")))
    order = {"default": 0, "ultra": 1, "low": 2, "terrain": 3, "shadows": 4, "water": 5, "all": 6}
    def key(name):
        parts = name.split("-")  # bench-crossing-default-1920x1080, bench-peer-water-1920x1080
        width = int(parts[-1].split("x")[0])
        return (parts[1], width, order.get(parts[2], 9))
    for name in sorted(names, key=key):
        with open(os.path.join(out, name, "summary.json")) as f:
            yield name[len("bench-"):], json.load(f)


def passes(s, n=TOP_PASSES):
    top = sorted(s["passGpuMsMedian"].items(), key=lambda kv: -kv[1])[:n]
    return top, sum(s["passGpuMsMedian"].values())


def row(name, s):
    f = s["frameMs"]
    top, total = passes(s)
    systems = sorted(s["systemCpuMsMedian"].items(), key=lambda kv: -kv[1])
    return {
        "bench": name,
        "frame": "%.2f / %.2f / %.2f" % (f["median"], f["p99"], f["max"]),
        "triangles": "%.2f M" % (s["trianglesMedian"] / 1e6),
        "draws": "%d" % s["drawCallsMedian"],
        "gpu": "%.2f: " % total + ", ".join("%s %.2f" % kv for kv in top),
        "cpu": "%.2f: " % s["cpuMs"]["median"] + ", ".join("%s %.2f" % kv for kv in systems if kv[1] >= 0.01),
    }


def markdown(out):
    rows = [row(n, s) for n, s in benches(out)]
    if not rows:
        sys.exit("gpu-table: no bench-*/summary.json under " + out)
    print("| bench | frame ms median / p99 / max | triangles | draw calls | GPU ms: sum of passes, largest passes "
          "| CPU ms: frame, systems |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print("| %(bench)s | %(frame)s | %(triangles)s | %(draws)s | %(gpu)s | %(cpu)s |" % r)


def tsv(out):
    print("bench\tframe_median_ms\tframe_p99_ms\tgpu_sum_ms\ttop_passes_gpu_ms\tcpu_median_ms\tsystems_cpu_ms")
    for name, s in benches(out):
        top, total = passes(s)
        systems = sorted(s["systemCpuMsMedian"].items(), key=lambda kv: -kv[1])
        print("%s\t%.2f\t%.2f\t%.2f\t%s\t%.2f\t%s" % (
            name, s["frameMs"]["median"], s["frameMs"]["p99"], total, " ".join("%s=%.2f" % kv for kv in top),
            s["cpuMs"]["median"], " ".join("%s=%.2f" % kv for kv in systems)))


if __name__ == "__main__":
    args = sys.argv[1:]
    if args[:1] == ["--tsv"] and len(args) == 2:
        tsv(args[1])
    elif len(args) == 1 and not args[0].startswith("-"):
        markdown(args[0])
    else:
        sys.exit("usage: gpu-table.py [--tsv] OUT_DIR")
