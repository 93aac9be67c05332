"""A minimal glTF 2.0 writer for the scenes in this folder (Python's standard library only):
buffers, accessors, meshes, materials, nodes, cameras, point lights, PNG images; written as
.glb, or as .gltf with an external .bin and images. make_scenes.py uses it."""
import json
import math
import struct
import zlib

FLOAT, UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5121, 5123, 5125


def f32(x):
    """x rounded to a float32, as a Python float (the value a reader stores)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def png(width, height, pixel):
    """An 8-bit RGB or RGBA PNG; pixel(x, y) returns (r, g, b) or (r, g, b, a) in 0..255, row 0 at
    the top."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    colour_type = 6 if len(pixel(0, 0)) == 4 else 2
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


class Gltf:
    def __init__(self):
        self.doc = {"asset": {"version": "2.0", "generator": "tracer scenes/gltf/gltf_writer.py"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                    "accessors": [], "bufferViews": [], "buffers": []}
        self.bin = bytearray()
        self.extensions = set()

    def _view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin += b"\0"
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin += data
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, values, kind, components):
        """values: a flat list; kind FLOAT or an unsigned integer type."""
        fmt = {FLOAT: "f", UNSIGNED_BYTE: "B", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I"}[kind]
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        target = 34963 if components == 1 and kind != FLOAT else 34962
        acc = {"bufferView": self._view(data, target), "componentType": kind, "count": len(values) // components,
               "type": {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}[components]}
        if components == 3 and kind == FLOAT:
            acc["min"] = [min(values[i::3]) for i in range(3)]
            acc["max"] = [max(values[i::3]) for i in range(3)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def material(self, name, **m):
        self.doc["materials"].append(dict(name=name, **m))
        for ext in m.get("extensions", {}):
            self.extensions.add(ext)
        return len(self.doc["materials"]) - 1

    def lambert(self, name, colour):
        """A diffuse material: metallic 0 and KHR_materials_specular's factor 0 (no specular layer)."""
        return self.material(name, pbrMetallicRoughness={"baseColorFactor": list(colour) + [1], "metallicFactor": 0,
                                                         "roughnessFactor": 1},
                             extensions={"KHR_materials_specular": {"specularFactor": 0}})

    def image(self, data):
        self.doc.setdefault("images", []).append({"bufferView": self._view(data), "mimeType": "image/png"})
        self.doc.setdefault("textures", []).append({"source": len(self.doc["images"]) - 1})
        return len(self.doc["textures"]) - 1

    def geometry(self, positions, indices, normals=None, uvs=None):
        """Accessors of a triangle mesh, for one or more meshes (primitive() takes them)."""
        attributes = {"POSITION": self.accessor(positions, FLOAT, 3)}
        if normals:
            attributes["NORMAL"] = self.accessor(normals, FLOAT, 3)
        if uvs:
            attributes["TEXCOORD_0"] = self.accessor(uvs, FLOAT, 2)
        kind = UNSIGNED_SHORT if len(positions) // 3 < 65536 else UNSIGNED_INT
        return {"attributes": attributes, "indices": self.accessor(indices, kind, 1)}

    def primitive(self, name, geometry, material):
        self.doc["meshes"].append({"name": name, "primitives": [dict(geometry, material=material)]})
        return len(self.doc["meshes"]) - 1

    def mesh(self, name, positions, indices, material, normals=None, uvs=None):
        return self.primitive(name, self.geometry(positions, indices, normals, uvs), material)

    def node(self, parent=None, **n):
        self.doc["nodes"].append(n)
        index = len(self.doc["nodes"]) - 1
        if parent is None:
            self.doc["scenes"][0]["nodes"].append(index)
        else:
            self.doc["nodes"][parent].setdefault("children", []).append(index)
        return index

    def camera(self, name, yfov, aspect, **node):
        self.doc.setdefault("cameras", []).append(
            {"name": name, "type": "perspective",
             "perspective": {"yfov": yfov, "aspectRatio": aspect, "znear": 0.01}})
        return self.node(camera=len(self.doc["cameras"]) - 1, **node)

    def point_light(self, colour, intensity, **node):
        return self.light({"type": "point", "color": list(colour), "intensity": intensity}, **node)

    def light(self, light, **node):
        """A KHR_lights_punctual light (its JSON object) on a new node."""
        self.extensions.add("KHR_lights_punctual")
        lights = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})["lights"]
        lights.append(light)
        return self.node(extensions={"KHR_lights_punctual": {"light": len(lights) - 1}}, **node)

    def _finish(self):
        if self.extensions:
            self.doc["extensionsUsed"] = sorted(self.extensions)
        while len(self.bin) % 4:
            self.bin += b"\0"
        return {k: v for k, v in self.doc.items() if v != []}

    def write_glb(self, path):
        doc = self._finish()
        doc["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(doc, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(self.bin), 0x004E4942) + self.bin
        with open(path, "wb") as f:
            f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)

    def write_gltf(self, path, bin_name):
        doc = self._finish()
        doc["buffers"] = [{"byteLength": len(self.bin), "uri": bin_name}]
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
        with open(path.rsplit("/", 1)[0] + "/" + bin_name if "/" in path else bin_name, "wb") as f:
            f.write(self.bin)


def uv_sphere(radius, segments, rings):
    """Positions, normals, uvs and indices of a UV sphere about the origin."""
    pos, nor, uv, idx = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            pos += [radius * c for c in n]
            nor += list(n)
            uv += [s / segments, r / rings]
    for r in range(rings):
        for s in range(segments):
            a, b = r * (segments + 1) + s, (r + 1) * (segments + 1) + s
            if r > 0:
                idx += [a, b, a + 1]
            if r < rings - 1:
                idx += [a + 1, b, b + 1]
    return pos, nor, uv, idx


def cube(half):
    """A cube's 24 corners (4 per face, with normals and uvs) and 12 triangles."""
    pos, nor, uv, idx = [], [], [], []
    for axis in range(3):
        for sign in (1, -1):
            n = [0, 0, 0]
            n[axis] = sign
            u_axis, v_axis = [(1, 2), (2, 0), (0, 1)][axis]
            base = len(pos) // 3
            for du, dv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0, 0, 0]
                p[axis] = sign * half
                p[u_axis] = du * half * sign
                p[v_axis] = dv * half
                pos += p
                nor += n
                uv += [(du + 1) / 2, (1 - dv) / 2]
            idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nor, uv, idx
