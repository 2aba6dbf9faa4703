# Sourced by the benchmark scripts that measure against Cycles: stops the script unless Debian's
# Blender is installed, and defines render_with_cycles.
command -v blender >/dev/null || { echo "blender not found: apt-get install blender (Debian package, 3.4)" >&2; exit 2; }

# render_with_cycles SCRIPT INPUT NAME LOG ARG...: Blender runs benchmarks/cycles/SCRIPT on INPUT
# with the ARGs, from $out, its output in LOG; the image it writes, $out/NAME.rgba.exr, is kept as
# $out/NAME.exr in R,G,B, the channels rtpro writes.
render_with_cycles() {
  local script=$1 input=$2 name=$3 log=$4
  shift 4
  (cd "$out" && blender -b --factory-startup --python "$root/benchmarks/cycles/$script" -- \
    "$input" "$out/$name.rgba.exr" "$@" >"$log" 2>&1) || { echo "blender failed, see $log" >&2; exit 1; }
  oiiotool "$out/$name.rgba.exr" --ch R,G,B -o "$out/$name.exr"
}
