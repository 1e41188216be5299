#!/usr/bin/python3
"""Seed corpora for the fuzz harnesses: valid and slightly broken files of every format the
readers take, and random byte strings for fuzz_decompose. Generated, never committed.

    fuzz/make_seeds.py OUT_DIR      writes OUT_DIR/{off,obj,ply,stl,scene,decompose}/

A scene seed starts with the byte that fuzz_read_scene turns into the format (SCENE_FORMATS).
"""
import base64
import io
import json
import math
import os
import random
import shutil
import struct
import sys
import zipfile


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


# ------------------------------------------------------------------ scenes (through assimp)
SCENE_FORMATS = ["dae", "gltf", "glb", "3mf", "fbx"]  # fuzz_read.cpp's kSceneNames, in order


def collada(v, f, matrices=((1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),), nested=False):
    positions = " ".join(num(c) for p in v for c in p)
    indices = " ".join(str(i) for t in f for i in t)
    nodes = ""
    for k, m in enumerate(matrices):
        nodes += (f'<node id="n{k}" name="n{k}"><matrix>{" ".join(num(x) for x in m)}</matrix>'
                  '<instance_geometry url="#g"/></node>')
    if nested:  # a node placed twice through instance_node
        nodes = f'<node id="twice" name="twice">{nodes}</node><node id="again"><instance_node url="#twice"/></node>'
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
<library_geometries><geometry id="g" name="g"><mesh>
<source id="p"><float_array id="pa" count="{3 * len(v)}">{positions}</float_array>
<technique_common><accessor source="#pa" count="{len(v)}" stride="3">
<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
</accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="{len(f)}"><input semantic="VERTEX" source="#v" offset="0"/><p>{indices}</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s">{nodes}</visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
"""


def gltf_parts(v, f, node=None):
    """The glTF JSON and its binary buffer (positions as float32, indices as uint16)."""
    positions = b"".join(struct.pack("<3f", *p) for p in v)
    indices = b"".join(struct.pack("<3H", *t) for t in f)
    indices += b"\0" * (-len(indices) % 4)
    binary = positions + indices
    lo = [min(p[i] for p in v) for i in range(3)]
    hi = [max(p[i] for p in v) for i in range(3)]
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [node or {"mesh": 0, "translation": [1, 2, 3]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": 6 * len(f)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(v), "type": "VEC3", "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5123, "count": 3 * len(f), "type": "SCALAR"}],
    }
    return doc, binary


def gltf(v, f, node=None):
    doc, binary = gltf_parts(v, f, node)
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(binary).decode()
    return json.dumps(doc)


def glb(v, f, node=None):
    doc, binary = gltf_parts(v, f, node)
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def three_mf(v, f, transform="1 0 0 0 1 0 0 0 1 0 0 0"):
    vertices = "".join(f'<vertex x="{num(p[0])}" y="{num(p[1])}" z="{num(p[2])}"/>' for p in v)
    tris = "".join(f'<triangle v1="{t[0]}" v2="{t[1]}" v3="{t[2]}"/>' for t in f)
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">'
             f'<resources><object id="1" type="model"><mesh><vertices>{vertices}</vertices>'
             f'<triangles>{tris}</triangles></mesh></object></resources>'
             f'<build><item objectid="1" transform="{transform}"/></build></model>')
    types = ('<?xml version="1.0" encoding="UTF-8"?>'
             '<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
             '<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
             '<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>'
             '</Types>')
    rels = ('<?xml version="1.0" encoding="UTF-8"?>'
            '<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
            '<Relationship Target="/3D/3dmodel.model" Id="rel0" '
            'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>')
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_STORED) as z:  # stored: the fuzzer can reach the XML
        for name, text in (("[Content_Types].xml", types), ("_rels/.rels", rels), ("3D/3dmodel.model", model)):
            info = zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0))  # fixed: reproducible seeds
            z.writestr(info, text)
    return out.getvalue()


def fbx_ascii(v, f, translation=(0, 0, 0)):
    positions = ",".join(num(c) for p in v for c in p)
    # FBX marks the last corner of each polygon by storing -(index + 1).
    indices = ",".join(f"{t[0]},{t[1]},{-t[2] - 1}" for t in f)
    return f"""; FBX 7.4.0 project file
