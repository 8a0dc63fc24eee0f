# Run by Blender (blender -b -P blender_check.py -- JOB.json): builds
# penumbra's scene in Cycles, renders the direct light with and without the
# objects casting shadows, and prints the RMSE of penumbra's traced
# reference against their ratio, the path tracer's shadow factor.
#
# The scene is built from penumbra's own scene file with penumbra's
# tessellation (src/scene/mesh.cpp), so both trace the same triangles; the
# sphere keeps penumbra's per-vertex normals. penumbra is y-up, Blender
# z-up: (x, y, z) -> (x, -z, y), a rotation.
import json
import math
import sys

import bpy
from mathutils import Matrix, Vector

CURVE_SEGMENTS = 48  # kCurveSegments, src/scene/mesh.hpp


TERMINATOR_GEOMETRY_OFFSET = 0.1


def to_blender(v):
    return Vector((v[0], -v[2], v[1]))


def shape_scale(shape):
    scale = shape.get("scale", 1.0)
    return list(scale) if isinstance(scale, list) else [scale] * 3


def shape_matrix(shape):
    # shape_transform: T * Rz * Ry * Rx * S.
    rx, ry, rz = (math.radians(a) for a in shape.get("rotation", [0, 0, 0]))
    m = Matrix.Translation(Vector(shape.get("position", [0, 0, 0])))
    m = m @ Matrix.Rotation(rz, 4, "Z") @ Matrix.Rotation(ry, 4, "Y") @ Matrix.Rotation(rx, 4, "X")
    sx, sy, sz = shape_scale(shape)
    return m @ Matrix.Diagonal(Vector((sx, sy, sz, 1.0)))


def plane(shape):
    n = 8
    hx, hz = 0.5 * shape["size"][0], 0.5 * shape["size"][2]
    verts = [(-hx + 2 * hx * i / n, 0.0, -hz + 2 * hz * j / n) for j in range(n + 1) for i in range(n + 1)]
    tris = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            c = a + n + 1
            tris += [(a, c, c + 1), (a, c + 1, a + 1)]
    return verts, tris, None


def box(shape):
    hx, hy, hz = (0.5 * s for s in shape["size"])
    verts, tris = [], []

    def face(c, u, v):
        b = len(verts)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            verts.append(tuple(c[k] + su * u[k] + sv * v[k] for k in range(3)))
        tris.extend([(b, b + 1, b + 2), (b, b + 2, b + 3)])

    face((hx, 0, 0), (0, 0, -hz), (0, hy, 0))
    face((-hx, 0, 0), (0, 0, hz), (0, hy, 0))
    face((0, hy, 0), (hx, 0, 0), (0, 0, -hz))
    face((0, -hy, 0), (hx, 0, 0), (0, 0, hz))
    face((0, 0, hz), (hx, 0, 0), (0, hy, 0))
    face((0, 0, -hz), (-hx, 0, 0), (0, hy, 0))
    return verts, tris, None


def sphere(shape):
    slices, stacks = CURVE_SEGMENTS, CURVE_SEGMENTS // 2
    r = shape["radius"]
    verts, normals, tris = [], [], []
    for j in range(stacks + 1):
        theta = math.pi * j / stacks
        for i in range(slices + 1):
            phi = 2 * math.pi * i / slices
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            verts.append(tuple(r * c for c in n))
            normals.append(n)
    for j in range(stacks):
        for i in range(slices):
            a = j * (slices + 1) + i
            c = a + slices + 1
            # Skip the poles' degenerate halves (zero area: nothing to hit).
            if j != stacks - 1:
                tris.append((a, c, c + 1))
            if j != 0:
                tris.append((a, c + 1, a + 1))
    return verts, tris, normals


CREASE_DEGREES = 80.0  # kCreaseDegrees, src/scene/model.cpp


