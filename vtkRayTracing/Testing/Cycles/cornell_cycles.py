# SPDX-License-Identifier: BSD-3-Clause
# Renders Mesolight's Cornell box (an OBJ + MTL written by `mesolight trace --scene cornell
# --export-obj`) with Blender Cycles, headless, to a linear float EXR of the same view as
# mesolight's CornellCamera:
#   blender -b --factory-startup --python cornell_cycles.py -- BOX.obj OUT.exr WIDTH HEIGHT SAMPLES
# The geometry is read from the OBJ here (no importer axis conversion): Blender's world keeps
# the box's y-up millimetres, and the camera is turned to match. Materials: Diffuse BSDF with
# Kd; emitters emit Ke on their front side only (one-sided, as in the path tracer) and are
# diffuse behind. No clamping, no denoising, many bounces: an unbiased reference.
import math
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, exr_path = argv[0], argv[1]
width, height, samples = int(argv[2]), int(argv[3]), int(argv[4])

vertices, faces, face_materials, current = [], [], [], None
for line in open(obj_path):
    parts = line.split()
    if not parts:
        continue
    if parts[0] == "v":
        vertices.append(tuple(float(x) for x in parts[1:4]))
    elif parts[0] == "usemtl":
        current = parts[1]
    elif parts[0] == "f":
        faces.append(tuple(int(x.split("/")[0]) - 1 for x in parts[1:4]))
        face_materials.append(current)

materials = {}
mtl_path = os.path.splitext(obj_path)[0] + ".mtl"
for line in open(mtl_path):
    parts = line.split()
    if not parts:
        continue
    if parts[0] == "newmtl":
        name = parts[1]
        materials[name] = {"Kd": (0.8, 0.8, 0.8), "Ke": (0.0, 0.0, 0.0)}
    elif parts[0] in ("Kd", "Ke"):
        materials[name][parts[0]] = tuple(float(x) for x in parts[1:4])

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

mesh = bpy.data.meshes.new("cornell")
mesh.from_pydata(vertices, [], faces)
mesh.update()
box = bpy.data.objects.new("cornell", mesh)
scene.collection.objects.link(box)

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

# mesolight's CornellCamera: at (278, 273, -800) looking along +z, up +y, 39.3077 degrees
# vertical. A Blender camera looks along its local -z with local +y up: turn it 180 degrees
# about y.
camera_data = bpy.data.cameras.new("camera")
camera_data.sensor_fit = "VERTICAL"
camera_data.angle = math.radians(39.3077)
camera_data.clip_start = 1.0
camera_data.clip_end = 10000.0
camera = bpy.data.objects.new("camera", camera_data)
camera.location = (278.0, 273.0, -800.0)
camera.rotation_euler = (0.0, math.pi, 0.0)
scene.collection.objects.link(camera)
scene.camera = camera

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False
scene.cycles.use_adaptive_sampling = False
scene.cycles.max_bounces = 128
scene.cycles.diffuse_bounces = 128
scene.cycles.glossy_bounces = 128
scene.cycles.transparent_max_bounces = 8
scene.cycles.sample_clamp_direct = 0.0
scene.cycles.sample_clamp_indirect = 0.0
scene.cycles.filter_width = 0.01
scene.render.resolution_x = width
scene.render.resolution_y = height
scene.render.resolution_percentage = 100
scene.view_settings.view_transform = "Standard"
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = exr_path
bpy.ops.render.render(write_still=True)
