#!/usr/bin/python3
"""Seed corpora for the fuzz harnesses: valid and slightly broken files of every format the
readers take, and random byte strings for fuzz_decompose. Generated, never committed.

    fuzz/make_seeds.py OUT_DIR      writes OUT_DIR/{off,obj,ply,stl,decompose}/
"""
import math
import os
import random
import shutil
import struct
import sys


# ------------------------------------------------------------------ shapes
def cube():
    v = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return v, quads


def tetrahedron():
    return [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def torus(major=6, minor=4, big=2.0, small=0.5):
    v = []
    for i in range(major):
        a = 2 * math.pi * i / major
        for j in range(minor):
            b = 2 * math.pi * j / minor
            r = big + small * math.cos(b)
            v.append((r * math.cos(a), r * math.sin(a), small * math.sin(b)))
    f = []
    for i in range(major):
        for j in range(minor):
            a, b = i * minor + j, ((i + 1) % major) * minor + j
            c, d = ((i + 1) % major) * minor + (j + 1) % minor, i * minor + (j + 1) % minor
            f += [(a, b, c), (a, c, d)]
    return v, f


def triangles(faces):
    out = []
    for p in faces:
        out += [(p[0], p[i], p[i + 1]) for i in range(1, len(p) - 1)]
    return out


SHAPES = {"cube": cube(), "tet": tetrahedron(), "torus": torus()}


def num(x):
    return repr(float(x))


# ------------------------------------------------------------------ OFF
def off_files():
    out = {}
    for name, (v, f) in SHAPES.items():
        body = "".join(f"{num(x)} {num(y)} {num(z)}\n" for x, y, z in v)
        body += "".join(f"{len(p)} " + " ".join(map(str, p)) + "\n" for p in f)
        out[f"{name}.off"] = f"OFF\n{len(v)} {len(f)} 0\n" + body
    v, f = cube()
    out["cube_inline_counts.off"] = f"OFF {len(v)} {len(f)} 0\n" + out["cube.off"].split("\n", 2)[2]
    out["cube_comments.off"] = "# a comment\n\nOFF # keyword\n\n" + out["cube.off"].split("\n", 1)[1].replace("\n", "  # c\n", 3)
    out["cube_colours.off"] = "COFF\n8 6 0\n" + "".join(f"{x} {y} {z} 255 0 0 255\n" for x, y, z in v) + \
        "".join("4 " + " ".join(map(str, p)) + " 0.5 0.5 0.5\n" for p in f)
    out["tet_numbers.off"] = "NOFF\n4 4 6\n+0 0.0e0 -0 0 0 1\n1E0 .0 0. 0 0 1\n0 1 0 0 0 1\nnan inf -inf 0 0 1\n" \
        "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    out["crlf.off"] = out["tet.off"].replace("\n", "\r\n")
    # broken
    out["bad_truncated.off"] = out["torus.off"][: len(out["torus.off"]) // 2]
    out["bad_index.off"] = out["tet.off"].replace("3 1 2 3", "3 1 2 4")
    out["bad_negative_index.off"] = out["tet.off"].replace("3 1 2 3", "3 1 -2 3")
    out["bad_two_corners.off"] = out["tet.off"].replace("3 1 2 3", "2 1 2")
    out["bad_counts.off"] = "OFF\n-4 4 0\n"
    out["bad_huge_counts.off"] = "OFF\n4000000000000 9000000000000000000 0\n0 0 0\n"
    out["bad_binary.off"] = "OFF BINARY\n" + "\0" * 12
    out["bad_4off.off"] = "4OFF\n1 0 0\n0 0 0 0\n"
    out["bad_word.off"] = out["tet.off"].replace("0.0 0.0 1.0", "0.0 zero 1.0")
    out["bad_header_only.off"] = "OFF\n"
    return out


# ------------------------------------------------------------------ OBJ
def obj_files():
    out = {}
    for name, (v, f) in SHAPES.items():
        out[f"{name}.obj"] = "".join(f"v {num(x)} {num(y)} {num(z)}\n" for x, y, z in v) + \
            "".join("f " + " ".join(str(i + 1) for i in p) + "\n" for p in f)
    v, f = cube()
    out["cube_slashes.obj"] = "# exported\nmtllib m.mtl\n" + "".join(f"v {x} {y} {z}\nvt 0 0\nvn 0 0 1\n" for x, y, z in v) + \
        "usemtl red\ns off\n" + "".join("f " + " ".join(f"{i + 1}/{i + 1}/{i + 1}" if k % 2 else f"{i + 1}//{i + 1}"
                                                            for k, i in enumerate(p)) + "\n" for p in f)
    out["cube_negative.obj"] = "".join(
        f"v {x} {y} {z}\n" for x, y, z in v) + "".join("f " + " ".join(str(i - 8) for i in p) + "\n" for p in f)
    out["cube_forward.obj"] = "".join("f " + " ".join(str(i + 1) for i in p) + "\n" for p in f) + \
        "".join(f"v {x} {y} {z}\n" for x, y, z in v)
    tv, tf = tetrahedron()
    groups = "o first piece\n" + "".join(f"v {x} {y} {z}\n" for x, y, z in tv) + \
        "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in tf)
    groups += "g second\no renamed\n" + "".join(f"v {x + 3} {y} {z}\n" for x, y, z in tv) + \
        "".join(f"f {a + 5} {b + 5} {c + 5}\n" for a, b, c in tf) + "o trailing\n"
    out["objects.obj"] = groups
    out["crlf.obj"] = out["tet.obj"].replace("\n", "\r\n")
    out["bad_zero.obj"] = out["tet.obj"].replace("f 1 3 2", "f 0 3 2")
    out["bad_index.obj"] = out["tet.obj"] + "f 1 2 9\n"
    out["bad_negative.obj"] = "f -1 -2 -3\n" + out["tet.obj"]
    out["bad_two.obj"] = out["tet.obj"] + "f 1 2\n"
    out["bad_garbage.obj"] = out["tet.obj"] + "@@@ 1 2 3\n"
    out["bad_number.obj"] = out["tet.obj"].replace("v 1.0", "v 1.0.0", 1)
    out["bad_huge.obj"] = out["tet.obj"] + "f 1 2 99999999999999\n"
    out["bad_truncated.obj"] = out["torus.obj"][: len(out["torus.obj"]) * 2 // 3]
    return out


# ------------------------------------------------------------------ PLY
PLY_PACK = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I",
            "float": "f", "double": "d", "int8": "b", "uint8": "B", "int32": "i", "float32": "f",
            "float64": "d", "uint32": "I", "int16": "h", "uint16": "H"}


def ply(v, f, fmt="ascii", xyz="float", count="uchar", index="int", extra_vertex=(), index_name="vertex_indices",
        elements_after=""):
    head = f"ply\nformat {fmt} 1.0\ncomment made by make_seeds.py\nelement vertex {len(v)}\n"
    head += "".join(f"property {xyz} {c}\n" for c in "xyz")
    head += "".join(f"property {t} {n}\n" for t, n in extra_vertex)
    head += f"element face {len(f)}\nproperty list {count} {index} {index_name}\n{elements_after}end_header\n"
    if fmt == "ascii":
        body = "".join(" ".join([num(x), num(y), num(z)] + ["1"] * len(extra_vertex)) + "\n" for x, y, z in v)
        body += "".join(f"{len(p)} " + " ".join(map(str, p)) + "\n" for p in f)
        return (head + body).encode()
    end = "<" if fmt == "binary_little_endian" else ">"
    body = b""
    for x, y, z in v:
        body += struct.pack(end + PLY_PACK[xyz] * 3, x, y, z)
        for t, _ in extra_vertex:
            body += struct.pack(end + PLY_PACK[t], 1)
    for p in f:
        body += struct.pack(end + PLY_PACK[count], len(p)) + struct.pack(end + PLY_PACK[index] * len(p), *p)
    return head.encode() + body


def ply_files():
    out = {}
    for name, (v, f) in SHAPES.items():
        out[f"{name}_ascii.ply"] = ply(v, f)
        out[f"{name}_le.ply"] = ply(v, f, "binary_little_endian")
        out[f"{name}_be.ply"] = ply(v, f, "binary_big_endian", xyz="double", count="uint", index="uint")
    v, f = cube()
    out["cube_extra_le.ply"] = ply(v, f, "binary_little_endian", xyz="float32", count="uint8", index="uint16",
                                   extra_vertex=(("uchar", "red"), ("double", "nx")), index_name="vertex_index",
                                   elements_after="element edge 0\nproperty int vertex1\nobj_info x\n")
    out["cube_short_be.ply"] = ply(v, f, "binary_big_endian", xyz="short", count="char", index="ushort")
    tv, tf = tetrahedron()
    base = out["tet_ascii.ply"].decode()
    out["bad_index.ply"] = base.replace("3 1 2 3", "3 1 2 7").encode()
    out["bad_count.ply"] = base.replace("3 1 2 3", "2 1 2").encode()
    out["bad_fraction.ply"] = base.replace("3 1 2 3", "3 1 2.5 3").encode()
    out["bad_no_end.ply"] = base.replace("end_header\n", "").encode()
    out["bad_format.ply"] = base.replace("format ascii", "format binary_middle_endian").encode()
    out["bad_no_vertex.ply"] = base.replace("element vertex", "element point").encode()
    out["bad_type.ply"] = base.replace("property float x", "property float128 x").encode()
    out["bad_truncated_le.ply"] = out["torus_le.ply"][:-7]
    out["bad_huge_element.ply"] = base.replace("element face 4", "element face 4000000000000").encode()
    out["bad_empty_element.ply"] = base.replace("element face", "element nothing 1000\nelement face").encode()
    return out


# ------------------------------------------------------------------ STL
def stl_ascii(v, f, name="seed"):
    s = f"solid {name}\n"
    for a, b, c in triangles(f):
        s += "  facet normal 0 0 1\n    outer loop\n"
        s += "".join(f"      vertex {num(x)} {num(y)} {num(z)}\n" for x, y, z in (v[a], v[b], v[c]))
        s += "    endloop\n  endfacet\n"
    return s + f"endsolid {name}\n"


def stl_binary(v, f, header=b"binary seed"):
    tris = triangles(f)
    out = header.ljust(80, b" ")[:80] + struct.pack("<I", len(tris))
    for a, b, c in tris:
        out += struct.pack("<3f", 0, 0, 1) + b"".join(struct.pack("<3f", *v[i]) for i in (a, b, c)) + b"\0\0"
    return out


def stl_files():
    out = {}
    for name, (v, f) in SHAPES.items():
        out[f"{name}_ascii.stl"] = stl_ascii(v, f).encode()
        out[f"{name}_binary.stl"] = stl_binary(v, f)
    v, f = cube()
    out["cube_solid_header.stl"] = stl_binary(v, f, b"solid but binary")
    out["cube_quad_loops.stl"] = ("solid quads\n" + "".join(
        "facet normal 0 0 0\nouter loop\n" + "".join(f"vertex {x} {y} {z}\n" for x, y, z in (v[i] for i in p)) +
        "endloop\nendfacet\n" for p in f) + "endsolid\n").encode()
    base = out["tet_ascii.stl"].decode()
    out["bad_count.stl"] = out["tet_binary.stl"][:80] + struct.pack("<I", 5) + out["tet_binary.stl"][84:]
    out["bad_truncated.stl"] = out["torus_binary.stl"][:-20]
    out["bad_short.stl"] = b"\1\2\3"
    out["bad_outside.stl"] = base.replace("outer loop\n", "", 1).encode()
    out["bad_unclosed.stl"] = base[: base.rfind("endloop")].encode()
    out["bad_word.stl"] = base.replace("endfacet", "endfacett", 1).encode()
    out["bad_two.stl"] = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid\n".encode()
    return out


# ------------------------------------------------------------------ decompose
def decompose_seeds():
    rng = random.Random(20070612)
    out = {}
    for shape in range(7):  # the harness's first byte picks the shape; no edits, then options
        out[f"shape{shape}.bin"] = bytes([shape, 0, 0, 0, 0, 0, 0, 0])
    for i in range(12):
        out[f"random{i:02d}.bin"] = bytes(rng.randrange(256) for _ in range(rng.randrange(8, 97)))
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    for kind, files in (("off", off_files()), ("obj", obj_files()), ("ply", ply_files()), ("stl", stl_files()),
                        ("decompose", decompose_seeds())):
        folder = os.path.join(root, kind)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        for name, data in files.items():
            with open(os.path.join(folder, name), "wb") as out:
                out.write(data if isinstance(data, bytes) else data.encode())
        print(f"{folder}: {len(files)} seeds")


if __name__ == "__main__":
    main()
