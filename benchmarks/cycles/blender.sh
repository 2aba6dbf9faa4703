# Sourced by the benchmark scripts that measure against Cycles: stops the script unless Debian's
# Blender is installed, and defines render_with_cycles.
command -v blender >/dev/null || { echo "blender not found: apt-get install blender (Debian package, 3.4)" >&2; exit 2; }

# run_blender SCRIPT LOG ARG...: Blender runs benchmarks/cycles/SCRIPT with the ARGs, from $out,
# its output in LOG; with the prefix in `pin` (pin_for, release_tree.sh), when it is set.
run_blender() {
  local script=$1 log=$2
  shift 2
  (cd "$out" && "${pin[@]}" blender -b --factory-startup --python "$root/benchmarks/cycles/$script" -- "$@" >"$log" 2>&1) ||
    { echo "blender failed, see $log" >&2; exit 1; }
}

# keep_rgb NAME: Cycles' $out/NAME.rgba.exr kept as $out/NAME.exr in R,G,B, the channels rtpro writes.
keep_rgb() { oiiotool "$out/$1.rgba.exr" --ch R,G,B -o "$out/$1.exr"; }

# render_with_cycles SCRIPT INPUT NAME LOG ARG...: Blender runs benchmarks/cycles/SCRIPT on INPUT
# with the ARGs; the image it writes, $out/NAME.rgba.exr, is kept as $out/NAME.exr (keep_rgb).
render_with_cycles() {
  local script=$1 input=$2 name=$3 log=$4
  shift 4
  run_blender "$script" "$log" "$input" "$out/$name.rgba.exr" "$@"
  keep_rgb "$name"
}

# timed_rtpro RUN ARG...: rtpro renders $out/rtpro.yaml into $out/rtpro-rRUN.exr with the ARGs, its
# statistics into $out/rtpro-rRUN.json and its wall-clock seconds, as "rtpro_seconds S", onto
# $out/rtpro.log (benchmarks/cycles/peer_report.py reads them).
timed_rtpro() {
  local run=$1 start
  shift
  start=$(date +%s.%N)
  "$build/rtpro" render "$out/rtpro.yaml" -o "$out/rtpro-r$run.exr" --quiet --no-journal --stats-json "$out/rtpro-r$run.json" "$@"
  echo "rtpro_seconds $(echo "$(date +%s.%N) - $start" | bc)" >>"$out/rtpro.log"
}

# coverage_and_compare ARG...: what benchmarks/cycles/peer_report.py compares beyond the images: rtpro
# renders $out/coverage.yaml (the scene with its surfaces white Lambert) with the ARGs and its
# albedo AOV, the coverage of each pixel, kept as $out/rtpro-coverage.exr; Cycles' alpha of run 1
# as $out/cycles-alpha.exr; and `rtpro compare` of run 1's images into $out/compare.json.
coverage_and_compare() {
  "$build/rtpro" render "$out/coverage.yaml" -o "$out/coverage.exr" --aov albedo --quiet --no-journal "$@"
  oiiotool "$out/coverage.exr" --ch albedo.R -o "$out/rtpro-coverage.exr"
  oiiotool "$out/cycles-r1.rgba.exr" --ch A -o "$out/cycles-alpha.exr"
  "$build/rtpro" compare "$out/cycles-r1.exr" "$out/rtpro-r1.exr" --json >"$out/compare.json" || true
}

# interleaved_runs SCRIPT ARG...: $runs times, Cycles renders benchmarks/cycles/SCRIPT into
# $out/cycles-rR.rgba.exr (and .exr, keep_rgb) with $size, $spp, $max_depth, $t and the ARGs, then
# rtpro renders $out/rtpro.yaml (timed_rtpro) on $backend with $t threads.
interleaved_runs() {
  local script=$1 r
  shift
  for r in $(seq "$runs"); do
    echo "run $r: Cycles, rtpro (${size}x$size, $spp spp, $t threads) ..." >&2
    run_blender "$script" "$out/cycles-r$r.log" "$out/cycles-r$r.rgba.exr" "$size" "$spp" "$max_depth" "$t" "$@"
    keep_rgb "cycles-r$r"
    timed_rtpro "$r" --backend "$backend" --threads "$t"
  done
}
