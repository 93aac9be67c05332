"""Blender Cycles' scene converter with two things more, for glossy.json and hdr-object.json.

Run as the converter itself, with its path in SCENE_TO_CYCLES:
  SCENE_TO_CYCLES=.../scene_to_cycles.py blender -b -noaudio --factory-startup \
      --python scenes/large/cycles_extras.py -- SCENE.json OUT.exr [its options]

* A white `conductor` (albedo [1, 1, 1], so Schlick's Fresnel is exactly 1 at every angle)
  becomes Cycles' Glossy BSDF, GGX, colour 1, the same roughness (both square it into alpha).
  Any other conductor is refused.
* An `environment` background (rotation 0) becomes the world's Environment Texture of the same
  file, linear filtering, times its strength. The tracer's map looks along +x at its centre,
  has +y at its top row and u growing towards +z; Cycles' equirectangular lookup has +x at the
  centre, +z at the top and u growing towards -y. The converter keeps the scene's coordinates
  as Blender's, so the lookup is given the direction (x, -z, y).
Every other kind is left to the converter.
"""
import json
import os

PATH = os.environ["SCENE_TO_CYCLES"]
with open(PATH) as f:
    SOURCE = f.read().rstrip()
if not SOURCE.endswith("main()"):
    raise SystemExit("%s: expected the converter to end by calling main()" % PATH)
converter = {"__name__": "scene_to_cycles", "__file__": PATH}
exec(compile(SOURCE[: -len("main()")], PATH, "exec"), converter)
convert_other_kinds = converter["make_material"]
configure_render = converter["configure"]
environment = {}  # the scene's environment background, set aside while the converter builds


def make_material(name, spec):
    if spec["type"] != "conductor":
        return convert_other_kinds(name, spec)
    if spec.get("albedo") != [1, 1, 1] or "eta" in spec:
        raise SystemExit("material %s: only a white conductor (albedo [1, 1, 1]) has a Glossy BSDF twin" % name)
    mat = converter["bpy"].data.materials.new(name)
    mat.use_nodes = True
    nodes = mat.node_tree
    for n in list(nodes.nodes):
        nodes.nodes.remove(n)
    out = nodes.nodes.new("ShaderNodeOutputMaterial")
    glossy = nodes.nodes.new("ShaderNodeBsdfGlossy")
    glossy.distribution = "GGX"
    glossy.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    glossy.inputs["Roughness"].default_value = float(spec.get("roughness", 0.0))
    nodes.links.new(glossy.outputs["BSDF"], out.inputs["Surface"])
    return mat


class JsonWithoutEnvironment:
    """The converter's json module, but a scene's environment background is handed to it as black."""

    @staticmethod
    def load(f):
        scene = json.load(f)
        bg = scene.get("background", {})
        if bg.get("type") == "environment":
            if float(bg.get("rotation", 0)) != 0:
                raise SystemExit("background: only rotation 0 is translated")
            environment.update(bg, base=os.path.dirname(os.path.abspath(f.name)))
            scene["background"] = {"type": "constant", "radiance": [0, 0, 0]}
        return scene


def configure(sc, args):
    configure_render(sc, args)
    if not environment:
        return
    bpy = converter["bpy"]
    world = bpy.context.scene.world
    nodes, links = world.node_tree.nodes, world.node_tree.links
    background = nodes["Background"]
    coords = nodes.new("ShaderNodeTexCoord")
    split = nodes.new("ShaderNodeSeparateXYZ")
    negate = nodes.new("ShaderNodeMath")
    negate.operation = "MULTIPLY"
    negate.inputs[1].default_value = -1.0
    join = nodes.new("ShaderNodeCombineXYZ")
    texture = nodes.new("ShaderNodeTexEnvironment")
    texture.interpolation = "Linear"
    texture.image = bpy.data.images.load(os.path.join(environment["base"], environment["file"]))
    links.new(coords.outputs["Generated"], split.inputs["Vector"])
    links.new(split.outputs["X"], join.inputs["X"])
    links.new(split.outputs["Z"], negate.inputs[0])
    links.new(negate.outputs["Value"], join.inputs["Y"])
    links.new(split.outputs["Y"], join.inputs["Z"])
    links.new(join.outputs["Vector"], texture.inputs["Vector"])
    links.new(texture.outputs["Color"], background.inputs["Color"])
    background.inputs["Strength"].default_value = float(environment.get("strength", 1.0))


converter["make_material"] = make_material
converter["json"] = JsonWithoutEnvironment
converter["configure"] = configure
converter["main"]()
