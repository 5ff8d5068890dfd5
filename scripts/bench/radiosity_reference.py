# Issue 19 item 12: the Cornell box by an independent path tracer (Blender's Cycles, Debian's
# `blender` package), per surface the area-mean radiosity B = π·L of its exposed part.
#
#   blender -b --factory-startup --python scripts/bench/radiosity_reference.py -- \
#       ours.json reference.json [--samples 256] [--seeds 4] [--pixels 96]
#
# ours.json comes from build/bin/radiosity_reference (the same scene: corners, reflectivity R,
# emission E). Every surface is a one-sided Lambertian: Diffuse BSDF with colour R (+ Emission
# of radiance E/π for the light). Black world (the box is open at the front), no clamping, no
# denoising, 128 diffuse bounces (0.78^128: nothing left), box pixel filter 1 px wide, linear
# float EXR (no view transform is applied to EXR data). For each surface an orthographic camera
# 1 mm in front of it, looking along −normal, frames it; a pixel counts when rays from its
# centre and 4 points near its corners all hit this surface first (excludes the rim pixels) and
# none of those points lies inside a body (the first surface along the normal met from behind:
# the floor under a block, which has no bottom face). Mean L of those pixels × π = B.
# Noise: the run is repeated with --seeds different seeds; reported: the mean over seeds and
# the standard error of that mean (std over seeds / √seeds), per channel.
import json
import math
import os
import sys
import tempfile

import bpy
from mathutils import Matrix, Vector

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if len(argv) < 2:
    raise SystemExit("usage: ... -- ours.json reference.json [--samples N] [--seeds S] [--pixels P] [--only NAME]")
src, dst = argv[0], argv[1]
opts = {"--samples": 256, "--seeds": 4, "--pixels": 96}
only = None
mode = "bake"
k = 2
while k < len(argv):
    if argv[k] == "--only":
        only = argv[k + 1]
    elif argv[k] == "--mode":
        mode = argv[k + 1]
    else:
        opts[argv[k]] = int(argv[k + 1])
    k += 2
data = json.load(open(src))

