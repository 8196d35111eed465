# Blender (background) render of a water surface tidepool exported as PLY:
#   blender -b -P blender_render.py -- surface_00075.ply out.png
import math
import sys

import bpy
from mathutils import Vector

ply, out = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
try:
    bpy.ops.preferences.addon_enable(module="io_mesh_ply")
except Exception:
    pass
bpy.ops.import_mesh.ply(filepath=ply)
water = bpy.context.selected_objects[0]
for poly in water.data.polygons:
    poly.use_smooth = True

mat = bpy.data.materials.new("water")
mat.use_nodes = True
bsdf = mat.node_tree.nodes["Principled BSDF"]
bsdf.inputs["Base Color"].default_value = (0.15, 0.45, 0.85, 1.0)
bsdf.inputs["Roughness"].default_value = 0.05
bsdf.inputs["IOR"].default_value = 1.33
bsdf.inputs["Transmission"].default_value = 0.85
water.data.materials.append(mat)

bpy.ops.mesh.primitive_plane_add(size=6, location=(0.5, 0.125, -0.002))
floor = bpy.context.active_object
fmat = bpy.data.materials.new("floor")
fmat.use_nodes = True
fmat.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.75, 0.75, 0.72, 1.0)
floor.data.materials.append(fmat)

cam = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(cam)
cam.location = Vector((1.35, -0.95, 0.8))
cam.rotation_euler = (Vector((0.5, 0.12, 0.12)) - cam.location).to_track_quat("-Z", "Y").to_euler()
cam.data.lens = 35
scene.camera = cam

sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 3.0
sun.rotation_euler = (math.radians(40), math.radians(15), math.radians(30))
scene.collection.objects.link(sun)
world = bpy.data.worlds.new("world")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.8, 0.85, 0.9, 1.0)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.8
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 48
scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = 960, 540
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
