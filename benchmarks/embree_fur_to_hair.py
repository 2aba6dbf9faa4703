#!/usr/bin/env python3
"""Turns a curve model of Embree's tutorial XML format (furBall_A.xml and its .bin.gz, from
Debian's embree-tools in /usr/share/doc/embree3/models) into a Cem Yuksel .hair file, so rtpro
renders the very fur Embree's `pathtracer -c furBall_A.ecs` does (benchmarks/fur_ball.yaml).

The XML names its arrays by byte offset and element count in the .bin: <indices> (one uint32 per
segment: its first control point) and <positions> (x, y, z, radius as float32). Segments whose
first points follow one another (i, i+1, ...) share their joints and make one strand. The .hair
thickness is the diameter (twice Embree's radius).

usage: embree_fur_to_hair.py [MODEL.xml] OUTPUT.hair
"""
import gzip
import pathlib
import struct
import sys
import xml.etree.ElementTree as ET

DEFAULT_MODEL = "/usr/share/doc/embree3/models/furBall_A.xml"


def read_model(xml_path):
    root = ET.parse(xml_path).getroot()
    curves = root.find(".//RoundLineSegments")
    if curves is None:
        curves = root.find(".//LineSegments")
    if curves is None:
        sys.exit(f"{xml_path}: no <RoundLineSegments> or <LineSegments> element")
    binary = pathlib.Path(str(xml_path) + ".bin")
    gz = pathlib.Path(str(binary) + ".gz")
    if not binary.exists() and not gz.exists():
        binary = pathlib.Path(xml_path).with_suffix(".bin")
        gz = pathlib.Path(str(binary) + ".gz")
    data = binary.read_bytes() if binary.exists() else gzip.decompress(gz.read_bytes())

    def array(tag, fmt, width):
        element = curves.find(tag)
        offset, count = int(element.get("ofs")), int(element.get("size"))
        size = struct.calcsize(fmt) * width * count
        if offset + size > len(data):
            sys.exit(f"{xml_path}: <{tag}> runs past the end of its .bin ({offset + size} > {len(data)} bytes)")
        return struct.unpack_from(f"<{width * count}{fmt}", data, offset)

    indices = array("indices", "I", 1)
    positions = array("positions", "f", 4)
    return list(indices), positions


def strands_of(indices):
    """Runs of segments i, i+1, ...: each a strand of (first point, point count)."""
    strands = []
    start = prev = None
    for first in indices:
        if prev is not None and first == prev + 1:
            prev = first
            continue
        if start is not None:
            strands.append((start, prev - start + 2))
        start = prev = first
    if start is not None:
        strands.append((start, prev - start + 2))
    return strands


def write_hair(path, strands, positions):
    points, thickness, segments = [], [], []
    for first, count in strands:
        if count - 1 > 65535:
            sys.exit(f"a strand of {count} points does not fit a .hair file's 16-bit segment count")
        segments.append(count - 1)
        for p in range(first, first + count):
            x, y, z, r = positions[4 * p:4 * p + 4]
            points += [x, y, z]
            thickness.append(2.0 * r)
    point_count = len(thickness)
    header = struct.pack("<4sIIIIfffff88s", b"HAIR", len(segments), point_count, 1 | 2 | 4, 0, 0.0, 1.0,
                         0.0, 0.0, 0.0, b"converted from Embree's tutorial XML by rtpro".ljust(88, b" "))
    with open(path, "wb") as out:
        out.write(header)
        out.write(struct.pack(f"<{len(segments)}H", *segments))
        out.write(struct.pack(f"<{3 * point_count}f", *points))
        out.write(struct.pack(f"<{point_count}f", *thickness))
    return len(segments), point_count


def main():
    args = sys.argv[1:]
    if len(args) == 1:
        args = [DEFAULT_MODEL] + args
    if len(args) != 2:
        sys.exit(__doc__)
    indices, positions = read_model(args[0])
    strands, points = write_hair(args[1], strands_of(indices), positions)
    print(f"{args[1]}: {strands} strands, {points} points, {len(indices)} segments from {args[0]}")


if __name__ == "__main__":
    main()
