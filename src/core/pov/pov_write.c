/* pov_write.c — the scene and species exports: file names, materials and their images, the
 * terrain, objects, species and plants, and the main scene file (see pov_write.h). */
#include "pov/pov_write.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "geometry/geometry.h"
#include "io/image_io.h"
#include "pov/pov_file.h"
#include "pov/pov_ground.h"
#include "pov/pov_mesh.h"
#include "pov/pov_names.h"
#include "pov/pov_number.h"
#include "util/srgb.h"

#define LINEAR_DIGITS 7   /* rotation and scale of a plant's matrix */
#define SETTING_DIGITS 9  /* camera, light and colours */

typedef struct export_paths {
    char base[POV_PATH_MAX]; /* the output path without its extension */
    const char *stem;        /* base's file name: how the files refer to one another */
} export_paths;

/* ------------------------------------------------------------------------------------------ */
/* file names                                                                                  */

static int split_path(const char *path, const char *ext, export_paths *ep, err_buf *err)
{
    size_t n = strlen(path), e = strlen(ext);
    if (n <= e || strcmp(path + n - e, ext))
        return err_set(err, "%s: the output name must end in %s", path, ext);
    if (n - e + 64 >= sizeof ep->base) return err_set(err, "%s: output path is too long", path);
    memcpy(ep->base, path, n - e);
    ep->base[n - e] = '\0';
    const char *slash = strrchr(ep->base, '/');
    ep->stem = slash ? slash + 1 : ep->base;
    if (!ep->stem[0]) return err_set(err, "%s: the output file needs a name before %s", path, ext);
    for (const char *p = ep->stem; *p; p++)
        if (*p == '"' || *p == '\\' || (unsigned char)*p < 0x20 || *p == 0x7f)
            return err_set(err, "%s: the output name may not hold quotes, backslashes or control "
                           "characters (POV-Ray reads the include and image names as strings)", path);
    return 0;
}

static int path_with(const export_paths *ep, const char *suffix, char out[POV_PATH_MAX], err_buf *err)
{
    if ((size_t)snprintf(out, POV_PATH_MAX, "%s%s", ep->base, suffix) >= POV_PATH_MAX)
        return err_set(err, "%s%s: output path is too long", ep->base, suffix);
    return 0;
}

static uint64_t file_size(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 && sb.st_size > 0 ? (uint64_t)sb.st_size : 0;
}

/* ------------------------------------------------------------------------------------------ */
/* materials                                                                                   */

static int material_is_grey(const material *m)
{
    return m->albedo.x == m->albedo.y && m->albedo.y == m->albedo.z;
}

static void material_image_name(const export_paths *ep, const char *ident, char *out, size_t n)
{
    snprintf(out, n, "%s_%s.png", ep->stem, ident);
}

/* The image of textured material i: the texture as stored (a grey albedo goes into the finish)
 * or with a coloured albedo multiplied in; alpha cut at one half when the renderer cuts. */
static int write_material_image(const scene *s, uint32_t i, const export_paths *ep, pov_export_stats *st,
                                err_buf *err)
{
    const material *m = &s->materials[i];
    const texture *t = &s->textures[m->texture];
    int cut = cutout_material(s, m), grey = material_is_grey(m);
    uint32_t ch = cut ? 4 : 3;
    size_t n = (size_t)t->width * t->height;
    uint8_t *px = malloc(n * ch);
    if (!px) return err_nomem(err, "out of memory for the %ux%u image of material \"%s\"", t->width, t->height, m->name);
    float albedo[3] = {m->albedo.x, m->albedo.y, m->albedo.z};
    for (size_t k = 0; k < n; k++) {
        const uint8_t *src = t->rgba + k * 4;
        uint8_t *dst = px + k * ch;
        for (int c = 0; c < 3; c++)
            dst[c] = grey ? src[c] : srgb8_from_linear(albedo[c] * texture_srgb_to_linear(src[c]));
        if (cut) dst[3] = cutout_texel_kept(src[3]) ? 255 : 0;
    }
    char ident[POV_IDENT_MAX], name[POV_PATH_MAX], path[POV_PATH_MAX];
    pov_material_identifier(s, i, ident);
    material_image_name(ep, ident, name, sizeof name);
    char suffix[POV_IDENT_MAX + 8];
    snprintf(suffix, sizeof suffix, "_%s.png", ident);
    int rc = path_with(ep, suffix, path, err);
    if (!rc) rc = image_write_u8(path, t->width, t->height, ch, px, err);
    free(px);
    if (rc) return -1;
    st->files++;
    st->bytes += file_size(path);
    return 0;
}

