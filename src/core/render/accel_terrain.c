/* accel_terrain.c — the terrain as Embree grid geometry (see accel_terrain.h). */
#include "render/accel_terrain.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/cutout.h"
#include "geometry/terrain_mesh.h"
#include "geometry/texture_lookup.h"
#include "render/accel_errors.h"
#include "render/accel_frame.h"
#include "render/ground_shade.h"

/* Where a grid hit lies: the grid, the tessellation's triangle in it, and the point's position
 * in its cell (fx east, fy north, both in [0, 1]) as Embree's grid coordinates give it. */
typedef struct terrain_hit {
    terrain_grid g;
    uint32_t t;
    double fx, fy;
} terrain_hit;

static terrain_hit terrain_hit_of(const struct accel_terrain *at, const sylva_heightfield *hf, unsigned tile,
                                  float u, float v)
{
    const accel_terrain_tile *tl = &at->tiles[tile];
    terrain_hit th = {.g = terrain_grid_of(hf, tl->grid)};
    double gx = (double)u * tl->w, gy = (double)v * tl->h;
    uint32_t ci = gx <= 0 ? 0 : (uint32_t)gx, cr = gy <= 0 ? 0 : (uint32_t)gy;
    if (ci >= tl->w) ci = tl->w - 1;
    if (cr >= tl->h) cr = tl->h - 1;
    th.fx = gx - ci, th.fy = 1.0 - (gy - cr);
    if (th.fx > 1) th.fx = 1;
    if (th.fy < 0) th.fy = 0;
    /* the tile's vertex rows run north to south: row cr is the cell row h - 1 - cr from its south */
    uint32_t i = tl->i0 + ci, j = tl->j0 + (tl->h - 1 - cr);
    th.t = terrain_triangle_of_cell(&th.g, i, j, th.fy > th.fx);
    return th;
}

/* Barycentrics (bu, bv) of the triangle's second and third corners at (fx, fy) of its cell. */
static void cell_barycentrics(uint32_t t, double fx, double fy, double *bu, double *bv)
{
    if (t & 1) *bu = fx, *bv = fy - fx; /* (i, j), (i+1, j+1), (i, j+1) */
    else *bu = fx - fy, *bv = fy;       /* (i, j), (i+1, j), (i+1, j+1) */
}

/* The material of triangle t of grid g. */
static const material *terrain_material_of(const scene *s, const terrain_grid *g, uint32_t t)
{
    int32_t id = terrain_triangle_material(g, t, s->terrain_material);
    return &s->materials[id >= 0 && (uint32_t)id < s->n_materials ? (uint32_t)id : (uint32_t)s->default_material];
}

/* Rejects the hits where a cut-out terrain material's texture is transparent. */
static void terrain_cutout_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    const scene *s = g->scene;
    const struct accel_terrain *at = g->terrain;
    const unsigned n = args->N;
    const float *hit = (const float *)args->hit; /* RTCHitN: Ng x, y, z, u, v, primID, ... */
    for (unsigned q = 0; q < n; q++) {
        if (args->valid[q] != -1) continue;
        unsigned tile = ((const unsigned *)args->hit)[5 * n + q];
        terrain_hit th = terrain_hit_of(at, s->terrain, tile, hit[3 * n + q], hit[4 * n + q]);
        const material *mt = terrain_material_of(s, &th.g, th.t);
        if (!cutout_material(s, mt)) continue;
        uint32_t k[3];
        float uv[3][2];
        double bu, bv;
        terrain_triangle_nodes(&th.g, th.t, k);
        for (int c = 0; c < 3; c++) terrain_node_vertex(&th.g, k[c] % th.g.nx, k[c] / th.g.nx, NULL, NULL, uv[c]);
        cell_barycentrics(th.t, th.fx, th.fy, &bu, &bv);
        float bw = (float)(1.0 - bu - bv);
        float tu = bw * uv[0][0] + (float)bu * uv[1][0] + (float)bv * uv[2][0];
        float tv = bw * uv[0][1] + (float)bu * uv[1][1] + (float)bv * uv[2][1];
        if (!cutout_texel_kept(texture_texel(&s->textures[mt->texture], tu, tv)[3])) args->valid[q] = 0;
    }
}

