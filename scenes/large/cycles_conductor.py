"""Blender Cycles' scene converter with one material kind more, for glossy.json.

Run as the converter itself, with its path in SCENE_TO_CYCLES:
  SCENE_TO_CYCLES=.../scene_to_cycles.py blender -b -noaudio --factory-startup \
      --python scenes/large/cycles_conductor.py -- SCENE.json OUT.exr [its options]

A white `conductor` (albedo [1, 1, 1], so Schlick's Fresnel is exactly 1 at every angle)
becomes Cycles' Glossy BSDF, GGX, colour 1, the same roughness (both square it into alpha).
Any other conductor is refused; every other kind is left to the converter.
"""
import os

PATH = os.environ["SCENE_TO_CYCLES"]
with open(PATH) as f:
    SOURCE = f.read().rstrip()
if not SOURCE.endswith("main()"):
    raise SystemExit("%s: expected the converter to end by calling main()" % PATH)
converter = {"__name__": "scene_to_cycles", "__file__": PATH}
exec(compile(SOURCE[: -len("main()")], PATH, "exec"), converter)
convert_other_kinds = converter["make_material"]


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


converter["make_material"] = make_material
converter["main"]()
