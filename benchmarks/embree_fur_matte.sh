# Sourced by the fur benchmarks: embree_fur_matte DIR writes DIR/furBall_matte.ecs (with its .xml
# and .xml.bin): Embree's furBall_A view and fibres, the fibres given Embree's "Matte" material in
# the colour of its "Hair" one (Debian's pathtracer aborts on "Hair" past a path length of 1), as
# benchmarks/fur_ball.yaml gives rtpro's; and benchmarks/fur_ball.hair, the same fibres for rtpro.
embree_fur_matte() {
  local dir=$1 models=/usr/share/doc/embree3/models
  [ -f "$root/benchmarks/fur_ball.hair" ] || python3 "$root/benchmarks/embree_fur_to_hair.py" "$root/benchmarks/fur_ball.hair"
  gunzip -c "$models/furBall_A.bin.gz" >"$dir/furBall_matte.xml.bin"
  python3 - "$models/furBall_A.xml" "$dir/furBall_matte.xml" <<'PY'
import re, sys
xml = open(sys.argv[1]).read()
matte = '<material><code>"Matte"</code><parameters><float3 name="reflectance">0.64 0.456 0.256</float3></parameters></material>'
open(sys.argv[2], "w").write(re.sub(r"<material>.*</material>", matte, xml, flags=re.S))
PY
  sed 's/furBall_A\.xml/furBall_matte.xml/' "$models/furBall_A.ecs" >"$dir/furBall_matte.ecs"
}
