"""Writes the glTF scenes of this folder (python3 scenes/gltf/make_scenes.py; docs/gltf.md):
  cornell-box.gltf (+ .bin)  the Cornell box's walls, blocks and lamp, diffuse and emissive, with
                             its camera; cornell-box-twin.json is the same scene in the tracer's
                             own format, number for number, and renders the same image
  sphere-grid.glb            metal_rough spheres, metallic by row and roughness by column, a
                             floor, a point light, an emissive panel and a camera
  textured.glb               a node hierarchy (scaled, rotated, translated parents) of cubes with
                             base colour, normal and metallic-roughness textures and a
                             KHR_texture_transform; one cube's uvs mirrored, one mirrored by its scale
  conventions.glb            a diffuse plane under a 10 cd point light 2 m above it, beside an
                             emissive quad of strength 2, seen from above: docs/gltf.md renders
                             it in Blender too (blender_compare.sh) to check camera and units
  cutouts.glb                a lattice fence and a leaf card (alphaMode MASK, the texture's alpha) and
                             a tinted pane (BLEND, alpha 0.4) before a sphere, under a low sun
The files are committed; run this after changing it."""
import json
import math
import os

from gltf_writer import Gltf, cube, f32, png, uv_sphere

HERE = os.path.dirname(os.path.abspath(__file__))

WALLS = [  # (material, four corners), as scenes/cornell-box.json
    ("white", [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]),
    ("white", [[556, 548.8, 0], [556, 548.8, 559.2], [0, 548.8, 559.2], [0, 548.8, 0]]),
    ("white", [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556, 548.8, 559.2]]),
    ("green", [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]),
    ("red", [[552.8, 0, 0], [549.6, 0, 559.2], [556, 548.8, 559.2], [556, 548.8, 0]]),
    ("lamp", [[343, 548.7, 227], [343, 548.7, 332], [213, 548.7, 332], [213, 548.7, 227]]),
]
BLOCK_TOPS = [([130, 165, 65], [82, 165, 225], [240, 165, 272], [290, 165, 114]),
              ([423, 330, 247], [265, 330, 296], [314, 330, 456], [472, 330, 406])]
COLOURS = {"white": [0.725, 0.71, 0.68], "red": [0.63, 0.065, 0.05], "green": [0.14, 0.45, 0.091]}
LAMP_FACTOR, LAMP_STRENGTH = [1.0, 0.8, 0.6], 17.0
YFOV = math.radians(39.3077)


def block_quads(top):
    """The top and four sides of a block standing on y = 0 under its top quad."""
    quads = [list(top)]
    for i in range(4):
        a, b = top[i], top[(i + 1) % 4]
        quads.append([[a[0], 0, a[2]], [b[0], 0, b[2]], list(b), list(a)])
    return quads


def cornell_quads():
    quads = [(m, q) for m, q in WALLS]
    for top in BLOCK_TOPS:
        quads += [("white", q) for q in block_quads(top)]
    return quads


