"""Renders a glTF file in Blender Cycles as Blender's own glTF importer reads it: the peer for
docs/gltf.md's comparison of conventions (camera, light units, emission, the metal-rough look).

  blender -b -noaudio --factory-startup --python scenes/gltf/blender_render.py -- \
      FILE.glb OUT.exr [--spp N] [--width W] [--height H] [--max-depth D] [--lighting SPEC|COMPAT|RAW]

Settings as ../shared/cycles/scene_to_cycles.py chose them for the tracer's JSON scenes: a box
filter one pixel wide, no adaptive sampling, denoising or clamping, caustics on, paths of at
most D scattering vertices (Cycles' max_bounces D - 1), a black world (the tracer's default for
a file with lights). Point lights get radius 0 (Cycles' default is a sphere light). --lighting
is the importer's conversion of KHR_lights_punctual intensities: SPEC (its default) turns
candela into watts as W = cd * 4 pi / 683, COMPAT as W = cd * 4 pi; RAW takes the number as watts."""
import argparse
import sys

import numpy

numpy.bool = bool  # Debian 12's numpy dropped the alias Blender 3.4's glTF importer uses

import bpy  # noqa: E402


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    p = argparse.ArgumentParser(prog="blender_render.py")
    p.add_argument("gltf")
    p.add_argument("out")
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--height", type=int, default=120)
    p.add_argument("--max-depth", type=int, default=8)
    p.add_argument("--lighting", default="SPEC", choices=["SPEC", "COMPAT", "RAW"])
    a = p.parse_args(argv)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=a.gltf, convert_lighting_mode=a.lighting)
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if not cameras:
        sys.exit("blender_render.py: the file places no camera")
    scene.camera = cameras[0]
    for o in scene.objects:
        if o.type == "LIGHT":
            o.data.shadow_soft_size = 0.0
            print("light %s: %s %.6g W" % (o.name, o.data.type, o.data.energy))
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0, 0, 0, 1)
    scene.world = world

    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = a.width, a.height, 100
    r.filter_size = 1.0
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_depth = "32"
    scene.view_settings.view_transform = "Standard"
    c = scene.cycles
    c.device = "CPU"
    c.samples = a.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.pixel_filter_type = "BOX"
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.blur_glossy = 0.0
    bounces = max(a.max_depth - 1, 0)
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
    c.transparent_max_bounces = c.volume_bounces = bounces
    r.filepath = a.out
    bpy.ops.render.render(write_still=True)


main()
