#!/usr/bin/env python3
"""Writes the generated seed corpora of the fuzz targets (docs/fuzzing.md):

- corpus/mesh/: each small mesh of the repository (scenes/assets, tests/inputs/support,
  tests/inputs/bad/meshes) as the mesh target reads it: one byte naming the extension (its index in
  scenes::MeshFileExtensions(), the order of EXTENSIONS below), then the file's bytes; and a minimal
  valid mesh of each format (MINIMAL).
- corpus/mavlink/: MAVLink frames of every message the codec knows (ids, CRC_EXTRA and lengths read
  from the kInfo lines of engine/mavlink/*.h): v2 (whole and truncated), v1, signed, several frames
  in a row, and broken ones (bad CRC, cut off, unknown id, bad flags, garbage between frames). The
  first byte picks how the target cuts the stream into chunks (0: in one piece).

The scene and mission targets read their seeds where they are (scenes/, tests/inputs/), so only
findings are kept in corpus/scene and corpus/mission. Run from anywhere; rewrites the generated
files (named gen_*) and leaves the others.
"""
import pathlib
import random
import re
import struct

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"
EXTENSIONS = ["obj", "gltf", "glb", "fbx", "ply", "stl", "dae"]
MAX_SEED_BYTES = 65536  # run_fuzzer.sh's -max_len

TRIANGLE = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]


