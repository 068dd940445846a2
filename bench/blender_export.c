/* blender_export.c — a built scene written for Blender, so that Cycles renders the same geometry,
 * materials, camera and light as sylva (bench/cycles_render.py builds it in Blender and renders;
 * bench/cycles_noise.sh compares the two renderers' time to a noise level).
 *
 * usage: bench_blender_export SCENE OUTDIR [WxH]
 *
 * OUTDIR receives (docs/rendering.md, "Against Cycles"):
 *   scene.json            camera, sun, render settings, materials, the list of meshes and objects
 *   mesh_NAME.ply         binary little-endian PLY: vertex x y z nx ny nz s t (float), face
 *                         vertex_indices (uchar 3, int) and material (int, index into scene.json's
 *                         materials); the terrain (its apron included), the water, each object's
 *                         or model's mesh and each prototype once, in its own frame
 *   instances.ply         one vertex per plant or tuft of ground cover: m00 .. m23 (float, the
 *                         3x4 row-major transform prototype frame -> world) and prototype (int)
 *   texture_N.png         each material texture as stored (8-bit sRGB; alpha cut at one half, as
 *                         the renderer cuts it, where the material is alpha-masked)
 *   ground.png            the procedural ground's colour (as the POV-Ray export writes it)
 *   sky.exr               the sky's radiance toward every direction, equirectangular (Blender's
 *                         mapping: column u = 0.5 - atan2(y, x) / 2pi, row from the zenith down)
 * Ground cover is placed for the image size as `sylva render` places it. What Blender does not
 * get: the ground's finer octaves and micro-relief, bark bump mapping, the leaf coat's exact
 * model, the physical sky's aerial perspective and the Earth's curvature (the script approximates
 * or leaves them out; the document lists them).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli_scene.h"
#include "cli/cli_status.h"
#include "geometry/camera_frame.h"
#include "geometry/cutout.h"
#include "geometry/ground_texture.h"
#include "geometry/light_summary.h"
#include "geometry/terrain_apron.h"
#include "geometry/water_surface.h"
#include "io/exr_write.h"
#include "io/image_io.h"

#define SKY_W 1024u
#define SKY_H 512u
#define PATH_LEN 4096

static int out_path(const char *dir, char *p, const char *name, err_buf *err)
{
    if ((size_t)snprintf(p, PATH_LEN, "%s/%s", dir, name) >= PATH_LEN) return err_set(err, "%s/%s: path too long", dir, name);
    return 0;
}

static FILE *open_out(const char *dir, const char *name, char *path, err_buf *err)
{
    if (out_path(dir, path, name, err)) return NULL;
    FILE *f = fopen(path, "wb");
    if (!f) err_set(err, "%s: cannot write (%s)", path, strerror(errno));
    return f;
}

static int close_out(FILE *f, const char *path, err_buf *err)
{
    int bad = ferror(f);
    if (fclose(f) || bad) return err_set(err, "%s: write failed", path);
    return 0;
}

/* m as mesh_NAME.ply, positions carried by xf when given (NULL: as they are). */
static int write_mesh(const char *dir, const scene *s, const mesh *m, const xform3x4 *xf, const char *name, err_buf *err)
{
    char file[256], path[PATH_LEN];
    snprintf(file, sizeof file, "mesh_%s.ply", name);
    FILE *f = open_out(dir, file, path, err);
    if (!f) return -1;
    fprintf(f, "ply\nformat binary_little_endian 1.0\ncomment sylva %s\nelement vertex %u\n"
               "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
               "property float nz\nproperty float s\nproperty float t\nelement face %u\n"
               "property list uchar int vertex_indices\nproperty int material\nend_header\n",
            name, m->nv, m->nt);
    for (uint32_t v = 0; v < m->nv; v++) {
        float rec[8];
        const float *p = m->pos + 3 * v, *n = m->nrm + 3 * v;
        vec3 pw = v3(p[0], p[1], p[2]), nw = v3(n[0], n[1], n[2]);
        if (xf) { /* normals by the renderer's rule: the cofactor matrix, flipped for a mirror */
            pw = xf_point(xf, pw);
            vec3 t = xf_normal(xf, nw);
            if (v3_len(t) > 0) nw = v3_norm(t);
        }
        rec[0] = pw.x, rec[1] = pw.y, rec[2] = pw.z, rec[3] = nw.x, rec[4] = nw.y, rec[5] = nw.z;
        rec[6] = m->uv[2 * v], rec[7] = m->uv[2 * v + 1];
        fwrite(rec, sizeof rec, 1, f);
    }
    for (uint32_t t = 0; t < m->nt; t++) {
        unsigned char three = 3;
        int32_t rec[4] = {(int32_t)m->tri[3 * t], (int32_t)m->tri[3 * t + 1], (int32_t)m->tri[3 * t + 2],
                          (int32_t)scene_triangle_material(s, m, t)};
        fwrite(&three, 1, 1, f);
        fwrite(rec, sizeof rec, 1, f);
    }
    return close_out(f, path, err);
}