/* 1 when a material the terrain uses is a cut-out. */
static int terrain_has_cutouts(const scene *s)
{
    int any = 0;
    for (uint32_t m = 0; m < s->n_materials && !any; m++) any = cutout_material(s, &s->materials[m]);
    if (!any) return 0; /* no node to look at */
    const material *last = NULL;
    for (uint32_t gi = 0; gi < terrain_grid_count(s->terrain); gi++) {
        terrain_grid g = terrain_grid_of(s->terrain, gi);
        uint32_t nt = 2 * (g.nx - 1) * (g.ny - 1);
        for (uint32_t t = 0; t < nt; t += 2) {
            const material *m = terrain_material_of(s, &g, t);
            if (m == last) continue;
            last = m;
            if (cutout_material(s, m)) return 1;
        }
    }
    return 0;
}

/* Appends the tiles of cells [i0, i1) x [j0, j1) of grid `grid` (nothing when empty). */
static void add_tiles(struct accel_terrain *at, uint32_t grid, uint32_t first_vertex, uint32_t i0,
                      uint32_t j0, uint32_t i1, uint32_t j1)
{
    for (uint32_t j = j0; j < j1; j += ACCEL_TERRAIN_TILE)
        for (uint32_t i = i0; i < i1; i += ACCEL_TERRAIN_TILE)
            at->tiles[at->n_tiles++] = (accel_terrain_tile){
                grid, i, j, i1 - i < ACCEL_TERRAIN_TILE ? i1 - i : ACCEL_TERRAIN_TILE,
                j1 - j < ACCEL_TERRAIN_TILE ? j1 - j : ACCEL_TERRAIN_TILE, first_vertex};
}

static uint32_t tiles_over(uint32_t i0, uint32_t j0, uint32_t i1, uint32_t j1)
{
    if (i1 <= i0 || j1 <= j0) return 0;
    return ((i1 - i0 - 1) / ACCEL_TERRAIN_TILE + 1) * ((j1 - j0 - 1) / ACCEL_TERRAIN_TILE + 1);
}

void accel_terrain_free(struct accel_terrain *t)
{
    if (!t) return;
    free(t->vertices), free(t->tiles), free(t);
}

int accel_terrain_add(accel *a, RTCScene rs, unsigned id, err_buf *err)
{
    const sylva_heightfield *hf = a->scene->terrain;
    uint32_t grids = terrain_grid_count(hf);
    uint64_t nv = 0, max_tiles = 0;
    for (uint32_t gi = 0; gi < grids; gi++) {
        terrain_grid g = terrain_grid_of(hf, gi);
        nv += (uint64_t)g.nx * g.ny;
        max_tiles += 4 * tiles_over(0, 0, g.nx - 1, g.ny - 1) + 4;
    }
    if (nv > UINT32_MAX) return err_set(err, "the terrain has %llu nodes; Embree takes 2^32 at most", (unsigned long long)nv);
    struct accel_terrain *at = a->terrain = calloc(1, sizeof *at);
    /* one float more: Embree reads the last vertex with a 16-byte load */
    if (at) at->vertices = malloc((nv * 3 + 1) * sizeof(float)), at->tiles = malloc(max_tiles * sizeof *at->tiles);
    if (!at || !at->vertices || !at->tiles)
        return err_nomem(err, "out of memory for the vertices of a %u x %u terrain", hf->nx, hf->ny);
    RTCGeometry geom = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_GRID);
    if (!geom) return accel_device_error(a, err) ? -1 : err_set(err, "Embree could not create a grid geometry");
    uint64_t v = 0;
    for (uint32_t gi = 0; gi < grids; gi++) {
        terrain_grid g = terrain_grid_of(hf, gi);
        uint32_t fv = (uint32_t)v;
        for (uint32_t r = 0; r < g.ny; r++)
            for (uint32_t i = 0; i < g.nx; i++) {
                float *p = at->vertices + (v + (size_t)r * g.nx + i) * 3;
                terrain_node_vertex(&g, i, g.ny - 1 - r, p, NULL, NULL);
                accel_frame_point(a, p);
            }
        v += (uint64_t)g.nx * g.ny;
        /* the drawn cells: the grid less the hole, as up to four rectangles */
        uint32_t cx = g.nx - 1, cy = g.ny - 1;
        if (g.hole_i1 <= g.hole_i0) {
            add_tiles(at, gi, fv, 0, 0, cx, cy);
            continue;
        }
        add_tiles(at, gi, fv, 0, 0, cx, g.hole_j0);                     /* south */
        add_tiles(at, gi, fv, 0, g.hole_j1, cx, cy);                    /* north */
        add_tiles(at, gi, fv, 0, g.hole_j0, g.hole_i0, g.hole_j1);      /* west */
        add_tiles(at, gi, fv, g.hole_i1, g.hole_j0, cx, g.hole_j1);     /* east */
    }
    at->vertices[nv * 3] = 0.0f;
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, at->vertices, 0,
                               3 * sizeof(float), (unsigned)nv);
    struct RTCGrid *tiles = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_GRID, 0, RTC_FORMAT_GRID,
                                                    sizeof(struct RTCGrid), at->n_tiles);
    if (!tiles) {
        rtcReleaseGeometry(geom);
        return accel_device_error(a, err) ? -1 : err_nomem(err, "out of memory for the terrain's grid tiles");
    }
    for (uint32_t k = 0; k < at->n_tiles; k++) {
        const accel_terrain_tile *t = &at->tiles[k];
        terrain_grid g = terrain_grid_of(hf, t->grid);
        uint32_t north_row = g.ny - 1 - (t->j0 + t->h); /* vertex row of the tile's northern nodes */
        tiles[k] = (struct RTCGrid){.startVertexID = (unsigned)(t->first_vertex + (uint64_t)north_row * g.nx + t->i0),
                                    .stride = g.nx, .width = (unsigned short)(t->w + 1),
                                    .height = (unsigned short)(t->h + 1)};
    }
    geom_info *g = &a->top_geoms[id];
    *g = (geom_info){.kind = GEOM_TERRAIN, .scene = a->scene, .terrain = at, .alpha = terrain_has_cutouts(a->scene)};
    rtcSetGeometryUserData(geom, g);
    rtcSetGeometryMask(geom, ACCEL_MASK_GROUND);
    if (g->alpha) {
        rtcSetGeometryIntersectFilterFunction(geom, terrain_cutout_filter);
        rtcSetGeometryOccludedFilterFunction(geom, terrain_cutout_filter);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(rs, geom, id);
    rtcReleaseGeometry(geom);
    return accel_device_error(a, err);
}