# --- the scene ------------------------------------------------------------------------------
for ob in list(bpy.data.objects):
    bpy.data.objects.remove(ob, do_unlink=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
cy = scene.cycles
cy.device = "CPU"
cy.use_denoising = False
cy.use_adaptive_sampling = False
cy.max_bounces = cy.diffuse_bounces = 128
cy.glossy_bounces = cy.transmission_bounces = cy.volume_bounces = cy.transparent_max_bounces = 0
cy.sample_clamp_direct = 0.0
cy.sample_clamp_indirect = 0.0
cy.caustics_reflective = cy.caustics_refractive = True
if hasattr(cy, "light_sampling_threshold"):
    cy.light_sampling_threshold = 0.0
cy.pixel_filter_type = "BOX"
cy.filter_width = 1.0
cy.film_exposure = 1.0
scene.render.film_transparent = False
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.threads_mode = "FIXED"
scene.render.threads = 2
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_mode = "RGB"
scene.render.image_settings.color_depth = "32"
scene.render.resolution_percentage = 100
scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
world = scene.world or bpy.data.worlds.new("w")
scene.world = world
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0

objects = []
for si, s in enumerate(data["surfaces"]):
    me = bpy.data.meshes.new(s["name"])
    me.from_pydata([tuple(v) for v in s["vertices"]], [], [list(range(len(s["vertices"])))])
    me.update()
    ob = bpy.data.objects.new(s["name"], me)
    scene.collection.objects.link(ob)
    mat = bpy.data.materials.new(s["name"])
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    dif = nt.nodes.new("ShaderNodeBsdfDiffuse")
    dif.inputs["Color"].default_value = (*s["reflectivity"], 1.0)
    dif.inputs["Roughness"].default_value = 0.0  # Lambert
    shader = dif.outputs["BSDF"]
    E = s["emission"]
    if max(E) > 0:
        em = nt.nodes.new("ShaderNodeEmission")
        L = [e / math.pi for e in E]  # Lambertian emitter: radiance = exitance / π
        top = max(L)
        em.inputs["Color"].default_value = (L[0] / top, L[1] / top, L[2] / top, 1.0)
        em.inputs["Strength"].default_value = top
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(dif.outputs["BSDF"], add.inputs[0])
        nt.links.new(em.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    nt.links.new(shader, out.inputs["Surface"])
    me.materials.append(mat)
    objects.append(ob)

cam_data = bpy.data.cameras.new("cam")
cam_data.type = "ORTHO"
cam_data.sensor_fit = "AUTO"
cam = bpy.data.objects.new("cam", cam_data)
scene.collection.objects.link(cam)
scene.camera = cam


def newell(vs):
    n = Vector((0, 0, 0))
    for a, b in zip(vs, vs[1:] + vs[:1]):
        n.x += (a.y - b.y) * (a.z + b.z)
        n.y += (a.z - b.z) * (a.x + b.x)
        n.z += (a.x - b.x) * (a.y + b.y)
    return n.normalized()


def render_surface(si, seeds, samples, pixels):
    s = data["surfaces"][si]
    vs = [Vector(v) for v in s["vertices"]]
    n = newell(vs)
    u = (vs[1] - vs[0])
    u = (u - u.dot(n) * n).normalized()
    w = n.cross(u)
    us = [v.dot(u) for v in vs]
    ws = [v.dot(w) for v in vs]
    h = max(max(us) - min(us), max(ws) - min(ws)) / pixels  # pixel size (m)
    rx = max(1, math.ceil((max(us) - min(us)) / h - 1e-9))
    ry = max(1, math.ceil((max(ws) - min(ws)) / h - 1e-9))
    c = vs[0].dot(n)  # plane offset
    uc, wc = 0.5 * (max(us) + min(us)), 0.5 * (max(ws) + min(ws))
    centre = uc * u + wc * w + c * n
    d = 1e-3
    cam.matrix_world = Matrix.Translation(centre + d * n) @ Matrix((u, w, n)).transposed().to_4x4()
    cam_data.ortho_scale = max(rx, ry) * h
    cam_data.clip_start = 1e-4
    cam_data.clip_end = 10.0
    scene.render.resolution_x, scene.render.resolution_y = rx, ry
    bpy.context.view_layer.update()
    dg = bpy.context.evaluated_depsgraph_get()
    mask = []
    for y in range(ry):
        for x in range(rx):
            ok = True
            for dx, dy in ((0.5, 0.5), (0.05, 0.05), (0.95, 0.05), (0.05, 0.95), (0.95, 0.95)):
                p = centre + ((x + dx) - rx / 2) * h * u + ((y + dy) - ry / 2) * h * w
                hit, loc, nor, idx, ob, mat = scene.ray_cast(dg, p + d * n, -n, distance=2 * d)
                if not hit or ob.name != objects[si].name:
                    ok = False
                    break
                # Inside a body (the floor under a block, which has no bottom): the first
                # surface along the normal is met from behind. Nobody sees it; left out, as
                # radiosity_reference leaves it out of our means.
                hit, loc, nor, idx, ob, mat = scene.ray_cast(dg, p + 1e-6 * n, n, distance=10.0)
                if hit and nor.dot(n) > 0:
                    ok = False
                    break
            if ok:
                mask.append(y * rx + x)
    means = []
    for seed in range(seeds):
        cy.seed = 1000 + seed
        cy.samples = samples
        path = os.path.join(tempfile.gettempdir(), "wb_radref_%d.exr" % os.getpid())
        scene.render.filepath = path
        bpy.ops.render.render(write_still=True)
        img = bpy.data.images.load(path, check_existing=False)
        px = list(img.pixels)
        ch = img.channels
        acc = [0.0, 0.0, 0.0]
        for i in mask:
            for c3 in range(3):
                acc[c3] += px[i * ch + c3]
        if os.environ.get("WB_RADREF_KEEP"):
            # Debugging aid: the render and its mask (masked pixels doubled in brightness).
            for i in mask:
                for c3 in range(3):
                    px[i * ch + c3] *= 2.0
            img.pixels[:] = px
            img.filepath_raw = os.path.join(os.environ["WB_RADREF_KEEP"], "%02d_%d.exr" % (si, seed))
            img.save()
        bpy.data.images.remove(img)
        means.append([math.pi * a / len(mask) for a in acc])
    mean = [sum(m[c3] for m in means) / seeds for c3 in range(3)]
    if seeds > 1:
        se = [math.sqrt(sum((m[c3] - mean[c3]) ** 2 for m in means) / (seeds - 1) / seeds) for c3 in range(3)]
    else:
        se = [float("nan")] * 3
    return {"name": s["name"], "B": mean, "stderr": se, "per_seed": means, "pixels": len(mask),
            "resolution": [rx, ry], "pixel_m": h}


def bake_surface(si, seeds, samples, pixels):
    # Cycles bakes the exitant radiance (COMBINED: emission + every bounce) at the centres of an
    # N × N texture mapped bilinearly onto the face: the whole face is sampled, its rim included
    # (the camera mode must drop the rim pixels, which biases the mean by ~1/N). Each texel is
    # weighted by the bilinear map's area element at its centre; texels inside a body (the floor
    # under a block) are left out, as radiosity_reference leaves them out of our means.
    s = data["surfaces"][si]
    vs = [Vector(v) for v in s["vertices"]]
    if len(vs) != 4:
        raise SystemExit("bake mode handles quads only: " + s["name"])
    n = newell(vs)
    ob = objects[si]
    me = ob.data
    if not me.uv_layers:
        uv = me.uv_layers.new(name="UV")
        for li, loop in enumerate(me.loops):
            uv.data[li].uv = [(0, 0), (1, 0), (1, 1), (0, 1)][loop.vertex_index]
    img = bpy.data.images.new("bake_%d" % si, pixels, pixels, float_buffer=True, alpha=False)
    nt = ob.active_material.node_tree
    tex = nt.nodes.new("ShaderNodeTexImage")
    tex.image = img
    for nd in nt.nodes:
        nd.select = False
    tex.select = True
    nt.nodes.active = tex
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    ob.select_set(True)
    bpy.context.view_layer.objects.active = ob
    scene.render.bake.margin = 0
    scene.render.bake.use_clear = True
    dg = bpy.context.evaluated_depsgraph_get()
    weights = []
    for y in range(pixels):
        for x in range(pixels):
            u, v = (x + 0.5) / pixels, (y + 0.5) / pixels
            P = (1 - u) * (1 - v) * vs[0] + u * (1 - v) * vs[1] + u * v * vs[2] + (1 - u) * v * vs[3]
            dPu = (1 - v) * (vs[1] - vs[0]) + v * (vs[2] - vs[3])
            dPv = (1 - u) * (vs[3] - vs[0]) + u * (vs[2] - vs[1])
            hit, loc, nor, idx, hob, mat = scene.ray_cast(dg, P + 1e-6 * n, n, distance=10.0)
            inside = hit and nor.dot(n) > 0
            weights.append(0.0 if inside else dPu.cross(dPv).length)
    wsum = sum(weights)
    means = []
    for seed in range(seeds):
        cy.seed = 1000 + seed
        cy.samples = samples
        bpy.ops.object.bake(type="COMBINED")
        px = list(img.pixels)
        acc = [0.0, 0.0, 0.0]
        for i, w in enumerate(weights):
            if w > 0.0:
                for c3 in range(3):
                    acc[c3] += w * px[i * 4 + c3]
        means.append([math.pi * a / wsum for a in acc])
    nt.nodes.remove(tex)
    bpy.data.images.remove(img)
    mean = [sum(m[c3] for m in means) / seeds for c3 in range(3)]
    if seeds > 1:
        se = [math.sqrt(sum((m[c3] - mean[c3]) ** 2 for m in means) / (seeds - 1) / seeds) for c3 in range(3)]
    else:
        se = [float("nan")] * 3
    return {"name": s["name"], "B": mean, "stderr": se, "per_seed": means,
            "pixels": sum(1 for w in weights if w > 0), "resolution": [pixels, pixels], "pixel_m": None}


results = []
for si in range(len(objects)):
    if only and only not in data["surfaces"][si]["name"]:
        continue
    if mode == "bake":
        r = bake_surface(si, opts["--seeds"], opts["--samples"], opts["--pixels"])
    else:
        r = render_surface(si, opts["--seeds"], opts["--samples"], opts["--pixels"])
    print("REF", r["name"], ["%.4f" % b for b in r["B"]], "±", ["%.4f" % e for e in r["stderr"]], r["pixels"], "px", flush=True)
    results.append(r)
json.dump({"renderer": "Blender %s Cycles" % bpy.app.version_string, "mode": mode, "samples": opts["--samples"],
           "seeds": opts["--seeds"], "pixels": opts["--pixels"], "surfaces": results}, open(dst, "w"), indent=1)
print("wrote", dst)
