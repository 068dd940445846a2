/* host.c — the host API table given to plugins. Every function checks its arguments: a plugin's
 * mistake becomes an error sentence, never a crash in the host. */
#include "scene_build/host.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "scene/heightfield.h"
#include "util/file_check.h"
#include "util/memory_budget.h"
#include "util/rng.h"
#include "util/task_pool.h"

void host_init(sylva_host *h, scene *sc, const char *scene_dir, uint64_t seed, const char *context,
               err_buf *err)
{
    memset(h, 0, sizeof *h);
    h->scene = sc, h->scene_dir = scene_dir, h->seed = seed, h->context = context, h->err = err;
}

void host_release(sylva_host *h)
{
    if (h->progress_open) progress_end(&h->prog);
    for (uint32_t i = 0; i < h->n_paths; i++) free(h->paths[i]);
    free(h->paths);
    free(h->plants);
    h->paths = NULL, h->n_paths = 0, h->plants = NULL, h->n_plants = 0, h->progress_open = 0;
}

static void host_log(sylva_host *h, sylva_log_level level, const char *fmt, ...)
{
    if (level == SYLVA_LOG_DEBUG && !h->verbose) return;
    if (level == SYLVA_LOG_INFO && h->warnings_only && !h->verbose) return;
    va_list ap;
    va_start(ap, fmt);
    flockfile(stderr); /* one line, whole, when tree variants log from several threads */
    fprintf(stderr, "sylva: %s%s: ", level == SYLVA_LOG_WARN ? "warning: " : "", h->context);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    funlockfile(stderr);
    va_end(ap);
}

static int host_error(sylva_host *h, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vset(h->err, fmt, ap);
    va_end(ap);
    h->error_set = 1;
    return SYLVA_ERR_PARAM;
}

/* A host function's allocation failed: the sentence, and SYLVA_ERR_NOMEM for the plugin. */
static int host_out_of_memory(sylva_host *h, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    err_vset(h->err, fmt, ap);
    va_end(ap);
    if (h->err) h->err->status = ERR_NOMEM;
    h->error_set = h->out_of_memory = 1;
    return SYLVA_ERR_NOMEM;
}

/* A failure of the scene's own functions passed on to the plugin: the sentence, and the
 * plugin status its kind stands for. */
static int host_pass_on(sylva_host *h, const err_buf *e)
{
    if (e->status == ERR_NOMEM) return host_out_of_memory(h, "%s", e->msg);
    host_error(h, "%s", e->msg);
    return e->status == ERR_LIMIT ? SYLVA_ERR_LIMIT : SYLVA_ERR_PARAM;
}

