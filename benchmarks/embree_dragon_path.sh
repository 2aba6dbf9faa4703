# Sourced by the Embree pathtracer benchmarks: embree_dragon_path DIR SIZE fetches the Stanford
# dragon (scripts/fetch-dragon.sh) and sets `peer_scene` to the arguments that make Embree's
# `pathtracer` render it, and writes DIR/dragon_path.yaml, the same scene for rtpro's path
# integrator: the mesh alone in white Lambert (the peer's OBJ material without an MTL is Kd 1), one
# point light of radiant intensity 1 (the peer's "x y z r g b"), the camera of
# benchmarks/dragon_benchmark.sh, SIZE x SIZE, paths of at most 8 vertices. The OBJ has no
# normals, so both shade its facets.
embree_dragon_path() {
  local dir=$1 size=$2 mesh=$root/assets/dragon.obj
  "$root/scripts/fetch-dragon.sh" >/dev/null
  peer_scene=(-i "$mesh" --vp -0.16 0.2 0.3 --vi 0 0.115 0 --vu 0 1 0 --fov 38 --pointlight -0.6 1.2 0.8 1 1 1)
  cat >"$dir/dragon_path.yaml" <<EOF
rtpro: 1
camera: {position: [-0.16, 0.2, 0.3], look_at: [0.0, 0.115, 0.0], up: [0, 1, 0], fov: 38, resolution: [$size, $size]}
render: {integrator: path, spp: 1, max_depth: 8}
materials: {white: {type: diffuse, color: [1, 1, 1]}}
lights: [{type: point, position: [-0.6, 1.2, 0.8], intensity: 1}]
world: [{type: mesh, file: $mesh, material: white}]
EOF
}
