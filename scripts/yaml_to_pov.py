#!/usr/bin/env python3
"""Translates an rtpro scene (spheres, point and directional lights, rtpro materials) into POV-Ray
3.7 SDL that renders the same picture in linear light, so POV-Ray can be measured beside rtpro on
the same work (benchmarks/povray_benchmark.sh, third_party_notes/povray.md).

Usage: yaml_to_pov.py SCENE.yaml OUT.pov [--size WxH] [--spp N] [--max-depth N] [--ini OUT.ini]

--size, --spp and --max-depth override the scene's values as `rtpro render` does. The image size
and the anti-aliasing live on POV-Ray's command line or in an .ini file, not in SDL: --ini writes
one with the size and the sampling that traces √spp × √spp jittered camera rays in every pixel.
Meshes and instances are refused (exit 2): POV-Ray would need its own mesh files for them.

How rtpro's model maps to POV-Ray 3.7 (source: source/backend/render/trace.cpp, 3.7-stable):
  ambient · C          finish ambient a, global ambient_light 1 (POV multiplies ambient by pigment)
  C ⊙ L · max(0, N·L)  diffuse 1, brilliance 1 (POV: |N·L| · diffuse · pigment · light)
  s · L · (R·L)^n      phong s, phong_size n (POV: R is the mirrored eye ray, as in rtpro)
  + refl × mirror      reflection {refl}: added on top, the surface colour is not reduced
  max_depth bounces    max_trace_level max_depth + 1 (POV counts the camera ray as level 1)
  no falloff           light_source without fade_distance/fade_power; adc_bailout 0: no cut-off
The camera uses look_at with `right -x*aspect`: POV-Ray builds its right vector as
cross(sky, direction), the left-handed convention, and a negative right vector mirrors that into
rtpro's cross(forward, up). POV's `angle` is horizontal: 2·atan(aspect · tan(vertical fov / 2)).
"""
import argparse
import math
import sys

import yaml

MATERIAL_DEFAULTS = {"color": [0.8, 0.8, 0.8], "specular": 0.5, "shininess": 10, "reflectivity": 0.0}
RENDER_DEFAULTS = {"spp": 16, "max_depth": 5, "ambient": 0.2, "background": [0.0, 0.0, 0.0]}


def fail(message):
    print(f"yaml_to_pov.py: {message}", file=sys.stderr)
    sys.exit(2)


def vec(v):
    return "<" + ", ".join(f"{float(x):.9g}" for x in v) + ">"


def parse_size(text):
    try:
        width, height = (int(part) for part in text.lower().split("x"))
    except ValueError:
        fail(f"--size must be WIDTHxHEIGHT, got '{text}'")
    return width, height


def pov_name(material):
    """A POV identifier for an rtpro material name (any string); the index keeps names distinct."""
    return "".join(c if c.isalnum() else "_" for c in material)


def camera_block(camera, width, height):
    position, look_at = camera["position"], camera["look_at"]
    up = camera.get("up", [0, 1, 0])
    aspect = width / height
    vertical = math.radians(float(camera.get("fov", 45)))
    horizontal = math.degrees(2 * math.atan(aspect * math.tan(vertical / 2)))
    return ("camera {\n  perspective\n"
            f"  location {vec(position)}\n"
            f"  sky {vec(up)}\n"
            "  up y\n"
            f"  right -x * {aspect:.12g}  // negative: rtpro's right is cross(forward, up)\n"
            f"  angle {horizontal:.12g}  // horizontal; rtpro's vertical fov is {camera.get('fov', 45)}\n"
            f"  look_at {vec(look_at)}\n"
            "}\n")


def material_block(name, material):
    m = {**MATERIAL_DEFAULTS, **(material or {})}
    finish = "diffuse 1 brilliance 1"
    if float(m["specular"]) > 0:
        finish += f" phong {float(m['specular']):.9g} phong_size {float(m['shininess']):.9g}"
    if float(m["reflectivity"]) > 0:
        finish += f" reflection {{ {float(m['reflectivity']):.9g} }}"
    return (f"#declare M_{name} = texture {{ pigment {{ rgb {vec(m['color'])} }}\n"
            f"  finish {{ ambient Ambient {finish} }} }}\n")


def far_distance(world):
    """Distance from the origin at which a parallel light sits beyond every sphere: POV-Ray tests
    shadows of parallel lights only up to the plane through the light's location."""
    reach = max((math.dist([0, 0, 0], s.get("center", [0, 0, 0])) + float(s.get("radius", 1)) for s in world),
                default=1.0)
    return 10 * reach + 1