static vec3 vec_of(const float p[3]) { return v3(p[0], p[1], p[2]); }

/* How far (bu, bv) lies outside its triangle: 0 inside. */
static double outside(double bu, double bv)
{
    double o = fmax(fmax(-bu, -bv), bu + bv - 1.0);
    return o > 0 ? o : 0.0;
}

/* Triangle t's corners in a's frame and the barycentrics of ray (org, d) on its plane (Moeller
 * and Trumbore, in double precision); 0 when the ray runs along the triangle. */
static int ray_barycentrics(const accel *a, const terrain_grid *g, uint32_t t, const double org[3], const double d[3],
                            uint32_t k[3], float p[3][3], double *bu, double *bv)
{
    terrain_triangle_nodes(g, t, k);
    for (int c = 0; c < 3; c++) {
        terrain_node_vertex(g, k[c] % g->nx, k[c] / g->nx, p[c], NULL, NULL);
        accel_frame_point(a, p[c]);
    }
    double e1[3], e2[3], o[3];
    for (int c = 0; c < 3; c++) e1[c] = p[1][c] - p[0][c], e2[c] = p[2][c] - p[0][c], o[c] = org[c] - p[0][c];
    double pv[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    double det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
    if (!(fabs(det) > 1e-12 * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]))) return 0;
    double qv[3] = {o[1] * e1[2] - o[2] * e1[1], o[2] * e1[0] - o[0] * e1[2], o[0] * e1[1] - o[1] * e1[0]};
    *bu = (o[0] * pv[0] + o[1] * pv[1] + o[2] * pv[2]) / det;
    *bv = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) / det;
    return 1;
}