def model(shape):
    # An OBJ's triangles (polygons as fans) with penumbra's vertex normals
    # (src/scene/smooth_normals.hpp): per corner, the area-weighted mean of
    # the normals of the triangles at its position within the crease angle
    # of its own triangle's. Normals are computed in the file's frame; the
    # caller rotates them (a uniform scale keeps their directions).
    verts, tris = [], []
    # The file's own normals (vn), which penumbra keeps when every corner
    # names one, as bent leaf-card normals must be.
    file_normals, corner_normals = [], []
    with open(shape["path"]) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                verts.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == "vn":
                file_normals.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == "f":
                ids = [int(p.split("/")[0]) for p in parts[1:]]
                ids = [i - 1 if i > 0 else len(verts) + i for i in ids]
                nids = [int(p.split("/")[2]) if p.count("/") == 2 and p.split("/")[2] else 0
                        for p in parts[1:]]
                nids = [i - 1 if i > 0 else (len(file_normals) + i if i < 0 else None)
                        for i in nids]
                for k in range(1, len(ids) - 1):
                    tris.append((ids[0], ids[k], ids[k + 1]))
                    corner_normals.append((nids[0], nids[k], nids[k + 1]))
    if tris and all(i is not None for c in corner_normals for i in c):
        normals = [[tuple(Vector(file_normals[j]).normalized()) for j in nids]
                   for nids in corner_normals]
        return share_vertices(verts, tris, normals)
    face_normals = []  # area-weighted (the cross product's length is twice the area)
    for a, b, c in tris:
        e1 = Vector(verts[b]) - Vector(verts[a])
        e2 = Vector(verts[c]) - Vector(verts[a])
        face_normals.append(e1.cross(e2))
    around = {}
    for t, tri in enumerate(tris):
        for i in tri:
            around.setdefault(verts[i], []).append(t)
    cos_crease = math.cos(math.radians(CREASE_DEGREES))
    normals = []
    for t, tri in enumerate(tris):
        own = face_normals[t].normalized() if face_normals[t].length > 0 else Vector((0, 1, 0))
        corners = []
        for i in tri:
            n = Vector((0.0, 0.0, 0.0))
            for u in around[verts[i]]:
                m = face_normals[u]
                if m.length > 0 and m.normalized().dot(own) >= cos_crease:
                    n += m
            corners.append(tuple(n.normalized() if n.length > 0 else own))
        normals.append(corners)
    return share_vertices(verts, tris, normals)


def share_vertices(verts, tris, normals):
    # One vertex per distinct (position, normal) pair of the triangles'
    # corners; normals[t][k] is corner k of triangle t's normal.
    out_verts, out_normals, out_tris, index = [], [], [], {}
    for tri, corners in zip(tris, normals):
        corner_ids = []
        for i, n in zip(tri, corners):
            key = (verts[i], n)
            if key not in index:
                index[key] = len(out_verts)
                out_verts.append(verts[i])
                out_normals.append(n)
            corner_ids.append(index[key])
        out_tris.append(tuple(corner_ids))
    return out_verts, out_tris, out_normals


BUILDERS = {"plane": plane, "box": box, "sphere": sphere, "model": model}


def add_object(name, shape, material):
    if shape["shape"] not in BUILDERS:
        raise SystemExit("pathtrace-check: shape '%s' is not supported" % shape["shape"])
    verts, tris, normals = BUILDERS[shape["shape"]](shape)
    m = shape_matrix(shape)
    world = [to_blender(m @ Vector(v)) for v in verts]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(world, [], tris)
    if normals is not None:
        rot = m.to_3x3().inverted().transposed()  # the normal matrix
        for p in mesh.polygons:
            p.use_smooth = True
        mesh.use_auto_smooth = True
        mesh.normals_split_custom_set_from_vertices(
            [to_blender((rot @ Vector(n)).normalized()) for n in normals])
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    # Cycles' "shadow terminator geometry offset" (Blender's default 0.1)
    # starts shadow rays near a smooth-shaded terminator from the smooth
    # surface the vertex normals describe, as penumbra's reference starts
    # them (Hanika 2021); no shading offset.
    if hasattr(obj, "cycles") and hasattr(obj.cycles, "shadow_terminator_geometry_offset"):
        obj.cycles.shadow_terminator_geometry_offset = TERMINATOR_GEOMETRY_OFFSET
        obj.cycles.shadow_terminator_offset = 0.0
    return obj