def cornell_box():
    g = Gltf()
    ids = {name: g.lambert(name, c) for name, c in COLOURS.items()}
    ids["lamp"] = g.material("lamp", emissiveFactor=LAMP_FACTOR,
                             pbrMetallicRoughness={"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
                             extensions={"KHR_materials_emissive_strength": {"emissiveStrength": LAMP_STRENGTH},
                                         "KHR_materials_specular": {"specularFactor": 0}})
    for i, (material, corners) in enumerate(cornell_quads()):
        g.node(mesh=g.mesh("quad%d" % i, [c for p in corners for c in p], [0, 1, 2, 0, 2, 3], ids[material]))
    # Looks down +z from in front of the open side: 180 degrees about y.
    g.camera("front", YFOV, 640 / 480, translation=[278, 273, -800], rotation=[0, 1, 0, 0])
    g.write_gltf(os.path.join(HERE, "cornell-box.gltf"), "cornell-box.bin")

    # The twin: every number the glTF reader computes, written so the JSON reader gets the same float.
    vfov = f32(YFOV * (180.0 / math.pi))
    lamp = [f32(f32(c) * f32(LAMP_STRENGTH)) for c in LAMP_FACTOR]
    twin = {"format": "tracer-scene/1",
            "camera": {"from": [278, 273, -800], "to": [278, 273, -799], "up": [0, 1, 0], "vfov": vfov},
            "film": {"width": 640, "height": 480},
            "render": {"integrator": "path", "spp": 64, "sampler": "sobol", "max_depth": 8},
            "background": {"type": "constant", "radiance": [1, 1, 1]},  # the glTF reader's neutral sky
            "materials": dict({n: {"type": "lambert", "albedo": c} for n, c in COLOURS.items()},
                              lamp={"type": "emissive", "radiance": lamp}),
            "shapes": [{"type": "mesh", "material": m, "positions": q, "indices": [[0, 1, 2], [0, 2, 3]]}
                       for m, q in cornell_quads()]}
    with open(os.path.join(HERE, "cornell-box-twin.json"), "w") as f:
        f.write(json.dumps(twin, indent=1) + "\n")


def floor(g, x, z, grey):
    """A grey Lambert floor at y = 0 over [-x, x] by [-z, z], facing up."""
    m = g.lambert("floor", [grey, grey, grey])
    g.node(mesh=g.mesh("floor", [-x, 0, -z, x, 0, -z, x, 0, z, -x, 0, z], [0, 2, 1, 0, 3, 2], m))


def pitched_camera(g, yfov_degrees, translation, pitch_degrees):
    """A 4:3 camera named "front" at `translation`, looking down -z tilted by `pitch_degrees` about x."""
    half = math.radians(pitch_degrees) / 2
    g.camera("front", math.radians(yfov_degrees), 4 / 3, translation=translation,
             rotation=[math.sin(half), 0, 0, math.cos(half)])


def sphere_grid():
    g = Gltf()
    pos, nor, uv, idx = uv_sphere(0.4, 20, 10)
    sphere = g.geometry(pos, idx, normals=nor, uvs=uv)
    for row, metallic in enumerate([0.0, 0.5, 1.0]):
        for col, roughness in enumerate([0.0, 0.25, 0.5, 0.75, 1.0]):
            m = g.material("m%.1f-r%.2f" % (metallic, roughness),
                           pbrMetallicRoughness={"baseColorFactor": [0.9, 0.6, 0.3, 1], "metallicFactor": metallic,
                                                 "roughnessFactor": roughness})
            mesh = g.primitive("sphere", sphere, m)
            g.node(mesh=mesh, translation=[(col - 2) * 1.0, 0.4 + row * 1.0, 0])
    floor(g, 4, 3, 0.5)
    panel = g.material("panel", emissiveFactor=[1, 1, 1],
                       extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}})
    g.node(mesh=g.mesh("panel", [-2, 4, 1, 2, 4, 1, 2, 4, 3, -2, 4, 3], [0, 1, 2, 0, 2, 3], panel))
    g.point_light([1, 0.95, 0.9], 20.0, translation=[0, 3.5, 4])
    pitched_camera(g, 40, [0, 1.9, 6.5], -8)
    g.write_glb(os.path.join(HERE, "sphere-grid.glb"))


