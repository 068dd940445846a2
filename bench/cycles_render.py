# cycles_render.py - builds a scene exported by bench_blender_export in Blender and renders it
# with Cycles at a ladder of sample counts (bench/cycles_noise.sh; docs/rendering.md, "Against
# Cycles").
#
# usage: blender -b --factory-startup -P bench/cycles_render.py -- EXPORT_DIR OUT_DIR SPP,SPP,...
#        [--threads N] [--seed S] [--size WxH] [--cycles-defaults 1]
#
# Settings as sylva renders: CPU, N threads (default 2), box pixel filter one pixel wide, the
# scene's max_depth (Cycles' bounces = max_depth - 1 for every kind of bounce; transparent
# bounces through cut-out leaves do not count, as in sylva), no clamping, no denoising, no
# adaptive sampling, no glossy filter, linear EXR (view transform Standard). The scene is built
# and synchronised once (persistent data) by a first render at 1 sample, which is discarded;
# each later render prints
#   cycles spp N cpu C wall W render R sync S file PATH
# C and W the process's processor time and the wall time around the render call, R and S Cycles'
# own render and synchronisation times (from the render's metadata, 10 ms steps).
# --cycles-defaults 1 keeps Cycles' own pixel filter (Blackman-Harris, 1.5 pixels), clamping of
# indirect light (10) and glossy filter (1) instead, for a comparison of what they change.
#
# The scene: meshes from binary PLY (smooth-shaded with sylva's vertex normals as custom split
# normals), plants and ground cover as geometry-node instances (Instance on Points over a point
# mesh holding each instance's prototype, rotation and scale), materials (Lambertian albedo x
# texture; leaves as diffuse reflection plus diffuse transmission under a GGX coat of index 1.45
# and roughness 0.35, the alpha cut at one half by a nearest-texel lookup), the sun (direction,
# angular diameter, irradiance as strength) and sylva's sky radiance as an equirectangular world.
import json
import os
import sys
import time

import bpy
import numpy as np


