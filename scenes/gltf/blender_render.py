"""Renders a glTF file in Blender Cycles as Blender's own glTF importer reads it: the peer for
docs/gltf.md's comparison of conventions (camera, light units, emission, the metal-rough look).

  blender -b -noaudio --factory-startup --python scenes/gltf/blender_render.py -- \
      FILE.glb OUT.exr [--spp N] [--width W] [--height H] [--max-depth D] [--lighting SPEC|COMPAT|RAW]
      [--world R,G,B | --environment FILE] [--camera-from=X,Y,Z --camera-to=X,Y,Z --camera-up=X,Y,Z --vfov=DEGREES]

Settings as ../shared/cycles/scene_to_cycles.py chose them for the tracer's JSON scenes: a box
filter one pixel wide, no adaptive sampling, denoising or clamping, caustics on, paths of at
most D scattering vertices (Cycles' max_bounces D - 1), a world of constant radiance --world
(default 1, 1, 1: the tracer's neutral sky for a glTF file) or an equirectangular image
--environment (an Environment Texture node, equirectangular, linear, strength 1: the tracer's
--environment). Point lights get radius 0
(Cycles' default is a sphere light). --lighting is the importer's conversion of
KHR_lights_punctual intensities: SPEC (its default) turns candela into watts as
W = cd * 4 pi / 683, COMPAT as W = cd * 4 pi; RAW takes the number as watts. --camera-from
places a pinhole camera (from, to and up in glTF's axes; --vfov the vertical field of view) for
a file that has none: the one `tracer info FILE` reports. Write them with '=' (a coordinate
list may start with a minus sign)."""
import argparse
import math
import sys

import numpy

numpy.bool = bool  # Debian 12's numpy dropped the alias Blender 3.4's glTF importer uses

import bpy  # noqa: E402
import mathutils  # noqa: E402


def blender_axes(text):
    """glTF's X,Y,Z (y up) as Blender's (z up): (x, -z, y), as its glTF importer converts them."""
    x, y, z = (float(c) for c in text.split(","))
    return mathutils.Vector((x, -z, y))


def place_camera(scene, eye, target, up, vfov):
    eye, target, up = blender_axes(eye), blender_axes(target), blender_axes(up)
    cam = bpy.data.objects.new("tracer-camera", bpy.data.cameras.new("tracer-camera"))
    scene.collection.objects.link(cam)
    ahead = (target - eye).normalized()
    right = ahead.cross(up).normalized()
    cam_up = right.cross(ahead)
    # A Blender camera looks down its local -z with +y up.
    cam.matrix_world = mathutils.Matrix((
        (right.x, cam_up.x, -ahead.x, eye.x),
        (right.y, cam_up.y, -ahead.y, eye.y),
        (right.z, cam_up.z, -ahead.z, eye.z),
        (0, 0, 0, 1)))
    cam.data.sensor_fit = "VERTICAL"
    cam.data.angle_y = math.radians(float(vfov))
    return cam


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
    p.add_argument("--world", default="1,1,1")
    p.add_argument("--environment")
    p.add_argument("--camera-from")
    p.add_argument("--camera-to")
    p.add_argument("--camera-up", default="0,1,0")
    p.add_argument("--vfov", default="40")
    a = p.parse_args(argv)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=a.gltf, convert_lighting_mode=a.lighting)
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if a.camera_from:
        cameras = [place_camera(scene, a.camera_from, a.camera_to, a.camera_up, a.vfov)]
    if not cameras:
        sys.exit("blender_render.py: the file places no camera (give --camera-from and --camera-to)")
    scene.camera = cameras[0]
    # A primitive without a material has glTF's default one (base colour 1, metallic 1,
    # roughness 1); Blender's importer leaves it Blender's default grey instead.
    default = None
    for o in scene.objects:
        if o.type == "MESH" and not any(slot.material for slot in o.material_slots):
            if default is None:
                default = bpy.data.materials.new("gltf-default")
                default.use_nodes = True
                bsdf = default.node_tree.nodes["Principled BSDF"]
                bsdf.inputs["Base Color"].default_value = (1, 1, 1, 1)
                bsdf.inputs["Metallic"].default_value = 1.0
                bsdf.inputs["Roughness"].default_value = 1.0
            o.data.materials.clear()
            o.data.materials.append(default)
    for o in scene.objects:
        if o.type == "LIGHT":
            o.data.shadow_soft_size = 0.0
            print("light %s: %s %.6g W" % (o.name, o.data.type, o.data.energy))
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = tuple(float(c) for c in a.world.split(",")) + (1,)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    if a.environment:
        texture = world.node_tree.nodes.new("ShaderNodeTexEnvironment")
        texture.image = bpy.data.images.load(a.environment)
        texture.image.colorspace_settings.name = "Linear"
        texture.projection = "EQUIRECTANGULAR"
        texture.interpolation = "Linear"
        world.node_tree.links.new(texture.outputs["Color"], world.node_tree.nodes["Background"].inputs["Color"])
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