FBXHeaderExtension:  {{
\tFBXHeaderVersion: 1003
\tFBXVersion: 7400
}}
GlobalSettings:  {{
\tVersion: 1000
\tProperties70:  {{
\t\tP: "UpAxis", "int", "Integer", "",2
\t\tP: "UnitScaleFactor", "double", "Number", "",1
\t}}
}}
Objects:  {{
\tGeometry: 100, "Geometry::seed", "Mesh" {{
\t\tVertices: *{3 * len(v)} {{
\t\t\ta: {positions}
\t\t}}
\t\tPolygonVertexIndex: *{3 * len(f)} {{
\t\t\ta: {indices}
\t\t}}
\t\tGeometryVersion: 124
\t}}
\tModel: 200, "Model::seed", "Mesh" {{
\t\tVersion: 232
\t\tProperties70:  {{
\t\t\tP: "Lcl Translation", "Lcl Translation", "", "A",{",".join(num(c) for c in translation)}
\t\t}}
\t}}
}}
Connections:  {{
\tC: "OO",200,0
\tC: "OO",100,200
}}
"""


def scene_files():
    v, f = SHAPES["cube"][0], triangles(SHAPES["cube"][1])
    tv, tf = SHAPES["torus"]
    mirror = (-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)
    shifted = (1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)
    files = {
        "dae": {"cube.dae": collada(v, f), "torus.dae": collada(tv, tf), "two.dae": collada(v, f, (shifted, mirror)),
                "nested.dae": collada(v, f, (shifted,), nested=True),
                "bad_index.dae": collada(v, [(0, 1, 99)] + f[1:]),
                "bad_truncated.dae": collada(v, f)[:700]},
        "gltf": {"cube.gltf": gltf(v, f), "torus.gltf": gltf(tv, tf),
                 "matrix.gltf": gltf(v, f, {"mesh": 0, "matrix": list(mirror)}),
                 "bad_index.gltf": gltf(v, [(0, 1, 99)] + f[1:]),
                 "bad_json.gltf": gltf(v, f)[:-30]},
        "glb": {"cube.glb": glb(v, f), "torus.glb": glb(tv, tf),
                "rotated.glb": glb(v, f, {"mesh": 0, "rotation": [0, 0, 0.7071068, 0.7071068], "scale": [2, 2, 2]}),
                "bad_length.glb": glb(v, f)[:40]},
        "3mf": {"cube.3mf": three_mf(v, f), "torus.3mf": three_mf(tv, tf),
                "moved.3mf": three_mf(v, f, "1 0 0 0 1 0 0 0 1 5 0 0"),
                "bad_index.3mf": three_mf(v, [(0, 1, 99)] + f[1:])},
        "fbx": {"cube.fbx": fbx_ascii(v, f), "torus.fbx": fbx_ascii(tv, tf, (1, 2, 3)),
                "bad_count.fbx": fbx_ascii(v, f).replace(f"*{3 * len(f)}", "*7", 1)},
    }
    out = {}
    for fmt, seeds in files.items():
        selector = bytes([SCENE_FORMATS.index(fmt)])
        for name, data in seeds.items():
            out[name] = selector + (data if isinstance(data, bytes) else data.encode())
    return out


# ------------------------------------------------------------------ decompose
def decompose_seeds():
    rng = random.Random(20070612)
    out = {}
    for shape in range(7):  # the harness's first byte picks the shape; no edits, then options
        out[f"shape{shape}.bin"] = bytes([shape, 0, 0, 0, 0, 0, 0, 0])
    for i in range(12):
        out[f"random{i:02d}.bin"] = bytes(rng.randrange(256) for _ in range(rng.randrange(8, 97)))
    # Past findings, kept as seeds so that every smoke run replays them.
    # 2026-11-29 (CI smoke): three unit cubes, one crossing another, tau 0.2: the wrap's hull ends
    # 1.01 tau off the model, reported (exit 8); the harness had required tau on a soup.
    out["finding-2026-11-29.bin"] = base64.b64decode("wlAU8ogCAAAAAAAAAP5zmcTDD7/kgTQdCJrdrbGk/ZVj3/ddjBZdfeRZk9pd+dA=")
    # 2026-11-29 (a random run): a double cone of 1e-6 merged into flat faces; the T-junction
    # split repeated a flat face's own corner and CGAL's orient_polygon_soup never returned.
    out["finding-2026-11-29-hang.bin"] = base64.b64decode("QSxCIbd/dmzvAWezt9rzs4pOcOH1hZDyIb/kgTQdCJrdrbWk/ZVj3/+hMX9bdBgmNHN2")
    # 2026-11-29 (the smoke run): a closed sphere-like solid passing through itself, tau 0.2: its
    # repair moves the surface and a hull ends 1.6 tau off the input as read, which the result
    # reports (exit 8); the harness had counted it as silent.
    out["finding-2026-11-29-crossing.bin"] = base64.b64decode(
        "LEIht39yaBgBD/oKKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoKCgoAAAAAAAAADTvZ3N0dg==")
    # 2026-11-29 (a random run): another closed surface passing through itself, decomposed
    # through its wrap at tau 0.2, a hull 1.01 tau off the model, reported (exit 8).
    out["finding-2026-11-29-crossing-wrap.bin"] = base64.b64decode(
        "3DDG4MmXI0+qPt87gQW/gULEww+/5IE0HQia3a3PsaQ68W7QKwYAAAAAoEI1NwEAYHAAAmCwTw==")
    # 2026-11-29 (a random run): a mesh whose faces the repairs leave all flat, sent to the wrap:
    # CGAL's alpha wrap read the box of an empty tree (UndefinedBehaviorSanitizer).
    out["finding-2026-11-29-flat-wrap.bin"] = base64.b64decode(
        "wlAU8ogCAAAAAAAAAP5zmcT//////////////////////wEAAAAAAAAAv+SBNB0Imt3aXfnQ")
    # 2026-12-02 (CI smoke): a self-crossing solid at tau 0.1 whose stalled piece was made final by
    # its hull; the component kept the misled pocket measure (0.109) as its concavity.
    out["finding-2026-12-02-stall.bin"] = base64.b64decode(
        "LEIht39yaBgBD/qz/qxnnX/vZTIhISEhISEhISEhISEhISEhISEhISEhISEhISEhISEhISEhISEhISEhIe9nc3R2")
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    for kind, files in (("off", off_files()), ("obj", obj_files()), ("ply", ply_files()), ("stl", stl_files()),
                        ("scene", scene_files()), ("decompose", decompose_seeds())):
        folder = os.path.join(root, kind)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        for name, data in files.items():
            with open(os.path.join(folder, name), "wb") as out:
                out.write(data if isinstance(data, bytes) else data.encode())
        print(f"{folder}: {len(files)} seeds")


if __name__ == "__main__":
    main()