static void write_material(pov_file *pf, const scene *s, uint32_t i, const export_paths *ep)
{
    const material *m = &s->materials[i];
    char ident[POV_IDENT_MAX], name[256], line[512];
    pov_material_identifier(s, i, ident);
    pov_comment_text(m->name, name, sizeof name);
    pov_append_vec3f(line, m->albedo.x, m->albedo.y, m->albedo.z, NULL);
    pov_printf(pf, "// %s: material \"%s\", %s", ident, name,
               m->bsdf == SYLVA_BSDF_LEAF ? "leaf (its albedo only: the verification mode has no transmission)"
                                          : "Lambertian");
    if (m->texture < 0) {
        pov_printf(pf, "\n#declare %s = texture { pigment { rgb %s } finish { Sylva_finish } }\n\n", ident, line);
        return;
    }
    char image[POV_PATH_MAX];
    material_image_name(ep, ident, image, sizeof image);
    int grey = material_is_grey(m);
    pov_printf(pf, "; albedo %s %s%s\n", line,
               grey ? "in the finish" : "multiplied into the image",
               cutout_material(s, m) ? "; alpha cut at one half" : "");
    pov_printf(pf, "#declare %s = texture {\n  uv_mapping pigment { image_map { png \"%s\" gamma srgb } }\n", ident, image);
    if (grey) {
        char a[POV_NUMBER_MAX];
        pov_format_float(a, m->albedo.x);
        pov_printf(pf, "  finish { ambient %s diffuse %s }\n}\n\n", a, a);
    } else {
        pov_put(pf, "  finish { Sylva_finish }\n}\n\n");
    }
}

static void write_finish_declaration(pov_file *pf)
{
    pov_put(pf, "// POV-Ray's ambient (pigment x ambient x ambient_light) plus diffuse (pigment x diffuse x\n"
                "// light colour x cos) with these values is sylva's verification formula\n"
                "// albedo x (ambient + irradiance x cos).\n"
                "#declare Sylva_finish = finish { ambient 1 diffuse 1 }\n\n");
}

/* The materials file, or the materials part of a species include: wanted (NULL: all) selects
 * the materials; their images are written beside. */
static int write_materials(pov_file *pf, const scene *s, const uint8_t *wanted, const export_paths *ep,
                           pov_export_stats *st, err_buf *err)
{
    write_finish_declaration(pf);
    for (uint32_t i = 0; i < s->n_materials; i++) {
        if (wanted && !wanted[i]) continue;
        if (s->materials[i].texture >= 0 && write_material_image(s, i, ep, st, err)) return -1;
        write_material(pf, s, i, ep);
    }
    return 0;
}

/* ------------------------------------------------------------------------------------------ */
/* geometry                                                                                    */

static void bounds_add(double lo[3], double hi[3], double x, double y, double z)
{
    double v[3] = {x, y, z};
    for (int d = 0; d < 3; d++) {
        if (v[d] < lo[d]) lo[d] = v[d];
        if (v[d] > hi[d]) hi[d] = v[d];
    }
}

static void bounds_add_mesh(double lo[3], double hi[3], const mesh *m)
{
    if (!m || !m->nv) return;
    float a[3], b[3];
    mesh_bounds(m, a, b);
    bounds_add(lo, hi, a[0], a[1], a[2]);
    bounds_add(lo, hi, b[0], b[1], b[2]);
}

/* Grows the bounds by m's bounding box carried through xf (per instance: cheap next to writing
 * its line). */
static void bounds_add_placed(double lo[3], double hi[3], const mesh *m, const xform3x4 *xf)
{
    if (!m->nv) return;
    float a[3], b[3];
    mesh_bounds(m, a, b);
    for (int c = 0; c < 8; c++) {
        vec3 q = xf_point(xf, v3(c & 1 ? b[0] : a[0], c & 2 ? b[1] : a[1], c & 4 ? b[2] : a[2]));
        bounds_add(lo, hi, q.x, q.y, q.z);
    }
}

/* Bounds of everything POV-Ray will see, for placing the sun beyond it. */
static void scene_bounds(const scene *s, const mesh *terrain, double lo[3], double hi[3])
{
    for (int d = 0; d < 3; d++) lo[d] = INFINITY, hi[d] = -INFINITY;
    bounds_add_mesh(lo, hi, terrain);
    if (s->terrain && s->terrain->has_water) {
        double a[3], b[3];
        water_surface_extent(s->terrain, a, b);
        bounds_add(lo, hi, a[0], a[1], a[2]);
        bounds_add(lo, hi, b[0], b[1], b[2]);
    }
    for (uint32_t o = 0; o < s->n_objects; o++) {
        const xform3x4 *xf;
        const mesh *m = scene_object_mesh(s, o, &xf);
        if (xf) bounds_add_placed(lo, hi, m, xf);
        else bounds_add_mesh(lo, hi, m);
    }
    for (uint32_t i = 0; i < s->n_instances; i++)
        bounds_add_placed(lo, hi, s->prototypes[s->instances[i].prototype].mesh, &s->instances[i].xf);
    bounds_add(lo, hi, s->camera.position[0], s->camera.position[1], s->camera.position[2]);
}

static void write_header(pov_file *pf, const char *file, const char *what, const char *source)
{
    char src[512];
    pov_comment_text(source, src, sizeof src);
    pov_printf(pf, "// %s — %s\n// Written by sylva %s%s%s. Coordinates: sylva's (right-handed, Z up, metres).\n\n",
               file, what, SYLVA_VERSION, source ? " from " : "", source ? src : "");
}