def light_block(light, far):
    colour = [float(c) * float(light.get("intensity", 1)) for c in light.get("color", [1, 1, 1])]
    if light["type"] == "point":
        return f"light_source {{ {vec(light['position'])}, rgb {vec(colour)} }}\n"
    if light["type"] == "directional":
        d = [float(x) for x in light["direction"]]
        norm = math.sqrt(sum(x * x for x in d))
        source = [-far * x / norm for x in d]
        return f"light_source {{ {vec(source)}, rgb {vec(colour)} parallel point_at <0, 0, 0> }}\n"
    fail(f"light type '{light['type']}' is not supported")


def sphere_line(entry, materials):
    material = entry.get("material", "default")
    if material not in materials:
        fail(f"unknown material '{material}'")
    return (f"sphere {{ {vec(entry.get('center', [0, 0, 0]))}, {float(entry.get('radius', 1)):.9g} "
            f"texture {{ M_{pov_name(material)} }} }}\n")


def translate(scene, source, width, height, spp, max_depth):
    render = {**RENDER_DEFAULTS, **(scene.get("render") or {})}
    world = scene.get("world") or []
    for entry in world:
        if entry.get("type") != "sphere":
            fail(f"{source}: only spheres can be translated, found a world entry of type '{entry.get('type')}'")
    materials = {"default": dict(MATERIAL_DEFAULTS), **(scene.get("materials") or {})}
    used = sorted({e.get("material", "default") for e in world}, key=list(materials).index)

    out = [f"// Generated by scripts/yaml_to_pov.py from {source} ({width}x{height}, {spp} spp,"
           f" max depth {max_depth}); do not edit by hand.\n",
           f"// Render at +W{width} +H{height} with linear output (EXR, or PNG with File_Gamma=1.0).\n",
           "#version 3.7;\n",
           "global_settings {\n  assumed_gamma 1.0\n  ambient_light rgb 1\n"
           f"  max_trace_level {max_depth + 1}\n  adc_bailout 0\n}}\n",
           f"#declare Ambient = {float(render['ambient']):.9g};\n",
           f"background {{ rgb {vec(render['background'])} }}\n",
           camera_block(scene["camera"], width, height)]
    far = far_distance(world)
    out += [light_block(light, far) for light in scene.get("lights") or []]
    out += [material_block(pov_name(name), materials[name]) for name in used]
    out += [sphere_line(entry, materials) for entry in world]
    return "".join(out)


def ini_text(ini_file, pov_file, width, height, spp):
    n = math.isqrt(spp)
    if n * n != spp:
        fail(f"spp must be a perfect square, got {spp}")
    if n > 9:
        fail(f"POV-Ray 3.7 supersamples at most 9x9 rays per pixel (Antialias_Depth 9), got {spp} spp")
    aa = ("Antialias=off\n" if n == 1 else
          "; Method 1 with threshold 0 supersamples every pixel (the test is distance >= threshold):\n"
          f"; {n}x{n} jittered rays, one per stratum, plus the pixel's centre ray: {spp + 1} camera rays.\n"
          f"Antialias=on\nSampling_Method=1\nAntialias_Threshold=0.0\nAntialias_Depth={n}\n"
          "Jitter=on\nJitter_Amount=1.0\n")
    return (f"; Settings for {pov_file}, written by scripts/yaml_to_pov.py.\n"
            f"; Usage: povray {ini_file} +I{pov_file} +OOUT.exr [+WT<threads>]\n"
            f"Width={width}\nHeight={height}\n{aa}"
            "Output_File_Type=E  ; OpenEXR: linear half floats, like rtpro's EXR\n"
            "Output_Alpha=off\nDisplay=off\nPause_When_Done=off\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("output")
    parser.add_argument("--size", help="WIDTHxHEIGHT instead of the scene's resolution")
    parser.add_argument("--spp", type=int, help="samples per pixel instead of the scene's")
    parser.add_argument("--max-depth", type=int, help="mirror bounces instead of the scene's")
    parser.add_argument("--ini", help="also write POV-Ray settings (size, sampling, EXR output) here")
    args = parser.parse_args()

    with open(args.scene) as f:
        scene = yaml.safe_load(f)
    render = {**RENDER_DEFAULTS, **(scene.get("render") or {})}
    width, height = parse_size(args.size) if args.size else scene["camera"].get("resolution", [640, 480])
    spp = args.spp if args.spp is not None else int(render["spp"])
    max_depth = args.max_depth if args.max_depth is not None else int(render["max_depth"])

    text = translate(scene, args.scene, width, height, spp, max_depth)
    with open(args.output, "w") as f:
        f.write(text)
    if args.ini:
        with open(args.ini, "w") as f:
            f.write(ini_text(args.ini, args.output, width, height, spp))


if __name__ == "__main__":
    main()
