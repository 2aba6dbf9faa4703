#!/usr/bin/env python3
"""Converts a triangle-mesh PLY (ascii or binary, vertex x y z + face index lists) to OBJ.

A one-off asset step for scripts/fetch-dragon.sh, deliberately independent of rtpro's own PLY
loader so the benchmark's OBJ input does not depend on the code it measures. ASCII coordinates are
copied as written, so the OBJ holds exactly the PLY's numbers.
Usage: ply_to_obj.py input.ply output.obj
"""
import struct
import sys

SCALAR_FORMATS = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B",
    "short": "h", "int16": "h", "ushort": "H", "uint16": "H",
    "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_header(stream):
    if stream.readline().strip() != b"ply":
        sys.exit("not a PLY file")
    encoding, elements = None, []
    while True:
        line = stream.readline()
        if not line:
            sys.exit("PLY header has no end_header")
        words = line.decode("ascii").split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "end_header":
            return encoding, elements
        if words[0] == "format":
            encoding = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            if words[1] == "list":
                elements[-1][2].append((words[4], SCALAR_FORMATS[words[2]], SCALAR_FORMATS[words[3]]))
            else:
                elements[-1][2].append((words[2], SCALAR_FORMATS[words[1]], None))


def ascii_rows(stream):
    for line in stream:
        yield line.split()


def binary_row(stream, order, properties):
    """One element's values as a list of scalars (lists flattened behind their count)."""
    row = []
    for _, scalar, item in properties:
        size = struct.calcsize(scalar)
        (value,) = struct.unpack(order + scalar, stream.read(size))
        if item is None:
            row.append(value)
        else:
            row.append(value)
            row.extend(struct.unpack(order + item * value, stream.read(struct.calcsize(item) * value)))
    return row


def convert(source, target):
    with open(source, "rb") as stream, open(target, "w", encoding="ascii") as out:
        encoding, elements = read_header(stream)
        order = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}[encoding]
        rows = ascii_rows(stream) if order is None else None
        for name, count, properties in elements:
            names = [p[0] for p in properties]
            for _ in range(count):
                row = next(rows) if rows else binary_row(stream, order, properties)
                if name == "vertex":
                    x, y, z = (row[names.index(axis)] for axis in "xyz")
                    out.write(f"v {fmt(x)} {fmt(y)} {fmt(z)}\n")
                elif name == "face":
                    if len(properties) != 1:
                        sys.exit("face elements with more than one property are not supported")
                    indices = [int(i) + 1 for i in row[1:1 + int(row[0])]]
                    out.write("f " + " ".join(map(str, indices)) + "\n")


def fmt(value):
    if isinstance(value, bytes):
        return value.decode("ascii")
    return repr(float(value))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    convert(sys.argv[1], sys.argv[2])