static int write_terrain(const scene *s, const mesh *terrain, const mesh *water, const export_paths *ep,
                         const char *source, pov_export_stats *st, err_buf *err)
{
    char path[POV_PATH_MAX], name[POV_PATH_MAX];
    if (path_with(ep, "_terrain.inc", path, err)) return -1;
    snprintf(name, sizeof name, "%s_terrain.inc", ep->stem);
    pov_file pf;
    if (pov_file_open(&pf, path, err)) return -1;
    const sylva_heightfield *hf = s->terrain;
    write_header(&pf, name, "the terrain", source);
    pov_printf(&pf, "// Terrain: %u x %u heights %g m x %g m apart from (%g, %g), two triangles per cell;\n"
                    "// vertex normals from central differences, as sylva shades it.\n",
               hf->nx, hf->ny, hf->dx, hf->dy, hf->x0, hf->y0);
    char image[POV_PATH_MAX], image_name[POV_PATH_MAX];
    int ground = 0;
    snprintf(image_name, sizeof image_name, "%s_ground.png", ep->stem);
    if (path_with(ep, "_ground.png", image, err) ||
        pov_write_ground(&pf, s, image, image_name, "Sylva_ground", &ground, err))
        goto fail;
    if (ground) st->files++, st->bytes += file_size(image);
    if (pov_write_mesh(&pf, "Terrain", terrain, s, ground ? "Sylva_ground" : NULL, err)) goto fail;
    if (water) {
        pov_printf(&pf, "\n// Water: the surface at %g m over the terrain's extent.\n", hf->water_level);
        if (pov_write_mesh(&pf, "Water", water, s, NULL, err)) goto fail;
    }
    if (pov_file_finish(&pf, &st->bytes, err)) return -1;
    st->files++;
    return 0;
fail:
    pov_file_abort(&pf);
    return -1;
}

/* Appends " matrix <m00,m10,m20, m01,m11,m21, m02,m12,m22, tx,ty,tz>": the columns of xf;
 * counts non-finite numbers in *bad. */
static char *append_matrix(char *p, const xform3x4 *xf, int *bad)
{
    /* rounding noise of a rotation (sin 90 degrees = 4e-8) is written as 0 */
    float big = 0.0f;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) big = fmaxf(big, fabsf(xf->m[r][c]));
    p = pov_append_text(p, " matrix <");
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++) {
            float v = xf->m[r][c];
            p = pov_append_real(p, fabsf(v) <= 1e-6f * big ? 0.0 : v, LINEAR_DIGITS, bad);
            *p++ = ',';
        }
    for (int r = 0; r < 3; r++) {
        p = pov_append_position(p, xf->m[r][3], bad);
        *p++ = r < 2 ? ',' : '>';
    }
    return p;
}

static int write_objects(const scene *s, const export_paths *ep, const char *source, pov_export_stats *st,
                         err_buf *err)
{
    char path[POV_PATH_MAX], name[POV_PATH_MAX], ident[POV_IDENT_MAX], text[256];
    if (path_with(ep, "_objects.inc", path, err)) return -1;
    snprintf(name, sizeof name, "%s_objects.inc", ep->stem);
    pov_file pf;
    if (pov_file_open(&pf, path, err)) return -1;
    write_header(&pf, name, "the objects: shared models declared once as mesh2 and placed by matrix, other "
                            "objects each a mesh2 in world coordinates", source);
    char line[2 * POV_IDENT_MAX + 12 * POV_NUMBER_MAX + 64];
    int bad = 0;
    for (uint32_t m = 0; m < s->n_models; m++) {
        const mesh *mm = s->models[m].mesh;
        pov_model_identifier(s, m, ident);
        pov_comment_text(s->models[m].name, text, sizeof text);
        pov_printf(&pf, "// model \"%s\": %u triangles, shared by the objects that place it\n", text, mm->nt);
        if (!mm->nt) {
            pov_put(&pf, "// (no triangles: not declared, its objects are left out)\n\n");
            continue;
        }
        if (pov_write_mesh(&pf, ident, mm, s, NULL, err)) goto fail;
        pov_put(&pf, "\n");
    }
    for (uint32_t o = 0; o < s->n_objects; o++) {
        const object *ob = &s->objects[o];
        if (ob->mesh) continue;
        pov_object_identifier(s, o, ident);
        pov_comment_text(ob->name, text, sizeof text);
        if (!s->models[ob->model].mesh->nt) {
            pov_printf(&pf, "// object \"%s\" has no triangles: left out\n", text);
            continue;
        }
        char model_ident[POV_IDENT_MAX];
        pov_model_identifier(s, (uint32_t)ob->model, model_ident);
        char *p = pov_append_text(line, "#declare ");
        p = pov_append_text(p, ident);
        p = pov_append_text(p, " = object { ");
        p = pov_append_text(p, model_ident);
        p = append_matrix(p, &ob->xf, &bad);
        p = pov_append_text(p, " }  // \"");
        pov_put(&pf, line);
        pov_printf(&pf, "%s\"\n", text);
    }
    if (bad) {
        err_set(err, "%s: %d object transforms hold non-finite numbers", path, bad);
        goto fail;
    }
    for (uint32_t o = 0; o < s->n_objects; o++) {
        if (!s->objects[o].mesh) continue;
        pov_object_identifier(s, o, ident);
        pov_comment_text(s->objects[o].name, text, sizeof text);
        if (!s->objects[o].mesh->nt) {
            pov_printf(&pf, "// object \"%s\" has no triangles: left out\n\n", text);
            continue;
        }
        pov_printf(&pf, "// object \"%s\": %u triangles\n", text, s->objects[o].mesh->nt);
        if (pov_write_mesh(&pf, ident, s->objects[o].mesh, s, NULL, err)) goto fail;
        pov_put(&pf, "\n");
    }
    if (pov_file_finish(&pf, &st->bytes, err)) return -1;
    st->files++;
    return 0;
fail:
    pov_file_abort(&pf);
    return -1;
}