def stable_up(direction):
    # stable_up (src/shadow/light_view.cpp): a light view's up, and so the
    # orientation of its shadow map and of the reference's square.
    return Vector((0, 0, -1)) if abs(direction.y) > 0.99 else Vector((0, 1, 0))


def look_rotation(forward, up):
    # glm::lookAt's frame: s = f x up, u = s x f; the camera (and an area
    # light) looks down its local -z with local y up.
    f = forward.normalized()
    s = f.cross(up).normalized()
    u = s.cross(f)
    cols = [to_blender(s), to_blender(u), to_blender(-f)]
    return Matrix([[cols[c][r] for c in range(3)] for r in range(3)])


def main():
    global TERMINATOR_GEOMETRY_OFFSET
    job = json.load(open(sys.argv[sys.argv.index("--") + 1]))
    TERMINATOR_GEOMETRY_OFFSET = job.get("terminator_geometry_offset", 0.1)
    scene_desc = job["scene"]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = job["samples"]
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = 0
    # Direct light only, nothing culled or clamped.
    c.max_bounces = 0
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.volume_bounces = 0
    c.light_sampling_threshold = 0.0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    # A pixel sees (almost) only its centre, as penumbra's G-buffer does.
    c.pixel_filter_type = "GAUSSIAN"
    c.filter_width = 0.01
    scene.render.resolution_x = job["width"]
    scene.render.resolution_y = job["height"]
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = job.get("threads", 1)
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world

    material = bpy.data.materials.new("grey")
    material.use_nodes = True
    bsdf = material.node_tree.nodes["Principled BSDF"]
    material.node_tree.nodes.remove(bsdf)
    diffuse = material.node_tree.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (0.8, 0.8, 0.8, 1.0)
    material.node_tree.links.new(diffuse.outputs["BSDF"], material.node_tree.nodes["Material Output"].inputs["Surface"])

    objects = [add_object("shape%d" % i, s, material) for i, s in enumerate(scene_desc["objects"])]

    cam = scene_desc["camera"]
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(cam.get("fov", 45.0))
    cam_obj = bpy.data.objects.new("camera", cam_data)
    cam_obj.matrix_world = Matrix.Translation(to_blender(cam["position"])) @ look_rotation(
        Vector(cam["target"]) - Vector(cam["position"]), Vector(cam.get("up", [0, 1, 0]))
    ).to_4x4()
    scene.collection.objects.link(cam_obj)
    scene.camera = cam_obj

    # The light (the ratio of the two renders does not depend on its
    # strength): a spot light's square source, the sun's disc of
    # directions (its angular diameter), a point light's sphere.
    light = scene_desc["lights"][job.get("light", 0)]
    if light["type"] == "spot":
        position = Vector(light["position"])
        direction = (Vector(light["target"]) - position).normalized()
        light_data = bpy.data.lights.new("square", "AREA")
        light_data.shape = "SQUARE"
        light_data.size = job["light_size"]
        light_data.energy = 1000.0
        placement = (Matrix.Translation(to_blender(position)) @
                     look_rotation(direction, stable_up(direction)).to_4x4())
    elif light["type"] == "directional":
        direction = Vector(light["direction"]).normalized()
        light_data = bpy.data.lights.new("sun", "SUN")
        light_data.angle = math.radians(job["light_size"])
        light_data.energy = 3.0
        placement = look_rotation(direction, stable_up(direction)).to_4x4()
    elif light["type"] == "point":
        light_data = bpy.data.lights.new("sphere", "POINT")
        light_data.shadow_soft_size = 0.5 * job["light_size"]
        light_data.energy = 1000.0
        placement = Matrix.Translation(to_blender(Vector(light["position"])))
    else:
        raise SystemExit("pathtrace-check: unknown light type " + str(light["type"]))
    light_obj = bpy.data.objects.new("light", light_data)
    light_obj.matrix_world = placement
    light_obj.visible_camera = False
    scene.collection.objects.link(light_obj)

    width, height = job["width"], job["height"]

    def load(path):
        image = bpy.data.images.load(path)
        image.colorspace_settings.name = "Non-Color"
        image.alpha_mode = "STRAIGHT"
        return list(image.pixels[:])  # RGBA, rows bottom to top

    def render(path, shadows):
        for o in objects:
            o.visible_shadow = shadows
        scene.render.filepath = path
        bpy.ops.render.render(write_still=True)
        return load(path)

    out = job["out_dir"]
    shadowed = render(out + "/cycles-shadowed.exr", True)
    unshadowed = render(out + "/cycles-unshadowed.exr", False)
    ref = load(job["reference"])
    # The surface each pixel sees, as its normal (0.5 n + 0.5, penumbra's
    # `normals` view): an emissive override material, the same pixel filter.
    normal_material = bpy.data.materials.new("normal")
    normal_material.use_nodes = True
    nodes, links = normal_material.node_tree.nodes, normal_material.node_tree.links
    nodes.remove(nodes["Principled BSDF"])
    geometry = nodes.new("ShaderNodeNewGeometry")
    scale = nodes.new("ShaderNodeVectorMath")
    scale.operation = "MULTIPLY_ADD"
    scale.inputs[1].default_value = (0.5, 0.5, 0.5)
    scale.inputs[2].default_value = (0.5, 0.5, 0.5)
    emission = nodes.new("ShaderNodeEmission")
    links.new(geometry.outputs["Normal"], scale.inputs[0])
    links.new(scale.outputs["Vector"], emission.inputs["Color"])
    links.new(emission.outputs["Emission"], nodes["Material Output"].inputs["Surface"])
    bpy.context.view_layer.material_override = normal_material
    c.samples = min(c.samples, 64)
    normals = render(out + "/cycles-normals.exr", True)
    penumbra_normals = load(job["normals"])
    # Which object each pixel sees (its index + 1 as an emission, 0 for
    # none), to split the error between the ground (planes) and the objects.
    for i, o in enumerate(objects):
        o.pass_index = i + 1
    nodes.remove(geometry)
    nodes.remove(scale)
    info = nodes.new("ShaderNodeObjectInfo")
    links.new(info.outputs["Object Index"], emission.inputs["Strength"])
    emission.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    c.samples = 1
    index = render(out + "/cycles-object.exr", True)
    shapes = [s["shape"] for s in scene_desc["objects"]]

    def on_object(i):
        k = int(round(index[4 * i])) - 1
        return 0 <= k < len(shapes) and shapes[k] != "plane"

    def blender_normal(i):
        # Blender's z-up normal back in penumbra's y-up frame.
        x, y, z = (2.0 * normals[4 * i + k] - 1.0 for k in range(3))
        return (x, z, -y)

    def same_surface(i):
        n = blender_normal(i)
        m = [2.0 * penumbra_normals[4 * i + k] - 1.0 for k in range(3)]
        return sum((n[k] - m[k]) ** 2 for k in range(3)) < 0.03**2

    # The path tracer's shadow factor, 0 where no light arrives at all (as
    # penumbra's reference has it), written as a grey EXR beside the renders.
    factor = [0.0] * (width * height)
    for i in range(width * height):
        u = unshadowed[4 * i]
        factor[i] = shadowed[4 * i] / u if u > 0.0 else 0.0
    factor_image = bpy.data.images.new("factor", width, height, alpha=True, float_buffer=True)
    factor_image.colorspace_settings.name = "Non-Color"
    factor_pixels = []
    for f in factor:
        factor_pixels += [f, f, f, 1.0]
    factor_image.pixels[:] = factor_pixels
    factor_image.filepath_raw = out + "/cycles-factor.exr"
    factor_image.file_format = "OPEN_EXR"
    factor_image.save()
    # And the difference, penumbra - Cycles, as a PNG: 0.5 grey is none,
    # white +0.1 or more, black -0.1 or less.
    diff_image = bpy.data.images.new("difference", width, height, alpha=True)
    diff_image.colorspace_settings.name = "Non-Color"
    diff_pixels = []
    for i, f in enumerate(factor):
        d = 0.5 + 5.0 * (ref[4 * i] - f) if ref[4 * i + 3] >= 0.5 else 0.5
        d = min(max(d, 0.0), 1.0)
        diff_pixels += [d, d, d, 1.0]
    diff_image.pixels[:] = diff_pixels
    diff_image.filepath_raw = out + "/difference.png"
    diff_image.file_format = "PNG"
    diff_image.save()

    # The pixels measured: judged by penumbra (inside the spot's cone,
    # reached by some light), seeing the same surface in both (normals
    # within 0.03: not a silhouette that passes within a rasterizer's
    # vertex snap of the pixel's centre), and receiving at least 10 % of
    # the median unshadowed light: below that the factor is a ratio of
    # small numbers (along a smooth-shaded terminator) that a stray sample
    # decides.
    judged = [i for i in range(width * height) if ref[4 * i + 3] >= 0.5]
    median = sorted(unshadowed[4 * i] for i in judged)[len(judged) // 2]
    aligned = [i for i in judged if same_surface(i)]
    lit = [i for i in aligned if unshadowed[4 * i] >= 0.1 * median]

    def rmse(pixels, image=None):
        image = ref if image is None else image
        return math.sqrt(sum((image[4 * i] - factor[i]) ** 2 for i in pixels) / len(pixels))

    errors = [ref[4 * i] - factor[i] for i in lit]
    objects_lit = [i for i in lit if on_object(i)]
    objects_judged = [i for i in aligned if on_object(i)]
    ground_lit = [i for i in lit if not on_object(i)]
    # Pixels penumbra leaves unjudged as reached by no light (0, alpha 0)
    # where Cycles lights the same surface, against every pixel Cycles lights
    # with at least 1 % of the median light (a tenth of what the RMSE
    # needs). Below that lie pixels one of Cycles' samples lit across a
    # silhouette (the default scene's sphere against the ground: one
    # sample of 512, its light the ground's over 512) and faces edge-on to
    # the source, of which a sliver too thin for the reference's points
    # lies above the horizon; `unjudged_any_light` counts them too.
    def unjudged(pixels):
        return [i for i in pixels
                if ref[4 * i + 3] < 0.5 and ref[4 * i] == 0.0 and same_surface(i)]
    cycles_any_light = [i for i in range(width * height) if shadowed[4 * i] > 0.0]
    cycles_lit = [i for i in cycles_any_light if shadowed[4 * i] >= 0.01 * median]
    unjudged_lit = unjudged(cycles_lit)
    result = {
        "light_size": job["light_size"],
        "pixels": len(judged),
        "rmse_all": rmse(judged),
        "pixels_same_surface": len(aligned),
        "pixels_measured": len(lit),
        "rmse": rmse(lit),
        "mean_error": sum(errors) / len(errors),
        "max_error": max(abs(e) for e in errors),
        "pixels_objects": len(objects_lit),
        "rmse_objects": rmse(objects_lit) if objects_lit else 0.0,
        "rmse_objects_all": rmse(objects_judged) if objects_judged else 0.0,
        "pixels_ground": len(ground_lit),
        "rmse_ground": rmse(ground_lit) if ground_lit else 0.0,
        "pixels_cycles_lit": len(cycles_lit),
        "unjudged_but_lit": len(unjudged_lit),
        "pixels_cycles_any_light": len(cycles_any_light),
        "unjudged_any_light": len(unjudged(cycles_any_light)),
        # Each as (x, y from the bottom, Cycles' factor, its unshadowed light
        # over the median).
        "unjudged_but_lit_pixels": [(i % width, i // width, factor[i], unshadowed[4 * i] / median)
                                    for i in unjudged_lit[:50]],
    }
    # The techniques' shadow factors over the same pixels.
    result["techniques"] = []
    for technique in job.get("techniques", []):
        image = load(technique["image"])
        result["techniques"].append({
            "name": technique["name"],
            "rmse": rmse(lit, image),
            "rmse_objects": rmse(objects_lit, image) if objects_lit else 0.0,
            "rmse_ground": rmse(ground_lit, image) if ground_lit else 0.0,
        })
    print("PATHTRACE-CHECK " + json.dumps(result))


main()