static int write_instances(const char *dir, const scene *s, err_buf *err)
{
    char path[PATH_LEN];
    FILE *f = open_out(dir, "instances.ply", path, err);
    if (!f) return -1;
    fprintf(f, "ply\nformat binary_little_endian 1.0\nelement vertex %u\n", s->n_instances);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++) fprintf(f, "property float m%d%d\n", r, c);
    fprintf(f, "property int prototype\nend_header\n");
    for (uint32_t i = 0; i < s->n_instances; i++) {
        fwrite(s->instances[i].xf.m, sizeof(float), 12, f);
        int32_t p = (int32_t)s->instances[i].prototype;
        fwrite(&p, sizeof p, 1, f);
    }
    return close_out(f, path, err);
}

/* texture t as texture_N.png; alpha cut at one half when cut. */
static int write_texture(const char *dir, const scene *s, uint32_t t, int cut, err_buf *err)
{
    const texture *tx = &s->textures[t];
    size_t n = (size_t)tx->width * tx->height;
    uint8_t *px = malloc(n * 4); /* owned here */
    if (!px) return err_nomem(err, "out of memory for texture %u", t);
    for (size_t k = 0; k < n; k++) {
        memcpy(px + 4 * k, tx->rgba + 4 * k, 3);
        px[4 * k + 3] = cut ? (cutout_texel_kept(tx->rgba[4 * k + 3]) ? 255 : 0) : 255;
    }
    char name[64], path[PATH_LEN];
    snprintf(name, sizeof name, "texture_%u%s.png", t, cut ? "_cut" : "");
    int rc = out_path(dir, path, name, err) || image_write_u8(path, tx->width, tx->height, 4, px, err);
    free(px);
    return rc ? -1 : 0;
}

/* The ground's image (as pov_ground.c writes it) and its placement into the json; nothing when
 * the terrain keeps its materials. */
static int write_ground(const char *dir, FILE *js, const scene *s, err_buf *err)
{
    ground_texture *g = NULL;
    if (!s->terrain || ground_texture_build(s, &g, err)) return s->terrain ? -1 : 0;
    if (!g) return 0;
    const sylva_heightfield *hf = s->terrain;
    char path[PATH_LEN];
    int rc = out_path(dir, path, "ground.png", err) || ground_texture_write_image(g, path, err);
    if (!rc)
        fprintf(js, "  \"ground\": {\"image\": \"ground.png\", \"origin\": [%.9g, %.9g], \"size\": [%.9g, %.9g], "
                    "\"beyond\": [%.9g, %.9g, %.9g]},\n",
                hf->x0, hf->y0, hf->dx * (hf->nx - 1), hf->dy * (hf->ny - 1), g->beyond.x, g->beyond.y, g->beyond.z);
    ground_texture_free(g);
    return rc ? -1 : 0;
}