static void prototype_comment(pov_file *pf, const scene *s, uint32_t p, const char *ident)
{
    const prototype *pr = &s->prototypes[p];
    char text[256];
    pov_comment_text(s->species[pr->species].name, text, sizeof text);
    pov_printf(pf, "// %s: species \"%s\", variant %u of %u (age %g, height %g m): %u triangles\n", ident, text,
               pr->variant, s->species[pr->species].n_variants, pr->age, pr->height, pr->mesh->nt);
}

/* Declares the prototypes selected by wanted (NULL: all). */
static int write_prototypes(pov_file *pf, const scene *s, const uint8_t *wanted, err_buf *err)
{
    char ident[POV_IDENT_MAX];
    for (uint32_t p = 0; p < s->n_prototypes; p++) {
        if (wanted && !wanted[p]) continue;
        pov_prototype_identifier(s, p, ident);
        prototype_comment(pf, s, p, ident);
        if (!s->prototypes[p].mesh->nt) {
            pov_put(pf, "// (no triangles: not declared, its plants are left out)\n\n");
            continue;
        }
        if (pov_write_mesh(pf, ident, s->prototypes[p].mesh, s, NULL, err)) return -1;
        pov_put(pf, "\n");
    }
    return 0;
}

static int write_species(const scene *s, const export_paths *ep, const char *source, pov_export_stats *st,
                         err_buf *err)
{
    char path[POV_PATH_MAX], name[POV_PATH_MAX];
    if (path_with(ep, "_species.inc", path, err)) return -1;
    snprintf(name, sizeof name, "%s_species.inc", ep->stem);
    pov_file pf;
    if (pov_file_open(&pf, path, err)) return -1;
    write_header(&pf, name, "each species variant, declared once as a mesh2 in its own frame (base of the "
                            "trunk at the origin, growing along +Z)", source);
    if (write_prototypes(&pf, s, NULL, err)) {
        pov_file_abort(&pf);
        return -1;
    }
    if (pov_file_finish(&pf, &st->bytes, err)) return -1;
    st->files++;
    return 0;
}

static double xf_determinant(const xform3x4 *x)
{
    const float(*m)[4] = x->m;
    return (double)m[0][0] * ((double)m[1][1] * m[2][2] - (double)m[1][2] * m[2][1]) -
           (double)m[0][1] * ((double)m[1][0] * m[2][2] - (double)m[1][2] * m[2][0]) +
           (double)m[0][2] * ((double)m[1][0] * m[2][1] - (double)m[1][1] * m[2][0]);
}

static int write_plants(const scene *s, const export_paths *ep, const char *source, pov_export_stats *st,
                        err_buf *err)
{
    char path[POV_PATH_MAX], name[POV_PATH_MAX];
    if (path_with(ep, "_plants.inc", path, err)) return -1;
    snprintf(name, sizeof name, "%s_plants.inc", ep->stem);
    char(*ident)[POV_IDENT_MAX] = malloc((size_t)(s->n_prototypes ? s->n_prototypes : 1) * POV_IDENT_MAX);
    if (!ident) return err_nomem(err, "out of memory for %u prototype names", s->n_prototypes);
    for (uint32_t p = 0; p < s->n_prototypes; p++) pov_prototype_identifier(s, p, ident[p]);
    pov_file pf;
    if (pov_file_open(&pf, path, err)) {
        free(ident);
        return -1;
    }
    write_header(&pf, name, "the plants", source);
    pov_printf(&pf, "// %u plants, each a species variant of %s_species.inc placed by\n"
                    "// matrix <m00,m10,m20, m01,m11,m21, m02,m12,m22, tx,ty,tz>: the columns of sylva's\n"
                    "// 3x4 transform from the variant's frame to the world.\n",
               s->n_instances, ep->stem);
    uint64_t skipped = 0;
    int bad = 0;
    char line[POV_IDENT_MAX + 12 * POV_NUMBER_MAX + 64];
    for (uint32_t i = 0; i < s->n_instances; i++) {
        const instance *in = &s->instances[i];
        double det = xf_determinant(&in->xf);
        if (!s->prototypes[in->prototype].mesh->nt || !(fabs(det) > 0.0) || !isfinite(det)) {
            skipped++;
            continue;
        }
        char *p = pov_append_text(line, "object { ");
        p = pov_append_text(p, ident[in->prototype]);
        p = append_matrix(p, &in->xf, &bad);
        p = pov_append_text(p, " }\n");
        pov_put(&pf, line);
    }
    if (skipped)
        pov_printf(&pf, "// %llu plants left out: their variant has no triangles or their transform is singular\n",
                   (unsigned long long)skipped);
    free(ident);
    if (bad) {
        pov_file_abort(&pf);
        return err_set(err, "%s: %d plant transforms hold non-finite numbers", path, bad);
    }
    uint64_t bytes = 0;
    if (pov_file_finish(&pf, &bytes, err)) return -1;
    st->files++;
    st->bytes += bytes;
    st->instance_bytes = bytes;
    st->instances = s->n_instances - skipped;
    st->skipped = skipped;
    return 0;
}

