"""The log-log plot of scaling.sh: time and peak resident memory against the output's vertices, ours
and alpha wrap's, one marker per mesh.

  pvpython scaling_plot.py scaling.tsv scaling.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1]), delimiter="\t"))
markers = {}
figure, (times, memory) = plt.subplots(1, 2, figsize=(11, 4.5))
for mesh in sorted({r["mesh"] for r in rows}):
    marker = "osD^v"[len(markers) % 5]
    markers[mesh] = marker
    for method, colour, label in (("ours", "tab:blue", "Shrink Wrap"), ("alpha", "tab:orange", "alpha wrap")):
        pick = sorted((r for r in rows if r["mesh"] == mesh and r["method"] == method),
                      key=lambda r: float(r["vertices"]))
        x = [float(r["vertices"]) for r in pick]
        times.plot(x, [float(r["seconds"]) for r in pick], marker=marker, color=colour,
                   label="%s, %s" % (label, mesh))
        memory.plot(x, [float(r["peak_mb"]) for r in pick], marker=marker, color=colour,
                    label="%s, %s" % (label, mesh))
for axes, title in ((times, "time (s)"), (memory, "peak resident memory (MB)")):
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("output vertices")
    axes.set_ylabel(title)
    axes.grid(True, which="both", alpha=0.3)
times.legend(fontsize=7)
figure.suptitle("L = Gap Size = alpha = diagonal / N, N = 100, 200, 400 (labels: mesh)")
figure.tight_layout()
figure.savefig(sys.argv[2], dpi=90)