void accel_terrain_shade(const accel *a, const struct RTCRayHit *rh, hit_info *h)
{
    const scene *s = a->scene;
    terrain_hit th = terrain_hit_of(a->terrain, s->terrain, rh->hit.primID, rh->hit.u, rh->hit.v);
    const terrain_grid *g = &th.g;
    uint32_t k[3];
    float p[3][3], n[3][3], uv[3][2];
    double d[3] = {rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z};
    double org[3] = {rh->ray.org_x, rh->ray.org_y, rh->ray.org_z};
    /* The barycentrics again, from the ray and the triangle in double precision. Embree's grid
     * coordinates are single precision over a whole tile, so near a cell's edge or diagonal they
     * may name the neighbouring triangle: then the drawn triangle of this cell or the next ones
     * that the ray meets inside is taken. Where the ray runs along the triangle, Embree's grid
     * coordinates stand. */
    double bu, bv;
    int along = !ray_barycentrics(a, g, th.t, org, d, k, p, &bu, &bv);
    if (along) {
        cell_barycentrics(th.t, th.fx, th.fy, &bu, &bv);
    } else if (outside(bu, bv) > 1e-9) {
        uint32_t cell = th.t / 2, ci = cell % (g->nx - 1), cj = cell / (g->nx - 1), best = th.t;
        double best_out = outside(bu, bv);
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++)
                for (uint32_t half = 0; half < 2; half++) {
                    int64_t i = (int64_t)ci + di, j = (int64_t)cj + dj;
                    if (i < 0 || j < 0 || i >= g->nx - 1 || j >= g->ny - 1 ||
                        !terrain_cell_drawn(g, (uint32_t)i, (uint32_t)j))
                        continue;
                    uint32_t t = terrain_triangle_of_cell(g, (uint32_t)i, (uint32_t)j, half);
                    double u2, v2;
                    if (t != th.t && ray_barycentrics(a, g, t, org, d, k, p, &u2, &v2) && outside(u2, v2) < best_out)
                        best = t, best_out = outside(u2, v2);
                }
        th.t = best;
        ray_barycentrics(a, g, th.t, org, d, k, p, &bu, &bv);
    }
    for (int c = 0; c < 3; c++) terrain_node_vertex(g, k[c] % g->nx, k[c] / g->nx, NULL, n[c], uv[c]);
    bu = bu < 0 ? 0 : bu > 1 ? 1 : bu;
    bv = bv < 0 ? 0 : bv > 1 - bu ? 1 - bu : bv;
    float fu = (float)bu, fv = (float)bv, fw = 1.0f - fu - fv;
    vec3 p0 = vec_of(p[0]), p1 = vec_of(p[1]), p2 = vec_of(p[2]);
    h->ng = v3_norm(v3_cross(v3_sub(p1, p0), v3_sub(p2, p0)));
    h->ns = v3_norm(v3_add(v3_add(v3_scale(vec_of(n[0]), fw), v3_scale(vec_of(n[1]), fu)), v3_scale(vec_of(n[2]), fv)));
    if (!(v3_dot(h->ns, h->ns) > 0.5f)) h->ns = h->ng;
    h->one_normal = !memcmp(n[0], n[1], sizeof n[0]) && !memcmp(n[0], n[2], sizeof n[0]);
    h->t = rh->ray.tfar;
    h->p = v3_add(v3_add(v3_scale(p0, fw), v3_scale(p1, fu)), v3_scale(p2, fv));
    h->u = fw * uv[0][0] + fu * uv[1][0] + fv * uv[2][0];
    h->v = fw * uv[0][1] + fu * uv[1][1] + fv * uv[2][1];
    h->mat = terrain_material_of(s, g, th.t);
    h->albedo = h->mat->albedo;
    if (h->mat->texture >= 0) {
        float rgba[4];
        texture_sample(&s->textures[h->mat->texture], h->u, h->v, rgba);
        h->albedo = v3_mul(h->albedo, v3(rgba[0], rgba[1], rgba[2]));
    }
    h->instance_id = 0, h->species_id = 0;
    h->kind = GEOM_TERRAIN;
    accel_terrain_ground(a, rh, h);
}

void accel_terrain_ground(const accel *a, const struct RTCRayHit *rh, hit_info *h)
{
    if (!a->ground) return;
    vec3 w = accel_frame_world(a, h->p); /* the ground is laid out in the world */
    if (a->flat_ground) { /* the export's image, no micro-relief */
        h->albedo = ground_texture_image_albedo(a->ground, w.x, w.y);
        return;
    }
    vec3 wo = v3_norm(v3(-rh->ray.dir_x, -rh->ray.dir_y, -rh->ray.dir_z));
    /* the pixel's width on the ground, stretched by the grazing angle (the geometric mean of
     * the footprint's two axes); the distance is the eye's, since a camera ray over the curved
     * Earth reaches the ground as the last of several chords */
    const double *eye = a->scene->camera.position;
    double ex = w.x - eye[0], ey = w.y - eye[1], ez = w.z - eye[2];
    float facing = fmaxf(fabsf(v3_dot(wo, h->ns)), 0.05f);
    double footprint = sqrt(ex * ex + ey * ey + ez * ez) * a->pixel_angle / sqrt(facing);
    ground_shade_point(a->ground, w, h->ng, wo, footprint, &h->albedo, &h->ns);
}