/* ------------------------------------------------------------------------------------------ */
/* the main scene file                                                                         */

/* The thin lens as POV-Ray's focal blur (render/lens.h): aperture is the pupil's diameter in
 * metres, focal_point the point in focus on the view axis. POV-Ray has no vignette: a scene's
 * vignette is named in a comment and left to the comparison. */
static void write_lens(pov_file *pf, const camera_settings *c, const double forward[3])
{
    if (c->f_number > 0.0) {
        double p[3];
        for (int d = 0; d < 3; d++) p[d] = c->position[d] + forward[d] * c->focus_distance;
        char ap[POV_NUMBER_MAX], fp[128];
        pov_format_real(ap, 2.0 * camera_lens_radius(c), SETTING_DIGITS);
        pov_append_vec3(fp, p, SETTING_DIGITS, NULL);
        pov_printf(pf, "  aperture %s  // the lens's pupil, focal length / f-number, metres\n"
                       "  focal_point %s  // focus_distance along the view\n  blur_samples 64\n",
                   ap, fp);
    }
    if (c->vignette > 0.0) {
        char v[POV_NUMBER_MAX];
        pov_format_real(v, c->vignette, SETTING_DIGITS);
        pov_printf(pf, "  // camera.vignette %s (1 - s + s cos^4 off the axis) has no POV-Ray equivalent\n", v);
    }
}

static void write_camera(pov_file *pf, const camera_settings *c, uint32_t width, uint32_t height)
{
    double f[3], r[3], up[3];
    /* The rolled frame's up as POV-Ray's sky: POV-Ray builds right and up from sky and the view
     * as sylva does, so the turned view is the same. Unrolled, the up vector as given. */
    camera_frame(c, f, r, up);
    const double *sky = c->roll_deg != 0.0 ? up : c->up;
    char a[128], b[256], u[128], aspect[POV_NUMBER_MAX], fov[POV_NUMBER_MAX];
    pov_append_vec3(a, c->position, SETTING_DIGITS, NULL);
    /* look_at: the point given, or the location plus the view's unit direction as a sum that
     * POV-Ray adds in double precision. A point 1 m ahead written to 9 digits would carry the
     * location's rounding (1e-5 m 7 km from the origin) into the view's direction: 1e-5 rad,
     * a millimetre 100 m out, where grass blades are a few millimetres wide. */
    if (c->has_look_at) {
        pov_append_vec3(b, c->look_at, SETTING_DIGITS, NULL);
    } else {
        char *p = pov_append_vec3(b, c->position, SETTING_DIGITS, NULL);
        p = pov_append_text(p, " + ");
        pov_append_vec3(p, f, SETTING_DIGITS, NULL);
    }
    pov_append_vec3(u, sky, SETTING_DIGITS, NULL);
    pov_format_real(aspect, (double)width / height, SETTING_DIGITS);
    pov_format_real(fov, c->fov_deg, SETTING_DIGITS);
    if (c->cylindrical) {
        /* cylinder 1: the angle across as sylva's; the tangent of the elevation spans the up
         * vector's length, angle (radians) x height / width (render/camera.h) */
        char span[POV_NUMBER_MAX];
        pov_format_real(span, c->fov_deg * M_PI / 180.0 * height / width, SETTING_DIGITS);
        pov_printf(pf, "camera {\n  cylinder 1  // a panorama: angle across linear in x, tangent of the elevation in y\n"
                       "  location %s\n  sky %s  // sylva's up vector\n"
                       "  up y * %s  // the tangent of the elevation from the bottom row to the top\n"
                       "  right -x * %s  // negative: right-handed axes shown unmirrored\n"
                       "  angle %s  // horizontal field of view, degrees\n  look_at %s\n}\n\n",
                   a, u, span, aspect, fov, b);
        return;
    }
    pov_printf(pf, "camera {\n  perspective\n  location %s\n  sky %s  // sylva's up vector\n"
                   "  right -x * %s  // width / height; negative: right-handed axes shown unmirrored\n"
                   "  angle %s  // horizontal field of view, degrees\n  look_at %s\n",
               a, u, aspect, fov, b);
    write_lens(pf, c, f);
    pov_put(pf, "}\n\n");
}