def read_ply(path):
    """Vertex and face arrays of a binary little-endian PLY written by bench_blender_export."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").split("\n")
    elements, current = [], None
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "element":
            current = [w[1], int(w[2]), []]
            elements.append(current)
        elif w[0] == "property":
            if w[1] == "list":
                current[2].append((w[4], [("n", "u1"), ("i", "<i4", (3,))]))
            else:
                current[2].append((w[2], {"float": "<f4", "int": "<i4"}[w[1]]))
    out, offset = {}, end
    for name, count, props in elements:
        fields = []
        for pname, ptype in props:
            if isinstance(ptype, list):
                fields.extend(ptype)
            else:
                fields.append((pname, ptype))
        dt = np.dtype(fields)
        out[name] = np.frombuffer(data, dtype=dt, count=count, offset=offset)
        offset += dt.itemsize * count
    return out


def make_mesh(name, ply, materials):
    v, f = ply["vertex"], ply.get("face")
    me = bpy.data.meshes.new(name)
    nv, nt = len(v), 0 if f is None else len(f)
    me.vertices.add(nv)
    me.vertices.foreach_set("co", np.stack([v["x"], v["y"], v["z"]], axis=1).ravel())
    if nt:
        me.loops.add(3 * nt)
        me.loops.foreach_set("vertex_index", f["i"].astype(np.int32).ravel())
        me.polygons.add(nt)
        me.polygons.foreach_set("loop_start", np.arange(0, 3 * nt, 3, dtype=np.int32))
        me.polygons.foreach_set("loop_total", np.full(nt, 3, dtype=np.int32))
        used = np.unique(f["material"])
        slot = {int(m): k for k, m in enumerate(used)}
        for m in used:
            me.materials.append(materials[int(m)])
        me.polygons.foreach_set("material_index", np.vectorize(slot.get)(f["material"]).astype(np.int32)
                                if len(used) > 1 else np.zeros(nt, np.int32))
        me.polygons.foreach_set("use_smooth", np.ones(nt, bool))
        uv = me.uv_layers.new(name="uv")
        st = np.stack([v["s"], v["t"]], axis=1)[f["i"].ravel()]
        uv.data.foreach_set("uv", st.astype(np.float32).ravel())
    me.update()
    if nt:
        me.use_auto_smooth = True
        me.normals_split_custom_set_from_vertices(np.stack([v["nx"], v["ny"], v["nz"]], axis=1))
    return me


def make_material(k, m, folder, ground):
    mat = bpy.data.materials.new("material_%d" % k)
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    albedo = nt.nodes.new("ShaderNodeRGB")
    albedo.outputs[0].default_value = (*m["albedo"], 1.0)
    colour = albedo.outputs[0]
    alpha = None
    if "texture" in m:
        tex = nt.nodes.new("ShaderNodeTexImage")
        tex.image = bpy.data.images.load(os.path.join(folder, m["texture"]), check_existing=True)
        tex.image.alpha_mode = "CHANNEL_PACKED"  # colour and alpha independent, as sylva reads them
        tex.interpolation = "Closest" if m["alpha_cut"] else "Linear"
        mul = nt.nodes.new("ShaderNodeMixRGB")
        mul.blend_type, mul.inputs[0].default_value = "MULTIPLY", 1.0
        nt.links.new(colour, mul.inputs[1])
        nt.links.new(tex.outputs["Color"], mul.inputs[2])
        colour = mul.outputs[0]
        if m["alpha_cut"]:
            alpha = tex.outputs["Alpha"]
    if ground:  # the ground's image over the terrain's footprint from above, its mean beyond
        pos = nt.nodes.new("ShaderNodeNewGeometry")
        mapping = nt.nodes.new("ShaderNodeMapping")
        mapping.inputs["Location"].default_value = (-ground["origin"][0] / ground["size"][0],
                                                    -ground["origin"][1] / ground["size"][1], 0)
        mapping.inputs["Scale"].default_value = (1 / ground["size"][0], 1 / ground["size"][1], 1)
        nt.links.new(pos.outputs["Position"], mapping.inputs["Vector"])
        tex = nt.nodes.new("ShaderNodeTexImage")
        tex.image = bpy.data.images.load(os.path.join(folder, ground["image"]), check_existing=True)
        tex.extension = "CLIP"
        nt.links.new(mapping.outputs[0], tex.inputs["Vector"])
        beyond = nt.nodes.new("ShaderNodeRGB")
        beyond.outputs[0].default_value = (*ground["beyond"], 1.0)
        mix = nt.nodes.new("ShaderNodeMixRGB")
        nt.links.new(tex.outputs["Alpha"], mix.inputs[0])
        nt.links.new(beyond.outputs[0], mix.inputs[1])
        nt.links.new(tex.outputs["Color"], mix.inputs[2])
        colour = mix.outputs[0]
    diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
    nt.links.new(colour, diffuse.inputs["Color"])
    shader = diffuse.outputs[0]
    if m["kind"] == "leaf":
        trans = nt.nodes.new("ShaderNodeBsdfTranslucent")
        trans.inputs["Color"].default_value = (*m["transmittance"], 1.0)
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(shader, add.inputs[0])
        nt.links.new(trans.outputs[0], add.inputs[1])
        coat = nt.nodes.new("ShaderNodeBsdfGlossy")
        coat.distribution = "GGX"
        coat.inputs["Roughness"].default_value = 0.35 ** 0.5  # Cycles' alpha is roughness squared
        fresnel = nt.nodes.new("ShaderNodeFresnel")
        fresnel.inputs["IOR"].default_value = 1.45
        mix = nt.nodes.new("ShaderNodeMixShader")
        nt.links.new(fresnel.outputs[0], mix.inputs[0])
        nt.links.new(add.outputs[0], mix.inputs[1])
        nt.links.new(coat.outputs[0], mix.inputs[2])
        shader = mix.outputs[0]
    if alpha is not None:  # kept where alpha >= 1/2 (the texture's alpha is 0 or 1 already)
        cut = nt.nodes.new("ShaderNodeMath")
        cut.operation = "GREATER_THAN"
        cut.inputs[1].default_value = 0.5
        nt.links.new(alpha, cut.inputs[0])
        clear = nt.nodes.new("ShaderNodeBsdfTransparent")
        mix = nt.nodes.new("ShaderNodeMixShader")
        nt.links.new(cut.outputs[0], mix.inputs[0])
        nt.links.new(clear.outputs[0], mix.inputs[1])
        nt.links.new(shader, mix.inputs[2])
        shader = mix.outputs[0]
    nt.links.new(shader, out.inputs["Surface"])
    return mat


def euler_xyz(r):
    """Blender's XYZ Euler angles of rotation matrices r (n x 3 x 3), r = Rz Ry Rx."""
    beta = np.arcsin(np.clip(-r[:, 2, 0], -1, 1))
    return np.stack([np.arctan2(r[:, 2, 1], r[:, 2, 2]), beta, np.arctan2(r[:, 1, 0], r[:, 0, 0])], axis=1)