def textured():
    g = Gltf()
    colour = g.image(png(32, 32, lambda x, y: (220, 60, 40) if (x // 8 + y // 8) % 2 else (240, 220, 200)))
    bumps = g.image(png(32, 32, lambda x, y: (128 + int(90 * math.sin(x / 32 * 2 * math.pi)), 128, 240)))
    rough = g.image(png(16, 16, lambda x, y: (0, 40 + 12 * x, 255 if y < 8 else 0)))
    transform = {"KHR_texture_transform": {"offset": [0.25, 0], "rotation": 0.3, "scale": [2, 2]}}
    g.extensions.add("KHR_texture_transform")
    m = g.material("tiles", pbrMetallicRoughness={"baseColorTexture": {"index": colour, "extensions": transform},
                                                  "metallicRoughnessTexture": {"index": rough, "extensions": transform},
                                                  "metallicFactor": 1, "roughnessFactor": 0.8},
                   normalTexture={"index": bumps, "scale": 0.7, "extensions": transform})
    plain = g.material("plain", pbrMetallicRoughness={"baseColorFactor": [0.2, 0.4, 0.8, 1], "metallicFactor": 0,
                                                      "roughnessFactor": 0.3})
    pos, nor, uv, idx = cube(0.5)
    geometry = g.geometry(pos, idx, normals=nor, uvs=uv)
    box, small = g.primitive("box", geometry, m), g.primitive("small", geometry, plain)
    root = g.node(name="root", scale=[1.2, 1.2, 1.2], translation=[0, 0.6, 0])
    g.node(parent=root, name="box", mesh=box, rotation=[0, math.sin(0.35), 0, math.cos(0.35)])
    arm = g.node(parent=root, name="arm", translation=[1.1, 0, 0.3], rotation=[0, 0, math.sin(0.2), math.cos(0.2)])
    g.node(parent=arm, name="small", mesh=small, scale=[0.4, 0.4, 0.4], translation=[0, 0.2, 0])
    # Mirrored tangent frames: the tiled box with its uvs mirrored in u, and under a mirroring scale.
    flipped = g.primitive("flipped", g.geometry(pos, idx, normals=nor, uvs=[1 - c if k % 2 == 0 else c
                                                                            for k, c in enumerate(uv)]), m)
    g.node(parent=root, name="flipped uvs", mesh=flipped, scale=[0.35, 0.35, 0.35], translation=[-1.15, -0.3, 0.2])
    g.node(parent=root, name="mirrored", mesh=box, scale=[-0.35, 0.35, 0.35], translation=[-0.75, -0.3, 0.85])
    floor(g, 3, 3, 0.6)
    g.point_light([1, 1, 1], 15.0, translation=[1.5, 3, 2.5])
    pitched_camera(g, 45, [0.4, 2.2, 4.2], -15)
    g.write_glb(os.path.join(HERE, "textured.glb"))


def conventions():
    g = Gltf()
    # Roughness 0: Blender's Principled diffuse (Disney's) is Lambert's near the normal only then.
    plane = g.material("plane", pbrMetallicRoughness={"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0,
                                                      "roughnessFactor": 0},
                       extensions={"KHR_materials_specular": {"specularFactor": 0}})
    g.node(mesh=g.mesh("plane", [0, -1, 0, 2, -1, 0, 2, 1, 0, 0, 1, 0], [0, 1, 2, 0, 2, 3], plane))
    lamp = g.material("lamp", emissiveFactor=[1, 1, 1],
                      pbrMetallicRoughness={"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0},
                      extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 2.0},
                                  "KHR_materials_specular": {"specularFactor": 0}})
    g.node(mesh=g.mesh("lamp", [-2, -1, 0, -0.5, -1, 0, -0.5, 1, 0, -2, 1, 0], [0, 1, 2, 0, 2, 3], lamp))
    g.point_light([1, 1, 1], 10.0, translation=[1, 0, 2])
    g.camera("top", math.radians(60), 4 / 3, translation=[0, 0, 5])
    g.write_glb(os.path.join(HERE, "conventions.glb"))


def rotation_to(direction):
    """The quaternion [x, y, z, w] that turns a light's -z onto the unit `direction`."""
    x, y, z = direction
    # the half-way vector h between -z and d: the rotation by 180 degrees about h maps -z to d
    hx, hy, hz = x, y, z - 1.0
    n = math.sqrt(hx * hx + hy * hy + hz * hz)
    return [hx / n, hy / n, hz / n, 0.0]


def sun_and_spot():
    """A floor, a sphere and a block lit by a directional light (3 lux) and a spot light."""
    g = Gltf()
    diffuse = {"KHR_materials_specular": {"specularFactor": 0}}
    grey = g.material("floor", pbrMetallicRoughness={"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0,
                                                     "roughnessFactor": 0}, extensions=diffuse)
    g.node(mesh=g.mesh("floor", [-3, 0, -3, -3, 0, 3, 3, 0, 3, 3, 0, -3], [0, 1, 2, 0, 2, 3], grey,
                       normals=[0, 1, 0] * 4))
    clay = g.material("clay", pbrMetallicRoughness={"baseColorFactor": [0.8, 0.45, 0.3, 1], "metallicFactor": 0,
                                                    "roughnessFactor": 0}, extensions=diffuse)
    pos, nor, _, idx = uv_sphere(0.5, 32, 16)
    g.node(mesh=g.mesh("sphere", pos, idx, clay, normals=nor), translation=[-0.8, 0.5, 0])
    pos, nor, _, idx = cube(0.4)
    g.node(mesh=g.mesh("block", pos, idx, grey, normals=nor), translation=[0.8, 0.4, -0.3])
    sun = [-0.4, -0.8, -0.45]
    n = math.sqrt(sum(c * c for c in sun))
    g.light({"type": "directional", "color": [1, 0.95, 0.9], "intensity": 3.0},
            rotation=rotation_to([c / n for c in sun]))
    g.light({"type": "spot", "color": [0.6, 0.7, 1], "intensity": 6.0,
             "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.5}},
            translation=[1.2, 2.5, 1.5], rotation=rotation_to([-0.35 / 1.2, -1 / 1.2, -0.6 / 1.2]))
    pitched_camera(g, 45, [0, 2.2, 4.5], -22)
    g.write_glb(os.path.join(HERE, "sun-and-spot.glb"))


def cutouts():
    """Cut-outs under a low sun: a lattice fence (MASK, alphaCutoff 0.5, its texture's alpha), a
    leaf card (MASK, an ellipse of alpha), a tinted pane (BLEND, alpha 0.4) and a sphere behind
    them on a floor; the shadows show the holes, and the pane passes 0.6 of the light."""
    g = Gltf()
    g.extensions.add("KHR_materials_specular")
    diffuse = {"KHR_materials_specular": {"specularFactor": 0}}
    grey = g.material("floor", pbrMetallicRoughness={"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0,
                                                     "roughnessFactor": 1}, extensions=diffuse)
    g.node(mesh=g.mesh("floor", [-4, 0, -4, -4, 0, 4, 4, 0, 4, 4, 0, -4], [0, 1, 2, 0, 2, 3], grey,
                       normals=[0, 1, 0] * 4))
    lattice = g.image(png(32, 32, lambda x, y: (200, 160, 90, 255 if x % 8 < 2 or y % 8 < 2 else 0)))
    fence = g.material("fence", pbrMetallicRoughness={"baseColorTexture": {"index": lattice}, "metallicFactor": 0,
                                                      "roughnessFactor": 1},
                       alphaMode="MASK", alphaCutoff=0.5, doubleSided=True, extensions=diffuse)
    quad = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]
    quad_uvs = [0, 1, 1, 1, 1, 0, 0, 0]
    fence_mesh = g.mesh("fence", [c * 1.6 for c in quad], [0, 1, 2, 0, 2, 3], fence, normals=[0, 0, 1] * 4,
                        uvs=quad_uvs)
    g.node(name="fence", mesh=fence_mesh, translation=[-2.2, 0, 0.2])
    leaf_alpha = lambda x, y: 255 if ((x - 15.5) / 9) ** 2 + ((y - 15.5) / 15) ** 2 < 1 else 0
    leaf_png = g.image(png(32, 32, lambda x, y: (60, 150 + 2 * y, 50, leaf_alpha(x, y))))
    leaf = g.material("leaf", pbrMetallicRoughness={"baseColorTexture": {"index": leaf_png}, "metallicFactor": 0,
                                                    "roughnessFactor": 1},
                      alphaMode="MASK", doubleSided=True, extensions=diffuse)
    leaf_mesh = g.mesh("leaf", [c * 1.2 for c in quad], [0, 1, 2, 0, 2, 3], leaf, normals=[0, 0, 1] * 4, uvs=quad_uvs)
    g.node(name="leaf", mesh=leaf_mesh, translation=[-0.45, 0.3, 0.6], rotation=[0, math.sin(-0.3), 0, math.cos(-0.3)])
    pane = g.material("pane", pbrMetallicRoughness={"baseColorFactor": [0.3, 0.5, 0.9, 0.4], "metallicFactor": 0,
                                                    "roughnessFactor": 1},
                      alphaMode="BLEND", doubleSided=True, extensions=diffuse)
    g.node(name="pane", mesh=g.mesh("pane", [c * 1.3 for c in quad], [0, 1, 2, 0, 2, 3], pane,
                                    normals=[0, 0, 1] * 4), translation=[0.95, 0, 0.3])
    clay = g.material("clay", pbrMetallicRoughness={"baseColorFactor": [0.8, 0.45, 0.3, 1], "metallicFactor": 0,
                                                    "roughnessFactor": 1}, extensions=diffuse)
    pos, nor, _, idx = uv_sphere(0.45, 32, 16)
    g.node(mesh=g.mesh("sphere", pos, idx, clay, normals=nor), translation=[0.3, 0.45, -1.2])
    sun = [-0.3, -0.55, -0.78]
    n = math.sqrt(sum(c * c for c in sun))
    g.light({"type": "directional", "color": [1, 0.97, 0.92], "intensity": 3.0},
            rotation=rotation_to([c / n for c in sun]))
    pitched_camera(g, 45, [-0.35, 2.2, 5.6], -18)
    g.write_glb(os.path.join(HERE, "cutouts.glb"))


if __name__ == "__main__":
    cornell_box()
    sphere_grid()
    textured()
    conventions()
    sun_and_spot()
    cutouts()