static void write_sun(pov_file *pf, const scene *s, const light_summary *l, const double lo[3], const double hi[3])
{
    if (!l->sun_on) {
        pov_put(pf, "// No sun (sun.enabled is false or its irradiance 0): ambient light only.\n\n");
        return;
    }
    double c[3], r2 = 0;
    for (int d = 0; d < 3; d++) {
        c[d] = 0.5 * (lo[d] + hi[d]);
        r2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    }
    /* POV-Ray tests a parallel light's shadows up to the plane through its location: put it
     * beyond everything. */
    double dist = sqrt(r2) + 10.0, at[3];
    double dir[3] = {l->sun_dir.x, l->sun_dir.y, l->sun_dir.z};
    for (int d = 0; d < 3; d++) at[d] = c[d] + (fabs(dir[d]) < 1e-7 ? 0.0 : dir[d]) * dist; /* no 1e-15 noise */
    char loc[128], pt[128], col[128];
    pov_append_vec3(loc, at, SETTING_DIGITS, NULL);
    pov_append_vec3(pt, c, SETTING_DIGITS, NULL);
    pov_append_vec3f(col, l->sun_irradiance.x, l->sun_irradiance.y, l->sun_irradiance.z, NULL);
    pov_printf(pf, "// The sun: azimuth %g deg, elevation %g deg, as a point-like (parallel) light beyond the\n"
                   "// scene; its colour is the irradiance on a surface facing it (sun.irradiance x sun.color).\n"
                   "// Declare Sylva_coverage_only=1 to leave it out when only the alpha channel is wanted\n"
                   "// (its shadow rays through alpha-masked leaves are most of POV-Ray's work).\n"
                   "#ifndef (Sylva_coverage_only)\nlight_source {\n  %s\n  color rgb %s\n  parallel\n  point_at %s\n}\n#end\n\n",
               s->sun.azimuth_deg, s->sun.elevation_deg, loc, col, pt);
}

static int write_main(const scene *s, const light_summary *l, const export_paths *ep, const char *pov_path,
                      const pov_export_options *o, const double lo[3], const double hi[3], int has_water,
                      pov_export_stats *st, err_buf *err)
{
    uint32_t w = o && o->width ? o->width : s->image.width, h = o && o->height ? o->height : s->image.height;
    uint32_t spp = o && o->spp ? o->spp : s->image.spp, grid = 1;
    while ((grid + 1) * (grid + 1) <= spp) grid++;
    pov_file pf;
    if (pov_file_open(&pf, pov_path, err)) return -1;
    char name[POV_PATH_MAX], aa[64];
    snprintf(name, sizeof name, "%s.pov", ep->stem);
    write_header(&pf, name, "a POV-Ray 3.7 scene", o ? o->source : NULL);
    if (grid > 1) snprintf(aa, sizeof aa, "+A0.0 +AM1 +R%u -J", grid);
    else snprintf(aa, sizeof aa, "-A");
    pov_printf(&pf, "// Lit as sylva's verification mode (render --verify) lights it: sun with hard shadows,\n"
                    "// constant ambient light, Lambertian surfaces, no indirect light. Render it from this\n"
                    "// folder as sylva renders it (%ux%u, %u spp):\n"
                    "//   povray +I\"%s.pov\" +O\"%s.exr\" +FE +W%u +H%u %s\n"
                    "// Add +UA Declare=Sylva_sky_transmit=1 for an alpha channel that is 0 where the sky shows.\n\n",
               w, h, spp, ep->stem, ep->stem, w, h, aa);
    char amb[128], sky[3][POV_NUMBER_MAX];
    pov_append_vec3f(amb, l->ambient.x, l->ambient.y, l->ambient.z, NULL);
    pov_format_float(sky[0], l->sky_mean.x);
    pov_format_float(sky[1], l->sky_mean.y);
    pov_format_float(sky[2], l->sky_mean.z);
    pov_printf(&pf, "#version 3.7;\n\nglobal_settings {\n  assumed_gamma 1.0  // linear: every colour here is sylva's linear RGB\n"
                    "  ambient_light rgb %s  // sky.ambient\n"
                    "  max_trace_level 256  // rays pass through many alpha-masked leaves\n}\n\n", amb);
    pov_printf(&pf, "#ifndef (Sylva_sky_transmit)\n  #declare Sylva_sky_transmit = 0;\n#end\n"
                    "// The sky's mean radiance over the upper hemisphere.\n"
                    "background { rgbt <%s, %s, %s, Sylva_sky_transmit> }\n\n", sky[0], sky[1], sky[2]);
    if (l->fog_distance > 0.0) {
        char fog[128], dist[POV_NUMBER_MAX];
        pov_append_vec3f(fog, l->fog_color.x, l->fog_color.y, l->fog_color.z, NULL);
        pov_format_float(dist, (float)l->fog_distance);
        pov_printf(&pf, "// The physical sky's air as constant fog (docs/models/atmosphere.md): transmittance\n"
                        "// exp(-t / distance), distance = 1 / extinction at 550 nm at the camera, colour the horizon\n"
                        "// sky's mean. It covers the background too; declare Sylva_no_air=1 to leave it out.\n"
                        "#ifndef (Sylva_no_air)\n  fog { fog_type 1 distance %s color rgb %s }\n#end\n\n",
                   dist, fog);
    }
    if (s->earth.curvature)
        pov_put(&pf, "// The scene file bends sylva's camera rays for the Earth's curvature and refraction\n"
                     "// (earth.curvature); POV-Ray's rays are straight, so this file shows it on a flat Earth:\n"
                     "// distant things stand higher here than in sylva's render (docs/models/curvature.md).\n\n");
    write_camera(&pf, &s->camera, w, h);
    write_sun(&pf, s, l, lo, hi);
    pov_printf(&pf, "#include \"%s_materials.inc\"\n", ep->stem);
    if (s->terrain) pov_printf(&pf, "#include \"%s_terrain.inc\"\n", ep->stem);
    if (s->n_objects) pov_printf(&pf, "#include \"%s_objects.inc\"\n", ep->stem);
    if (s->n_prototypes) pov_printf(&pf, "#include \"%s_species.inc\"\n", ep->stem);
    pov_put(&pf, "\n");
    if (s->terrain) pov_put(&pf, "object { Terrain }\n");
    if (has_water) pov_put(&pf, "object { Water }\n");
    char ident[POV_IDENT_MAX], text[256];
    for (uint32_t i = 0; i < s->n_objects; i++) {
        if (!scene_object_mesh(s, i, NULL)->nt) continue;
        pov_object_identifier(s, i, ident);
        pov_comment_text(s->objects[i].name, text, sizeof text);
        pov_printf(&pf, "object { %s }  // \"%s\"\n", ident, text);
    }
    if (s->n_instances) pov_printf(&pf, "#include \"%s_plants.inc\"\n", ep->stem);
    if (pov_file_finish(&pf, &st->bytes, err)) return -1;
    st->files++;
    return 0;
}