def make_instances(scene, folder, spec, protos):
    v = read_ply(os.path.join(folder, spec))["vertex"]
    n = len(v)
    m = np.stack([v["m%d%d" % (r, c)] for r in range(3) for c in range(4)], axis=1).reshape(n, 3, 4).astype(np.float64)
    lin, t = m[:, :, :3], m[:, :, 3]
    scale = np.linalg.norm(lin, axis=1)  # column lengths
    rot = lin / scale[:, None, :]
    det = np.linalg.det(rot)
    scale[det < 0, 0] *= -1
    rot[det < 0, :, 0] *= -1
    eul = euler_xyz(rot)
    # what rotation x scale leaves out (shear): reported, expected 0
    back = rot * scale[:, None, :]
    shear = float(np.abs(back - lin).max()) if n else 0.0
    me = bpy.data.meshes.new("instance_points")
    me.vertices.add(n)
    me.vertices.foreach_set("co", t.astype(np.float32).ravel())
    for name, kind, data in (("proto", "INT", v["prototype"].astype(np.int32)),
                             ("rot", "FLOAT_VECTOR", eul.astype(np.float32).ravel()),
                             ("scl", "FLOAT_VECTOR", scale.astype(np.float32).ravel())):
        a = me.attributes.new(name, kind, "POINT")
        a.data.foreach_set("value" if kind == "INT" else "vector", data)
    ob = bpy.data.objects.new("instances", me)  # its points are not drawn: the modifier replaces them
    scene.collection.objects.link(ob)
    tree = bpy.data.node_groups.new("instance_plants", "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    nodes, links = tree.nodes, tree.links
    gin, gout = nodes.new("NodeGroupInput"), nodes.new("NodeGroupOutput")
    inst = nodes.new("GeometryNodeInstanceOnPoints")
    coll = nodes.new("GeometryNodeCollectionInfo")
    coll.inputs["Collection"].default_value = protos
    coll.inputs["Separate Children"].default_value = True
    coll.inputs["Reset Children"].default_value = True
    coll.transform_space = "ORIGINAL"
    attrs = {}
    for name, dtype in (("proto", "INT"), ("rot", "FLOAT_VECTOR"), ("scl", "FLOAT_VECTOR")):
        a = nodes.new("GeometryNodeInputNamedAttribute")
        a.data_type = dtype
        a.inputs["Name"].default_value = name
        attrs[name] = next(o for o in a.outputs if o.enabled)  # one "Attribute" socket per data type
    links.new(gin.outputs[0], inst.inputs["Points"])
    links.new(coll.outputs[0], inst.inputs["Instance"])
    inst.inputs["Pick Instance"].default_value = True
    links.new(attrs["proto"], inst.inputs["Instance Index"])
    links.new(attrs["rot"], inst.inputs["Rotation"])
    links.new(attrs["scl"], inst.inputs["Scale"])
    links.new(inst.outputs[0], gout.inputs[0])
    mod = ob.modifiers.new("instances", "NODES")
    mod.node_group = tree
    print("cycles: %d instances (largest shear left out %.2g)" % (n, shear), flush=True)


def build(folder):
    with open(os.path.join(folder, "scene.json")) as f:
        sc = json.load(f)
    scene = bpy.context.scene
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob)
    ground = sc.get("ground")
    materials = [make_material(k, m, folder, None) for k, m in enumerate(sc["materials"])]
    ground_materials = [make_material(k, m, folder, ground) for k, m in enumerate(sc["materials"])] if ground else None
    for k, spec in enumerate(sc["meshes"]):
        ply = read_ply(os.path.join(folder, spec["file"]))
        me = make_mesh("mesh_%d" % k, ply, ground_materials if spec.get("ground") and ground else materials)
        scene.collection.objects.link(bpy.data.objects.new("mesh_%d" % k, me))
    if sc["instances"]:
        protos = bpy.data.collections.new("prototypes")  # not linked to the scene: drawn only as instances
        for k, file in enumerate(sc["prototypes"]):
            me = make_mesh("prototype_%05d" % k, read_ply(os.path.join(folder, file)), materials)
            protos.objects.link(bpy.data.objects.new("prototype_%05d" % k, me))  # names sort in index order
        make_instances(scene, folder, sc["instances"], protos)
    cam = sc["camera"]
    from mathutils import Matrix, Vector
    fwd, up = Vector(cam["forward"]), Vector(cam["up"])
    right = fwd.cross(up)
    rot = Matrix((right, up, -fwd)).transposed()  # camera looks down its -Z with +Y up
    cd = bpy.data.cameras.new("camera")
    cd.sensor_fit, cd.angle = "HORIZONTAL", np.radians(cam["fov_deg"])
    cd.clip_start, cd.clip_end = 1e-3, 1e7
    co = bpy.data.objects.new("camera", cd)
    co.matrix_world = Matrix.Translation(Vector(cam["position"])) @ rot.to_4x4()
    scene.collection.objects.link(co)
    scene.camera = co
    sun = sc["sun"]
    if sun["on"]:
        e = sun["irradiance"]
        strength = max(e)
        ld = bpy.data.lights.new("sun", "SUN")
        ld.energy, ld.color = strength, [x / strength for x in e]
        ld.angle = np.radians(sun["angular_diameter_deg"])
        lo = bpy.data.objects.new("sun", ld)
        lo.rotation_euler = (-Vector(sun["direction"])).to_track_quat("-Z", "Y").to_euler()
        scene.collection.objects.link(lo)
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    env = world.node_tree.nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(os.path.join(folder, sc["sky"]["image"]))
    env.image.colorspace_settings.name = "Linear"
    world.node_tree.links.new(env.outputs[0], world.node_tree.nodes["Background"].inputs["Color"])
    scene.world = world
    return sc


