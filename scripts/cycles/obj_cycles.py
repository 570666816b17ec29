# SPDX-License-Identifier: BSD-3-Clause
# Renders an OBJ + MTL scene with Blender Cycles, headless, to a linear float EXR, from a camera
# given as to `mesolight trace` / `mesolight vlf render`:
#   blender -b --factory-startup --python obj_cycles.py -- SCENE.obj OUT.exr WIDTH HEIGHT \
#       SAMPLES SEED X,Y,Z,FX,FY,FZ UX,UY,UZ FOV_DEGREES
# Settings chosen to render what Mesolight's path tracer renders:
# - geometry read here (polygons as written, no importer axis conversion), world y-up kept;
# - materials: Diffuse BSDF of colour Kd; emitters add an Emission of colour Ke, strength 1, on
#   their front side only (one-sided, as the path tracer's): with strength 1, Cycles' mesh
#   emission is the radiance Ke itself, the path tracer's convention (no light falloff node: a
#   mesh emitter has none);
# - pixel filter: a box one pixel wide, as the path tracer's uniform jitter within the pixel;
# - no clamping, no denoising, no adaptive sampling, no "filter glossy", 1024 bounces (Russian
#   roulette ends paths; both are unbiased), black world;
# - view transform Standard and a 32-bit float EXR: the linear radiance.
# Prints "cycles seconds S" (the render alone, without Blender's start-up and the scene set-up).
import math
import os
import sys
import time

import bpy
from mathutils import Matrix, Vector

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, exr_path = argv[0], argv[1]
width, height, samples, seed = int(argv[2]), int(argv[3]), int(argv[4]), int(argv[5])
camera_values = [float(x) for x in argv[6].split(",")]
up = Vector([float(x) for x in argv[7].split(",")])
fov = float(argv[8])

vertices, faces, face_materials, current, mtl_name = [], [], [], None, None
for line in open(obj_path):
    parts = line.split()
    if not parts:
        continue
    if parts[0] == "v":
        vertices.append(tuple(float(x) for x in parts[1:4]))
    elif parts[0] == "mtllib":
        mtl_name = parts[1]
    elif parts[0] == "usemtl":
        current = parts[1]
    elif parts[0] == "f":
        indices = [int(x.split("/")[0]) for x in parts[1:]]
        faces.append(tuple(i - 1 if i > 0 else len(vertices) + i for i in indices))
        face_materials.append(current)

materials = {}
mtl_path = os.path.join(os.path.dirname(obj_path), mtl_name or "")
for line in open(mtl_path):
    parts = line.split()
    if not parts:
        continue
    if parts[0] == "newmtl":
        name = parts[1]
        materials[name] = {"Kd": (0.5, 0.5, 0.5), "Ke": (0.0, 0.0, 0.0)}
    elif parts[0] in ("Kd", "Ke"):
        materials[name][parts[0]] = tuple(float(x) for x in parts[1:4])

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
mesh = bpy.data.meshes.new("scene")
mesh.from_pydata(vertices, [], faces)
mesh.update()
obj = bpy.data.objects.new("scene", mesh)
scene.collection.objects.link(obj)

names = sorted(materials)
for name in names:
    values = materials[name]
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    nodes = material.node_tree.nodes
    links = material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*values["Kd"], 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert, not Oren-Nayar
    if max(values["Ke"]) > 0.0:
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (*values["Ke"], 1.0)
        emission.inputs["Strength"].default_value = 1.0
        front = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs[0], front.inputs[0])
        links.new(emission.outputs[0], front.inputs[1])
        geometry = nodes.new("ShaderNodeNewGeometry")
        mix = nodes.new("ShaderNodeMixShader")
        links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        links.new(front.outputs[0], mix.inputs[1])
        links.new(diffuse.outputs[0], mix.inputs[2])
        links.new(mix.outputs[0], output.inputs["Surface"])
    else:
        links.new(diffuse.outputs[0], output.inputs["Surface"])
    mesh.materials.append(material)
for polygon, name in zip(mesh.polygons, face_materials):
    polygon.material_index = names.index(name)

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

# The camera frame of mesolight's PinholeCamera: forward to the focal point, right = forward x
# up, true up = right x forward. A Blender camera looks along its local -z, local +y up.
eye = Vector(camera_values[0:3])
forward = (Vector(camera_values[3:6]) - eye).normalized()
right = forward.cross(up).normalized()
true_up = right.cross(forward)
camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle = math.radians(fov)
camera_data.clip_start = 1e-3
camera_data.clip_end = 1e5
camera = bpy.data.objects.new("camera", camera_data)
rotation = Matrix((right, true_up, -forward)).transposed()
camera.matrix_world = Matrix.Translation(eye) @ rotation.to_4x4()
scene.collection.objects.link(camera)
scene.camera = camera

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.seed = seed
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.cycles.max_bounces = 1024
scene.cycles.diffuse_bounces = 1024
scene.cycles.glossy_bounces = 1024
scene.cycles.transmission_bounces = 1024
scene.cycles.transparent_max_bounces = 8
scene.cycles.sample_clamp_direct = 0.0
scene.cycles.sample_clamp_indirect = 0.0
scene.cycles.blur_glossy = 0.0
scene.cycles.caustics_reflective = True
scene.cycles.caustics_refractive = True
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
scene.render.resolution_x = width
scene.render.resolution_y = height
scene.render.resolution_percentage = 100
scene.render.use_persistent_data = False
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = exr_path
start = time.time()
bpy.ops.render.render(write_still=True)
print("cycles seconds %.2f" % (time.time() - start))