static int host_param_error(sylva_host *h, const sylva_params *p, const char *param, const char *fmt, ...)
{
    char msg[ERR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const sylva_value *v = p && param ? sylva_param(p, param) : NULL;
    uint32_t line = v && v->line ? v->line : (p ? p->line : 0);
    uint32_t col = v && v->line ? v->column : (p ? p->column : 0);
    const char *file = p && p->file ? p->file : "scene";
    err_at(h->err, ERR_UNSTATED, file, line, col, "'%s': %s", param ? param : "?", msg);
    h->error_set = 1;
    return SYLVA_ERR_PARAM;
}

static void host_progress(sylva_host *h, const char *label, uint64_t done, uint64_t total)
{
    if (!h->progress_open) {
        char l[64];
        snprintf(l, sizeof l, "%s", label ? label : h->context);
        progress_begin(&h->prog, l, total, h->quiet);
        h->progress_open = 1;
    }
    progress_set(&h->prog, done, total);
    if (total && done >= total) {
        progress_end(&h->prog);
        h->progress_open = 0;
    }
}

static void host_rng_init(sylva_host *h, sylva_rng *r, const char *purpose, uint64_t index)
{
    rng_stream(r, h->seed, purpose ? purpose : "", index);
}

static uint64_t host_rng_u64(sylva_rng *r) { return rng_next_u64(r); }
static double host_rng_uniform(sylva_rng *r) { return rng_next_double(r); }

static int host_mesh_append(sylva_host *h, sylva_mesh *m, const float *pos, const float *nrm,
                            const float *uv, uint32_t nv, const uint32_t *tri, const int32_t *mat,
                            uint32_t nt)
{
    if (!m) return host_error(h, "mesh_append called without a mesh");
    if (mat)
        for (uint32_t t = 0; t < nt; t++)
            if (mat[t] < -1 || mat[t] >= (int32_t)h->scene->n_materials)
                return host_error(h, "triangle %u has material id %d; valid ids are -1 to %u", t,
                                  mat[t], h->scene->n_materials - 1);
    err_buf e;
    return mesh_append(m, pos, nrm, uv, nv, tri, mat, -1, nt, &e) ? host_pass_on(h, &e) : SYLVA_OK;
}

static uint32_t host_mesh_triangle_count(const sylva_mesh *m) { return m ? m->nt : 0; }

/* A plugin that lets generate() run concurrently must make its materials and textures in
 * create(): ids handed out in whichever order the threads came would differ from run to run. */
static int host_refuse_concurrent(sylva_host *h, const char *fn)
{
    return host_error(h, "%s called from a generate() that the plugin declares concurrent "
                      "(SYLVA_PLUGIN_CONCURRENT_GENERATE); make materials and textures in create()", fn);
}

static int32_t host_texture_new(sylva_host *h, const char *name, uint32_t w, uint32_t hh,
                                const uint8_t *rgba)
{
    if (h->concurrent) return host_refuse_concurrent(h, "texture_new");
    if (!rgba) return host_error(h, "texture_new called without texels");
    err_buf e;
    int32_t id = scene_add_texture(h->scene, name ? name : "texture", w, hh, rgba, &e);
    return id < 0 ? host_pass_on(h, &e) : id;
}

static int32_t host_material_new(sylva_host *h, const sylva_material_desc *d)
{
    if (h->concurrent) return host_refuse_concurrent(h, "material_new");
    if (!d || d->size < sizeof(sylva_material_desc))
        return host_error(h, "material_new: the descriptor is missing or its size is wrong");
    if (d->bsdf != SYLVA_BSDF_LAMBERT && d->bsdf != SYLVA_BSDF_LEAF)
        return host_error(h, "material '%s': unknown bsdf %d", d->name ? d->name : "?", (int)d->bsdf);
    if (d->texture >= (int32_t)h->scene->n_textures)
        return host_error(h, "material '%s': texture %d does not exist", d->name ? d->name : "?", d->texture);
    for (int k = 0; k < 3; k++)
        if (!(d->albedo[k] >= 0 && d->albedo[k] <= 1 && d->transmittance[k] >= 0 && d->transmittance[k] <= 1))
            return host_error(h, "material '%s': albedo and transmittance must be in [0, 1]",
                              d->name ? d->name : "?");
    if (d->bsdf == SYLVA_BSDF_LEAF)
        for (int k = 0; k < 3; k++)
            if (d->albedo[k] + d->transmittance[k] > 1.0f)
                return host_error(h, "material '%s': albedo + transmittance is %g in channel %d; a leaf "
                                  "cannot scatter more than it receives (at most 1)",
                                  d->name ? d->name : "?", d->albedo[k] + d->transmittance[k], k);
    err_buf e;
    int32_t id = scene_add_material(h->scene, d, &e);
    return id < 0 ? host_pass_on(h, &e) : id;
}

static int host_memory_check(sylva_host *h, uint64_t bytes, uint64_t heightfield_nodes, const char *what)
{
    const uint64_t per_node = HEIGHTFIELD_NODE_BYTES + HEIGHTFIELD_RENDER_NODE_BYTES;
    err_buf e;
    if (heightfield_nodes > UINT64_MAX / per_node || bytes > UINT64_MAX - heightfield_nodes * per_node)
        bytes = UINT64_MAX;
    else bytes += heightfield_nodes * per_node;
    if (!memory_check(bytes, what ? what : "the plugin's work", &e)) return SYLVA_OK;
    host_error(h, "%s", e.msg);
    return SYLVA_ERR_LIMIT;
}

static sylva_heightfield *host_heightfield_new(sylva_host *h, uint32_t nx, uint32_t ny, int with_material)
{
    if (h->kind && h->kind != SYLVA_KIND_TERRAIN) {
        host_error(h, "heightfield_new is for terrain plugins; a %s plugin cannot replace the terrain",
                   h->kind == SYLVA_KIND_TREE ? "tree" : "ecology");
        return NULL;
    }
    if (nx < 2 || ny < 2 || nx > 65536 || ny > 65536 || (uint64_t)nx * ny > (1ull << 28)) {
        host_error(h, "heightfield of %u x %u nodes: each side must be 2 to 65536 and the total at "
                   "most 2^28 nodes", nx, ny);
        return NULL;
    }
    char what[96];
    snprintf(what, sizeof what, "a terrain of %u x %u nodes", nx, ny);
    if (host_memory_check(h, 0, (uint64_t)nx * ny, what)) return NULL;
    sylva_heightfield *hf = calloc(1, sizeof *hf);
    float *z = calloc((size_t)nx * ny, sizeof(float));
    int32_t *mat = with_material ? malloc((size_t)nx * ny * sizeof(int32_t)) : NULL;
    if (!hf || !z || (with_material && !mat)) {
        free(hf), free(z), free(mat);
        host_out_of_memory(h, "out of memory for a %u x %u heightfield", nx, ny);
        return NULL;
    }
    for (size_t i = 0; mat && i < (size_t)nx * ny; i++) mat[i] = -1;
    *hf = (sylva_heightfield){.size = sizeof *hf, .nx = nx, .ny = ny, .dx = 1, .dy = 1, .z = z,
                              .material = mat, .water_material = -1};
    /* The scene takes it now, so a failing plugin leaks nothing. */
    sylva_heightfield **slot = h->surveyed ? &h->scene->surveyed : &h->scene->terrain;
    if (*slot != (h->surveyed ? h->scene->terrain : h->scene->surveyed)) heightfield_free(*slot);
    *slot = hf;
    return hf;
}

/* Checks a new level's window against hf and its last level (sylva_terrain_level's rules). */
static int level_window_ok(sylva_host *h, const sylva_heightfield *hf, uint32_t i0, uint32_t j0,
                           uint32_t cx, uint32_t cy, uint32_t refine)
{
    uint64_t i1 = (uint64_t)i0 + cx, j1 = (uint64_t)j0 + cy;
    if (!cx || !cy || i1 > hf->nx - 1 || j1 > hf->ny - 1 || refine < 2 || refine > 4096)
        return host_error(h, "level of detail over cells [%u, %llu) x [%u, %llu) with refine %u: "
                          "the window must hold at least one of the heightfield's %u x %u cells "
                          "and refine must be 2 to 4096", i0, (unsigned long long)i1, j0,
                          (unsigned long long)j1, refine, hf->nx - 1, hf->ny - 1);
    if (!hf->n_levels) return SYLVA_OK;
    const sylva_terrain_level *p = &hf->levels[hf->n_levels - 1];
    uint64_t pi1 = (uint64_t)p->i0 + p->cells_x, pj1 = (uint64_t)p->j0 + p->cells_y;
    int inside = i0 >= p->i0 && j0 >= p->j0 && i1 <= pi1 && j1 <= pj1 && refine % p->refine == 0 &&
                 refine > p->refine;
    /* a side strictly inside, or both on the heightfield's edge */
    int sides = (i0 > p->i0 || i0 == 0) && (j0 > p->j0 || j0 == 0) &&
                (i1 < pi1 || i1 == hf->nx - 1) && (j1 < pj1 || j1 == hf->ny - 1);
    if (inside && sides) return SYLVA_OK;
    return host_error(h, "level of detail over cells [%u, %llu) x [%u, %llu) with refine %u does not "
                      "nest in the level before it, cells [%u, %llu) x [%u, %llu) with refine %u: "
                      "it must lie inside it, strictly where not at the heightfield's edge, with a "
                      "larger refine that is a multiple of it", i0, (unsigned long long)i1, j0,
                      (unsigned long long)j1, refine, p->i0, (unsigned long long)pi1, p->j0,
                      (unsigned long long)pj1, p->refine);
}

static sylva_terrain_level *host_heightfield_level_new(sylva_host *h, sylva_heightfield *hf, uint32_t i0,
                                                       uint32_t j0, uint32_t cells_x, uint32_t cells_y,
                                                       uint32_t refine, int with_material)
{
    if (!hf || hf != (h->surveyed ? h->scene->surveyed : h->scene->terrain)) {
        host_error(h, "heightfield_level_new: the heightfield is not the one heightfield_new made");
        return NULL;
    }
    if (h->surveyed) {
        host_error(h, "heightfield_level_new: the ground as surveyed has no levels of detail (the "
                   "request's 'surveyed' is 1: give the DTM's own nodes)");
        return NULL;
    }
    if (level_window_ok(h, hf, i0, j0, cells_x, cells_y, refine)) return NULL;
    uint64_t nx = (uint64_t)cells_x * refine + 1, ny = (uint64_t)cells_y * refine + 1;
    char what[128];
    snprintf(what, sizeof what, "a terrain level of detail of %llu x %llu nodes", (unsigned long long)nx,
             (unsigned long long)ny);
    if (nx > 65536 || ny > 65536 || nx * ny > (1ull << 28)) {
        host_error(h, "%s: each side must be at most 65536 and the total at most 2^28 nodes", what);
        return NULL;
    }
    if (host_memory_check(h, 0, nx * ny, what)) return NULL;
    sylva_terrain_level *grown = realloc(hf->levels, (hf->n_levels + 1) * sizeof *grown);
    float *z = calloc(nx * ny, sizeof(float));
    int32_t *mat = with_material ? malloc(nx * ny * sizeof(int32_t)) : NULL;
    if (grown) hf->levels = grown;
    if (!grown || !z || (with_material && !mat)) {
        free(z), free(mat);
        host_out_of_memory(h, "out of memory for %s", what);
        return NULL;
    }
    for (size_t i = 0; mat && i < nx * ny; i++) mat[i] = -1;
    sylva_terrain_level *l = &hf->levels[hf->n_levels++];
    *l = (sylva_terrain_level){.size = sizeof *l, .i0 = i0, .j0 = j0, .cells_x = cells_x,
                               .cells_y = cells_y, .refine = refine, .nx = (uint32_t)nx,
                               .ny = (uint32_t)ny, .z = z, .material = mat};
    return l;
}

static int host_terrain_height(sylva_host *h, double x, double y, double *z)
{
    return scene_surveyed_height(h->scene, x, y, z) ? SYLVA_ERR_PARAM : SYLVA_OK;
}

static int host_terrain_normal(sylva_host *h, double x, double y, double n[3])
{
    return scene_surveyed_normal(h->scene, x, y, n) ? SYLVA_ERR_PARAM : SYLVA_OK;
}

static int host_plant_add(sylva_host *h, const sylva_plant *p)
{
    if (h->kind && h->kind != SYLVA_KIND_ECOLOGY)
        return host_error(h, "plant_add is for ecology plugins; plants of a scene come from its ecology");
    if (!p || p->size < sizeof(sylva_plant)) return host_error(h, "plant_add: the plant's size is wrong");
    if (p->species >= h->n_species)
        return host_error(h, "plant_add: species %u does not exist (%u species)", p->species, h->n_species);
    if (!(p->age > 0 && p->age <= 1))
        return host_error(h, "plant_add: age %g is outside (0, 1]", p->age);
    if (h->n_plants >= 100000000u) return host_error(h, "more than 100000000 plants (the scene limit)");
    if (h->n_plants == h->cap_plants) {
        uint32_t cap = h->cap_plants ? h->cap_plants * 2 : 1024;
        sylva_plant *q = realloc(h->plants, (size_t)cap * sizeof *q);
        if (!q) return host_out_of_memory(h, "out of memory adding plant %u", h->n_plants);
        h->plants = q, h->cap_plants = cap;
    }
    h->plants[h->n_plants++] = *p;
    return SYLVA_OK;
}

/* A plugin opens what this returns, so the rules of scene paths hold here too: a GDAL virtual
 * path only when the command line allowed it (returned as written), and never a FIFO, device or
 * folder (NULL, with the reason as the host error). */
static const char *host_resolve_path(sylva_host *h, const char *rel)
{
    if (!rel) return NULL;
    int virtual_path = file_is_gdal_virtual(rel);
    if (virtual_path && !file_gdal_virtual_allowed()) {
        host_error(h, "'%s' is a GDAL virtual path, URL or connection string, which may reach the "
                   "network; name a local file, or run with --allow-gdal-virtual", rel);
        return NULL;
    }
    size_t n = strlen(h->scene_dir) + strlen(rel) + 2;
    char *s = malloc(n), **list = realloc(h->paths, (h->n_paths + 1) * sizeof(char *));
    if (list) h->paths = list;
    if (!s || !list) {
        free(s);
        host_out_of_memory(h, "out of memory resolving path '%s'", rel);
        return NULL;
    }
    if (rel[0] == '/' || virtual_path) snprintf(s, n, "%s", rel);
    else snprintf(s, n, "%s/%s", h->scene_dir, rel);
    struct stat st;
    err_buf why;
    if (!virtual_path && stat(s, &st) == 0 && file_check_regular(s, rel, &why)) {
        free(s);
        host_error(h, "%s", why.msg);
        return NULL;
    }
    h->paths[h->n_paths++] = s;
    return s;
}

/* The plugin allocator is the host's: its limits and the fault-injection tests reach it. */
static void *host_mem_alloc(size_t bytes) { return malloc(bytes); }
static void *host_mem_calloc(size_t count, size_t size) { return calloc(count, size); }
static void *host_mem_realloc(void *block, size_t bytes) { return realloc(block, bytes); }
static void host_mem_free(void *block) { free(block); }

static const sylva_value *host_param(sylva_host *h, const sylva_params *p, const char *name)
{
    if (!p || !name) {
        host_error(h, "param called without %s", p ? "a parameter name" : "parameters");
        return NULL;
    }
    int k = sylva_param_index(p, name);
    if (k >= 0) return &p->values[k];
    char names[ERR_MSG_MAX / 2];
    size_t len = 0;
    names[0] = '\0';
    for (uint32_t i = 0; i < p->n && len < sizeof names; i++) {
        int w = snprintf(names + len, sizeof names - len, "%s%s", i ? ", " : "", p->spec[i].name);
        if (w < 0) break;
        len += (size_t)w;
    }
    host_error(h, "%s read parameter '%s', which its schema does not have; %s%s",
               h->context ? h->context : "the plugin", name,
               p->n ? "the parameters are: " : "the schema has no parameters", names);
    return NULL;
}

static unsigned host_threads(sylva_host *h) { return h && h->threads ? h->threads : task_pool_default_threads(); }

static const sylva_host_api api_table = {
    .size = sizeof(sylva_host_api),
    .abi_major = SYLVA_ABI_MAJOR,
    .abi_minor = SYLVA_ABI_MINOR,
    .log = host_log,
    .error = host_error,
    .param_error = host_param_error,
    .progress = host_progress,
    .rng_init = host_rng_init,
    .rng_u64 = host_rng_u64,
    .rng_uniform = host_rng_uniform,
    .mesh_append = host_mesh_append,
    .mesh_triangle_count = host_mesh_triangle_count,
    .texture_new = host_texture_new,
    .material_new = host_material_new,
    .heightfield_new = host_heightfield_new,
    .terrain_height = host_terrain_height,
    .terrain_normal = host_terrain_normal,
    .plant_add = host_plant_add,
    .resolve_path = host_resolve_path,
    .mem_alloc = host_mem_alloc,
    .mem_calloc = host_mem_calloc,
    .mem_realloc = host_mem_realloc,
    .mem_free = host_mem_free,
    .param = host_param,
    .memory_check = host_memory_check,
    .heightfield_level_new = host_heightfield_level_new,
    .threads = host_threads,
};

const sylva_host_api *host_api_table(void) { return &api_table; }