def metadata_seconds(path, key):
    """Cycles' time `key` (e.g. render_time) from the EXR header's string attribute
    cycles.<view layer>.<key> ("MM:SS.ss"), in seconds; None when absent."""
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    at = head.find(("." + key + "\0").encode())
    if at < 0:
        return None
    at += len(key) + 2
    at = head.index(b"\0", at) + 1  # past the type name
    size = int.from_bytes(head[at:at + 4], "little")
    sec = 0.0
    for part in head[at + 4:at + 4 + size].decode("latin-1").split(":"):
        sec = 60 * sec + float(part)
    return sec


def main():
    args = sys.argv[sys.argv.index("--") + 1:]
    folder, out_dir, ladder = args[0], args[1], [int(x) for x in args[2].split(",")]
    opts = dict(zip(args[3::2], args[4::2]))
    threads, seed = int(opts.get("--threads", 2)), opts.get("--seed")
    t0 = time.perf_counter()
    sc = build(folder)
    print("cycles: scene imported in %.2f s" % (time.perf_counter() - t0), flush=True)
    scene = bpy.context.scene
    r, c = scene.render, scene.cycles
    r.engine = "CYCLES"
    c.device = "CPU"
    r.threads_mode, r.threads = "FIXED", threads
    w, h = sc["image"]["width"], sc["image"]["height"]
    if "--size" in opts:
        w, h = (int(x) for x in opts["--size"].split("x"))
    r.resolution_x, r.resolution_y, r.resolution_percentage = w, h, 100
    r.use_persistent_data = True
    bounces = max(sc["image"]["max_depth"] - 1, 0)
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
    c.volume_bounces = 0
    c.transparent_max_bounces = 1024
    if opts.get("--cycles-defaults") != "1":
        c.pixel_filter_type, c.filter_width = "BOX", 1.0
        c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
        c.blur_glossy = 0.0
    c.use_denoising = c.use_adaptive_sampling = False
    c.seed = int(seed) if seed is not None else int(sc["image"]["seed"])
    scene.view_settings.view_transform, scene.view_settings.look = "Standard", "None"
    scene.view_settings.exposure, scene.view_settings.gamma = 0.0, 1.0
    r.image_settings.file_format, r.image_settings.color_depth = "OPEN_EXR", "32"
    r.image_settings.exr_codec = "ZIP"
    os.makedirs(out_dir, exist_ok=True)
    for k, spp in enumerate([1] + ladder):
        c.samples = spp
        path = os.path.join(out_dir, "cycles_%s.exr" % (spp if k else "warmup"))
        r.filepath = path
        c0, w0 = time.process_time(), time.perf_counter()
        bpy.ops.render.render(write_still=True)
        cpu, wall = time.process_time() - c0, time.perf_counter() - w0
        if k:
            print("cycles spp %d cpu %.4f wall %.4f render %s sync %s file %s" % (
                spp, cpu, wall, metadata_seconds(path, "render_time"), metadata_seconds(path, "synchronization_time"),
                path), flush=True)
        else:
            print("cycles: scene built and synchronised in %.2f s (first render, 1 sample)" % wall, flush=True)


main()