static int write_sky(const char *dir, const light_summary *l, err_buf *err)
{
    float *rgb = calloc((size_t)SKY_W * SKY_H * 3, sizeof(float)); /* owned here */
    if (!rgb) return err_nomem(err, "out of memory for the sky's image");
    for (uint32_t r = 0; r < SKY_H && l->sky_kind != SKY_NONE; r++) {
        double el = M_PI * (0.5 - (r + 0.5) / SKY_H); /* row 0 at the zenith */
        for (uint32_t c = 0; c < SKY_W; c++) {
            double az = -2.0 * M_PI * ((c + 0.5) / SKY_W - 0.5); /* Blender: u = 0.5 - atan2(y, x) / 2pi */
            vec3 d = v3((float)(cos(el) * cos(az)), (float)(cos(el) * sin(az)), (float)sin(el));
            vec3 L = light_summary_sky(l, d);
            float *o = rgb + 3 * ((size_t)r * SKY_W + c);
            o[0] = L.x, o[1] = L.y, o[2] = L.z;
        }
    }
    char path[PATH_LEN];
    exr_frame fr = {.width = SKY_W, .height = SKY_H, .rgb = rgb};
    int rc = out_path(dir, path, "sky.exr", err) || exr_write(path, &fr, err);
    free(rgb);
    return rc ? -1 : 0;
}

static void json_vec(FILE *f, const char *key, const double *v, const char *tail)
{
    fprintf(f, "\"%s\": [%.9g, %.9g, %.9g]%s", key, v[0], v[1], v[2], tail);
}

