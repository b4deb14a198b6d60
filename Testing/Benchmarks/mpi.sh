#!/usr/bin/env bash
# The filters under ParaView's MPI engine (issue #14), as Markdown for RESULTS.md: Mesh Signed
# Distance by pieces on a 300^3 grid of CGAL's armadillo, and Shrink Wrap on a multiblock of four CGAL
# meshes, on 1, 2 and 3 ranks, threads per rank 1 or all cores, interleaved over three rounds; wall
# time of the slowest rank and peak memory per rank.
#   bash Testing/Benchmarks/mpi.sh <build folder> distance|wrap [nodes per axis]   (run.sh calls it)
set -euo pipefail
build="${1:-build}"
mode="${2:-distance}"
nodes="${3:-300}"
here="$(cd "$(dirname "$0")" && pwd)"
plugin="$build/lib/paraview-5.11/plugins/ShrinkWrap/ShrinkWrap.so"
meshes=()
for name in $([ "$mode" = distance ] && echo armadillo || echo camel hand ChineseDragon-10kv mech-holes-shark); do
  [ -f "$build/$name.vtk" ] ||
    pvpython "$here/mpi_bench.py" convert "$build/cgal/data/meshes/$name.off" "$build/$name.vtk" >/dev/null 2>&1
  meshes+=("$build/$name.vtk")
done
args=(distance "$nodes")
[ "$mode" = distance ] || args=(wrap)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() { # ranks threads
  local threads=(env)
  [ "$2" = all ] || threads=(env VTK_SMP_MAX_THREADS="$2")
  if [ "$1" = 1 ]; then
    "${threads[@]}" pvbatch "$here/mpi_bench.py" "${args[0]}" "$plugin" "$1 x $2" "${args[@]:1}" "${meshes[@]}" \
      2>/dev/null | grep "^|"
  else
    "${threads[@]}" mpiexec --oversubscribe -np "$1" pvbatch --symmetric "$here/mpi_bench.py" "${args[0]}" "$plugin" \
      "$1 x $2" "${args[@]:1}" "${meshes[@]}" 2>/dev/null | grep "^|"
  fi
}
echo "| ranks x threads per rank | ranks | seconds (slowest rank) | peak MiB per rank | MiB added by the update per rank | points on the smallest piece |"
echo "|---|---|---|---|---|---|"
for round in 1 2 3; do
  for config in "1 1" "2 1" "3 1" "1 all" "2 all"; do
    run $config
  done
done
