#!/usr/bin/env bash
# Issue 62's scaling: Shrink Wrap at Target Edge Length = Gap Size = diagonal / N (Resolution 1.5 N)
# beside CGAL's alpha wrap at alpha = diagonal / N, each run in a fresh process (its peak resident
# memory is that run's), on three CGAL meshes; then the log-log plot of time and peak memory against
# the output's vertices.
#   bash Testing/Benchmarks/scaling.sh <build folder> [meshes=camel,fandisk,armadillo] [sizes=100,200,400]
# Prints the rows (Markdown) and writes <build>/scaling.tsv and <build>/scaling.png.
set -euo pipefail
build="${1:-build}"
meshes="${2:-camel,fandisk,armadillo}"
sizes="${3:-100,200,400}"
here="$(cd "$(dirname "$0")" && pwd)"
bench="$build/bin/BenchShrinkWrapCGAL6"
[ -x "$bench" ] || bench="$build/bin/BenchShrinkWrap"
table="$build/scaling.tsv"
printf 'mesh\tmethod\tN\tvertices\tseconds\tpeak_mb\tmean_wt\tmean_tw\n' > "$table"
echo "| target | method | vertices | time s | mean w→t | mean t→w | max w→t | max t→w | self-int. pairs (CGAL) | closed manifold | genus | angles < 20° | status | peak memory |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for mesh in ${meshes//,/ }; do
  for n in ${sizes//,/ }; do
    for side in ours alpha; do
      out="$("$bench" "$build/cgal/data/meshes" --meshes "$mesh" --sizes "$n" --only "$side" 2>/dev/null |
        grep '^| \(Shrink\|alpha\)\|^peak')"
      row="$(echo "$out" | grep '^|')"
      peak="$(echo "$out" | sed -n 's/^peak resident memory: \([0-9]*\) MB/\1/p')"
      echo "| $mesh ${row%|} | $peak MB |"
      # | method | vertices | time s | mean w→t | mean t→w | ...
      echo "$row" | awk -F'|' -v m="$mesh" -v s="$side" -v n="$n" -v p="$peak" \
        '{ gsub(/ |%/, "", $3); gsub(/ |%/, "", $4); gsub(/ |%/, "", $5); gsub(/ |%/, "", $6);
           printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", m, s, n, $3, $4, p, $5, $6 }' >> "$table"
    done
  done
done
"$here/../run-with-x.sh" pvpython "$here/scaling_plot.py" "$table" "$build/scaling.png" >/dev/null 2>&1 ||
  pvpython "$here/scaling_plot.py" "$table" "$build/scaling.png"
echo "plot: $build/scaling.png"