static int export_scene(const char *dir, const scene *s, uint32_t w, uint32_t h, err_buf *err)
{
    light_summary l;
    if (light_summary_init(&l, &s->sun, &s->sky, s->site.origin[2], s->camera.position[2], 0, err)) return -1;
    if (s->camera.cylindrical || s->camera.f_number > 0 || s->camera.k1 != 0 || s->camera.k2 != 0)
        return err_set(err, "the export takes a pinhole camera only (no panorama, lens or distortion)");
    char path[PATH_LEN];
    FILE *js = open_out(dir, "scene.json", path, err);
    if (!js) return -1;
    int rc = -1;
    mesh *terrain = NULL, *water = NULL;
    const camera_settings *c = &s->camera;
    double fwd[3], right[3], up[3];
    camera_frame(c, fwd, right, up);
    fprintf(js, "{\n  \"camera\": {");
    json_vec(js, "position", c->position, ", ");
    json_vec(js, "forward", fwd, ", ");
    json_vec(js, "up", up, ", ");
    fprintf(js, "\"fov_deg\": %.9g},\n", c->fov_deg);
    fprintf(js, "  \"image\": {\"width\": %u, \"height\": %u, \"spp\": %u, \"max_depth\": %u, \"seed\": %llu},\n", w, h,
            s->image.spp, s->image.max_depth, (unsigned long long)s->image.seed);
    double sd[3] = {l.sun_dir.x, l.sun_dir.y, l.sun_dir.z}, se[3] = {l.sun_irradiance.x, l.sun_irradiance.y, l.sun_irradiance.z};
    fprintf(js, "  \"sun\": {\"on\": %d, ", l.sun_on);
    json_vec(js, "direction", sd, ", ");
    json_vec(js, "irradiance", se, ", ");
    fprintf(js, "\"angular_diameter_deg\": %.9g},\n", s->sun.angular_diameter_deg);
    fprintf(js, "  \"sky\": {\"image\": \"sky.exr\", \"aerial_perspective_left_out\": %d},\n",
            l.sky_kind == SKY_PHYSICAL);
    if (write_sky(dir, &l, err) || write_ground(dir, js, s, err)) goto done;
    /* materials: each textured one's texture written once per cut (a texture may serve both) */
    fprintf(js, "  \"materials\": [\n");
    for (uint32_t i = 0; i < s->n_materials; i++) {
        const material *m = &s->materials[i];
        int cut = m->texture >= 0 && cutout_material(s, m);
        fprintf(js, "    {\"kind\": \"%s\", ", m->bsdf == SYLVA_BSDF_LEAF ? "leaf" : "lambert");
        double a[3] = {m->albedo.x, m->albedo.y, m->albedo.z}, t[3] = {m->transmittance.x, m->transmittance.y, m->transmittance.z};
        json_vec(js, "albedo", a, ", ");
        json_vec(js, "transmittance", t, ", ");
        if (m->texture >= 0) {
            int first = 1; /* the first material with this texture and cut writes it */
            for (uint32_t k = 0; k < i && first; k++)
                first = !(s->materials[k].texture == m->texture &&
                          (s->materials[k].texture >= 0 && cutout_material(s, &s->materials[k])) == cut);
            if (first && write_texture(dir, s, (uint32_t)m->texture, cut, err)) goto done;
            fprintf(js, "\"texture\": \"texture_%d%s.png\", ", m->texture, cut ? "_cut" : "");
        }
        fprintf(js, "\"alpha_cut\": %d}%s\n", cut, i + 1 < s->n_materials ? "," : "");
    }
    fprintf(js, "  ],\n  \"meshes\": [\n");
    const char *sep = "";
    if (s->terrain) {
        double eye[3] = {c->position[0], c->position[1], c->position[2]};
        terrain = terrain_mesh_with_apron(s->terrain, s->terrain_material, eye, err);
        if (!terrain || water_surface_build(s, &water, err)) goto done;
        if (write_mesh(dir, s, terrain, NULL, "terrain", err)) goto done;
        fprintf(js, "    {\"file\": \"mesh_terrain.ply\", \"ground\": true}"), sep = ",\n";
        if (water) {
            if (write_mesh(dir, s, water, NULL, "water", err)) goto done;
            fprintf(js, "%s    {\"file\": \"mesh_water.ply\"}", sep);
        }
    }
    char name[64];
    for (uint32_t o = 0; o < s->n_objects; o++) { /* models placed by their transform, baked in (few objects) */
        const xform3x4 *xf = NULL;
        const mesh *m = scene_object_mesh(s, o, &xf);
        if (!m->nt) continue;
        snprintf(name, sizeof name, "object_%u", o);
        if (write_mesh(dir, s, m, xf, name, err)) goto done;
        fprintf(js, "%s    {\"file\": \"mesh_%s.ply\"}", sep, name), sep = ",\n";
    }
    fprintf(js, "\n  ],\n  \"prototypes\": [\n");
    for (uint32_t p = 0; p < s->n_prototypes; p++) {
        snprintf(name, sizeof name, "prototype_%05u", p);
        if (write_mesh(dir, s, s->prototypes[p].mesh, NULL, name, err)) goto done;
        fprintf(js, "    \"mesh_%s.ply\"%s\n", name, p + 1 < s->n_prototypes ? "," : "");
    }
    fprintf(js, "  ],\n  \"instances\": %s\n}\n", s->n_instances ? "\"instances.ply\"" : "null");
    if (s->n_instances && write_instances(dir, s, err)) goto done;
    rc = 0;
done:
    mesh_free(terrain);
    mesh_free(water);
    if (close_out(js, path, rc ? &(err_buf){{0}} : err)) rc = -1;
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 4) {
        fprintf(stderr, "usage: %s SCENE OUTDIR [WxH]\n", argv[0]);
        return 1;
    }
    const char *outdir = argv[2];
    uint32_t w = 0, h = 0;
    if (argc == 4 && (sscanf(argv[3], "%ux%u", &w, &h) != 2 || !w || !h)) {
        fprintf(stderr, "%s: %s: the size is WxH, e.g. 320x180\n", argv[0], argv[3]);
        return 1;
    }
    if (mkdir(outdir, 0777) && errno != EEXIST) {
        fprintf(stderr, "%s: %s: %s\n", argv[0], outdir, strerror(errno));
        return 1;
    }
    cli_scene c;
    build_options bo = {.quiet = 1};
    cli_scene_use use = {.view = {.picture = 1, .width = w, .height = h}}; /* 0: the scene's size */
    int rc = cli_scene_open(&c, "blender-export", argv[1], &use, &bo);
    if (!rc && !w) w = c.scene->image.width, h = c.scene->image.height;
    if (!rc) {
        err_buf err = {{0}};
        if (export_scene(outdir, c.scene, w, h, &err)) {
            fprintf(stderr, "blender-export: %s\n", err.msg);
            rc = 2;
        } else
            fprintf(stderr, "blender-export: %u prototypes, %u instances, %u objects into %s\n", c.scene->n_prototypes,
                    c.scene->n_instances, c.scene->n_objects, outdir);
    }
    cli_scene_close(&c);
    return rc;
}