int pov_export_scene(const scene *s, const char *pov_path, const pov_export_options *o,
                     pov_export_stats *st_out, err_buf *err)
{
    pov_export_stats st = {0};
    export_paths ep;
    if (split_path(pov_path, ".pov", &ep, err)) return -1;
    const char *source = o ? o->source : NULL;
    light_summary l;
    if (light_summary_init(&l, &s->sun, &s->sky, s->site.origin[2], s->camera.position[2], 0, err)) return -1;
    int rc = -1;
    mesh *terrain = NULL, *water = NULL;
    if (s->terrain) {
        /* the apron beyond the edge, as the path tracer has it, in the terrain's mesh */
        double eye[3] = {s->camera.position[0], s->camera.position[1], s->camera.position[2]};
        terrain = terrain_mesh_with_apron(s->terrain, s->terrain_material, eye, err);
        if (!terrain || water_surface_build(s, &water, err)) goto done;
    }
    char path[POV_PATH_MAX], name[POV_PATH_MAX];
    if (path_with(&ep, "_materials.inc", path, err)) goto done;
    snprintf(name, sizeof name, "%s_materials.inc", ep.stem);
    pov_file pf;
    if (pov_file_open(&pf, path, err)) goto done;
    write_header(&pf, name, "one texture per material", source);
    if (write_materials(&pf, s, NULL, &ep, &st, err)) {
        pov_file_abort(&pf);
        goto done;
    }
    if (pov_file_finish(&pf, &st.bytes, err)) goto done;
    st.files++;
    if (terrain && write_terrain(s, terrain, water, &ep, source, &st, err)) goto done;
    if (s->n_objects && write_objects(s, &ep, source, &st, err)) goto done;
    if (s->n_prototypes && write_species(s, &ep, source, &st, err)) goto done;
    if (s->n_instances && write_plants(s, &ep, source, &st, err)) goto done;
    double lo[3], hi[3];
    scene_bounds(s, terrain, lo, hi);
    if (write_main(s, &l, &ep, pov_path, o, lo, hi, water != NULL, &st, err)) goto done;
    rc = 0;
done:
    mesh_free(terrain);
    mesh_free(water);
    if (st_out) *st_out = st;
    return rc;
}

/* ------------------------------------------------------------------------------------------ */
/* one species                                                                                 */

static void write_species_preview(pov_file *pf, const scene *s, const uint8_t *wanted, const export_paths *ep,
                                  const char *source)
{
    char name[POV_PATH_MAX], ident[POV_IDENT_MAX];
    snprintf(name, sizeof name, "%s.pov", ep->stem);
    write_header(pf, name, "a preview of the species' variants side by side", source);
    /* place the variants along +X, one width apart */
    double x = 0, top = 1, spacing = 0;
    for (uint32_t p = 0; p < s->n_prototypes; p++) {
        if (!wanted[p] || !s->prototypes[p].mesh->nt) continue;
        float a[3], b[3];
        mesh_bounds(s->prototypes[p].mesh, a, b);
        double span = fmax(b[0] - a[0], b[1] - a[1]);
        if (span > spacing) spacing = span;
        if (b[2] > top) top = b[2];
    }
    spacing = spacing * 1.25 + 0.1;
    pov_printf(pf, "//   povray +I\"%s.pov\" +O\"%s.png\" +W800 +H600 +A0.1\n#version 3.7;\n\n"
                   "global_settings { assumed_gamma 1.0 ambient_light rgb <0.2, 0.2, 0.2> }\n"
                   "background { rgb <0.35, 0.45, 0.6> }\n#include \"%s.inc\"\n\n",
               ep->stem, ep->stem, ep->stem);
    uint32_t shown = 0;
    for (uint32_t p = 0; p < s->n_prototypes; p++) {
        if (!wanted[p] || !s->prototypes[p].mesh->nt) continue;
        pov_prototype_identifier(s, p, ident);
        char tx[POV_NUMBER_MAX];
        pov_format_real(tx, x, 6);
        pov_printf(pf, "object { %s translate <%s, 0, 0> }\n", ident, tx);
        x += spacing;
        shown++;
    }
    double width = shown ? x - spacing : 0, cx = width / 2;
    /* fit width and height into a 4:3 frame with a 40 degree horizontal field of view */
    double th = tan(20.0 * M_PI / 180.0);
    double dist = fmax((width / 2 + spacing / 2) / th, (top / 2) / (th * 0.75)) * 1.15 + 1.0;
    char cxs[POV_NUMBER_MAX], d[POV_NUMBER_MAX], hz[POV_NUMBER_MAX], far[POV_NUMBER_MAX], west[POV_NUMBER_MAX],
        south[POV_NUMBER_MAX], tile[POV_NUMBER_MAX];
    pov_format_real(cxs, cx, 6);
    pov_format_real(d, -dist, 6);
    pov_format_real(hz, top / 2, 6);
    pov_format_real(far, 100 * (dist + top), 6);
    pov_format_real(west, cx - 60 * (dist + top), 6);
    pov_format_real(south, -80 * (dist + top), 6);
    pov_format_real(tile, spacing / 2, 6);
    pov_printf(pf, "\ncamera {\n  perspective\n  location <%s, %s, %s>\n  sky <0, 0, 1>\n  right -x * 4/3\n"
                   "  angle 40\n  look_at <%s, 0, %s>\n}\n"
                   "// the sun from the south-west, 45 degrees up\n"
                   "light_source { <%s, %s, %s> color rgb 1 parallel point_at <%s, 0, 0> }\n"
                   "plane { z, 0 pigment { checker rgb 0.35, rgb 0.45 scale %s } finish { Sylva_finish } }\n",
               cxs, d, hz, cxs, hz, west, south, far, cxs, tile);
}

