#!/usr/bin/env python3
"""Charts mygl-bench's CSV: time per frame against pixels differing from llvmpipe, one point per
method per scene, one panel per frame size; the reference renderers are marked."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    with open(csv_path) as f:
        rows = list(csv.DictReader(f))
    sizes = sorted({r["size"] for r in rows}, key=lambda s: int(s.split("x")[0]))
    variants = sorted({r["variant"] for r in rows})
    scenes = sorted({r["scene"] for r in rows})
    shapes = "osD^v<>phX*Pd8H"  # repeated when scenes outnumber them
    markers = {scene: shapes[i % len(shapes)] for i, scene in enumerate(scenes)}
    colors = {v: plt.cm.tab10(i % 10) for i, v in enumerate(variants)}
    fig, axes = plt.subplots(1, len(sizes), figsize=(7 * len(sizes) + 2, 5.5), squeeze=False)
    for ax, size in zip(axes[0], sizes):
        for r in (r for r in rows if r["size"] == size):
            reference = r["reference"] == "1"
            ax.scatter(float(r["median_ms"]), int(r["differing"]) + 1, marker=markers[r["scene"]],
                       color=colors[r["variant"]], s=90 if reference else 50,
                       edgecolors="black" if reference else "none")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("median time per frame (ms, log)")
        ax.set_ylabel("pixels differing from llvmpipe + 1 (log)")
        ax.set_title(f"{size}: speed against accuracy")
        ax.grid(True, which="both", alpha=0.3)
    handles = [plt.Line2D([], [], linestyle="", marker="o", color=colors[v], label=v) for v in variants]
    handles += [plt.Line2D([], [], linestyle="", marker=markers[s], color="gray", label=s) for s in scenes]
    fig.legend(handles=handles, loc="center right", fontsize=8)
    fig.subplots_adjust(right=0.84 if len(sizes) > 1 else 0.72)
    fig.savefig(png_path, dpi=90)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