def minimal_meshes():
    """One small valid triangle of each format."""
    out = {}
    out["obj"] = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
    out["ply"] = (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  b"property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                  b"end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    out["ply_binary"] = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         b"property float y\nproperty float z\nelement face 1\n"
                         b"property list uchar int vertex_indices\nend_header\n" +
                         b"".join(struct.pack("<3f", *v) for v in TRIANGLE) +
                         struct.pack("<B3i", 3, 0, 1, 2))
    out["stl"] = (b"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                  b"vertex 0 1 0\nendloop\nendfacet\nendsolid t\n")
    out["stl_binary"] = (b"\0" * 80 + struct.pack("<I", 1) + struct.pack("<3f", 0, 0, 1) +
                         b"".join(struct.pack("<3f", *v) for v in TRIANGLE) + b"\0\0")
    positions = b"".join(struct.pack("<3f", *v) for v in TRIANGLE)
    gltf_json = ('{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],'
                 '"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],'
                 '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",'
                 '"min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],'
                 '"buffers":[{"byteLength":36%s}]}')
    import base64
    out["gltf"] = (gltf_json % (',"uri":"data:application/octet-stream;base64,' +
                                base64.b64encode(positions).decode() + '"')).encode()
    json_chunk = (gltf_json % "").encode()
    json_chunk += b" " * (-len(json_chunk) % 4)
    glb = (struct.pack("<II", len(json_chunk), 0x4E4F534A) + json_chunk +
           struct.pack("<II", len(positions), 0x004E4942) + positions)
    out["glb"] = b"glTF" + struct.pack("<II", 2, 12 + len(glb)) + glb
    out["dae"] = b"""<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh>
<source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>
<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node><instance_geometry url="#g"/></node></visual_scene>
</library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>
"""
    return out


def write_mesh_corpus():
    folder = CORPUS / "mesh"
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.glob("gen_*"):
        old.unlink()
    sources = []
    for d in ["scenes/assets", "tests/inputs/support", "tests/inputs/bad/meshes"]:
        sources += sorted(p for p in (ROOT / d).iterdir() if p.is_file())
    for path in sources:
        ext = path.suffix[1:].lower()
        data = path.read_bytes()
        if ext not in EXTENSIONS or len(data) + 1 > MAX_SEED_BYTES:
            continue
        name = "gen_" + path.parent.name + "_" + path.name.replace(".", "_")
        (folder / name).write_bytes(bytes([EXTENSIONS.index(ext)]) + data)
    for name, data in minimal_meshes().items():
        ext = name.split("_")[0]
        (folder / ("gen_minimal_" + name)).write_bytes(bytes([EXTENSIONS.index(ext)]) + data)


def crc_accumulate(data, crc=0xFFFF):
    """CRC-16/MCRF4XX, MAVLink's X.25 checksum (engine/mavlink/crc.h)."""
    for b in data:
        tmp = b ^ (crc & 0xFF)
        tmp = (tmp ^ (tmp << 4)) & 0xFF
        crc = ((crc >> 8) ^ (tmp << 8) ^ (tmp << 3) ^ (tmp >> 4)) & 0xFFFF
    return crc


assert crc_accumulate(b"123456789") == 0x6F91


def known_messages():
    """(id, name, crc_extra, base_length, full_length) of each message the codec knows."""
    pattern = re.compile(r'kInfo\{(\d+), "(\w+)", (\d+), (\d+), (\d+)\}')
    out = []
    for header in sorted((ROOT / "engine" / "mavlink").glob("*.h")):
        out += [tuple(int(g) if g.isdigit() else g for g in m.groups())
                for m in pattern.finditer(header.read_text())]
    return sorted(out)


def frame_v2(msgid, crc_extra, payload, seq=0, incompat=0, truncate=True):
    if truncate:
        payload = payload.rstrip(b"\0") or b"\0"
    body = struct.pack("<BBBBBB", len(payload), incompat, 0, seq, 1, 1) + \
        struct.pack("<I", msgid)[:3] + payload
    crc = crc_accumulate(bytes([crc_extra]), crc_accumulate(body))
    out = b"\xfd" + body + struct.pack("<H", crc)
    if incompat & 1:
        out += bytes(range(13))
    return out


def frame_v1(msgid, crc_extra, payload, seq=0):
    body = struct.pack("<BBBBB", len(payload), seq, 1, 1, msgid) + payload
    crc = crc_accumulate(bytes([crc_extra]), crc_accumulate(body))
    return b"\xfe" + body + struct.pack("<H", crc)


def write_mavlink_corpus():
    folder = CORPUS / "mavlink"
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.glob("gen_*"):
        old.unlink()
    rng = random.Random(17)
    messages = known_messages()
    assert len(messages) >= 20, messages

    def write(name, data, chunking=0):
        (folder / ("gen_" + name)).write_bytes(bytes([chunking]) + data)

    every = b""
    for msgid, name, extra, base, full in messages:
        payload = bytes(rng.randrange(256) for _ in range(full))
        short = payload[:base // 2] + b"\0" * (full - base // 2)
        v2 = frame_v2(msgid, extra, payload, seq=msgid & 0xFF)
        write(f"{name}_v2", v2)
        write(f"{name}_v2_truncated", frame_v2(msgid, extra, short))
        write(f"{name}_v2_signed", frame_v2(msgid, extra, payload, incompat=1))
        if msgid < 256:
            write(f"{name}_v1", frame_v1(msgid, extra, payload[:base]))
        write(f"{name}_v2_chunked", v2, chunking=1 + msgid % 200)
        bad = bytearray(v2)
        bad[-1] ^= 0xFF
        write(f"{name}_bad_crc", bytes(bad))
        write(f"{name}_cut", v2[:len(v2) // 2])
        write(f"{name}_bad_flags", frame_v2(msgid, extra, payload, incompat=2))
        every += v2
    write("every_message", every)
    write("every_message_chunked", every, chunking=7)
    garbage = bytes(rng.choice([0xFD, 0xFE, rng.randrange(256)]) for _ in range(64))
    write("garbage_between_frames", garbage + every[:200] + garbage + every[200:400])
    write("unknown_id", frame_v2(0xABCDE, 0, b"hello"))
    write("start_bytes_only", b"\xfd\xfe" * 40)


if __name__ == "__main__":
    write_mesh_corpus()
    write_mavlink_corpus()