int pov_export_species(const scene *s, uint32_t species_index, int32_t variant, const char *path, const char *source,
                       pov_export_stats *st_out, err_buf *err)
{
    pov_export_stats st = {0};
    if (species_index >= s->n_species)
        return err_set(err, "species %u does not exist; the scene has %u", species_index, s->n_species);
    const struct species *sp = &s->species[species_index];
    if (variant >= 0 && (uint32_t)variant >= sp->n_variants)
        return err_set(err, "species \"%s\" has variants 0 to %u; there is no variant %d", sp->name,
                       sp->n_variants ? sp->n_variants - 1 : 0, variant);
    size_t n = strlen(path);
    int preview = n > 4 && !strcmp(path + n - 4, ".pov");
    export_paths ep;
    if (split_path(path, preview ? ".pov" : ".inc", &ep, err)) return -1;
    uint8_t *wanted_proto = calloc(s->n_prototypes ? s->n_prototypes : 1, 1);
    uint8_t *wanted_mat = calloc(s->n_materials ? s->n_materials : 1, 1);
    int rc = -1;
    if (!wanted_proto || !wanted_mat) {
        err_nomem(err, "out of memory exporting species \"%s\"", sp->name);
        goto done;
    }
    uint32_t chosen = 0;
    for (uint32_t k = 0; k < sp->n_variants; k++) {
        if (variant >= 0 && k != (uint32_t)variant) continue;
        uint32_t p = sp->first_prototype + k;
        wanted_proto[p] = 1;
        for (uint32_t t = 0; t < s->prototypes[p].mesh->nt; t++) wanted_mat[scene_triangle_material(s, s->prototypes[p].mesh, t)] = 1;
        chosen += s->prototypes[p].mesh->nt > 0;
    }
    if (!chosen) {
        err_set(err, "species \"%s\" has no triangles to export%s", sp->name, variant >= 0 ? " in that variant" : "");
        goto done;
    }
    char inc[POV_PATH_MAX], name[POV_PATH_MAX], text[256];
    if (path_with(&ep, ".inc", inc, err)) goto done;
    snprintf(name, sizeof name, "%s.inc", ep.stem);
    pov_comment_text(sp->name, text, sizeof text);
    pov_file pf;
    if (pov_file_open(&pf, inc, err)) goto done;
    write_header(&pf, name, "one species as POV-Ray 3.7 objects", source);
    pov_printf(&pf, "// Species \"%s\": each variant a mesh2 with the base of the trunk at the origin, growing\n"
                    "// along +Z, in metres. In a scene with sylva's axes (Z up) use it as it is:\n"
                    "//   object { NAME rotate <0, 0, 30> translate <x, y, z> }\n"
                    "// In a scene with POV-Ray's usual axes (Y up, left-handed) apply Sylva_to_y_up first,\n"
                    "// which also keeps the model unmirrored:\n"
                    "//   object { NAME transform { Sylva_to_y_up } translate <x, y, z> }\n"
                    "// The materials are Lambertian with sylva's albedo; leaves show no transmission.\n\n"
                    "#declare Sylva_to_y_up = transform { matrix <1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0> }\n\n",
               text);
    if (write_materials(&pf, s, wanted_mat, &ep, &st, err) || write_prototypes(&pf, s, wanted_proto, err)) {
        pov_file_abort(&pf);
        goto done;
    }
    if (pov_file_finish(&pf, &st.bytes, err)) goto done;
    st.files++;
    if (preview) {
        if (pov_file_open(&pf, path, err)) goto done;
        write_species_preview(&pf, s, wanted_proto, &ep, source);
        if (pov_file_finish(&pf, &st.bytes, err)) goto done;
        st.files++;
    }
    rc = 0;
done:
    free(wanted_proto);
    free(wanted_mat);
    if (st_out) *st_out = st;
    return rc;
}
