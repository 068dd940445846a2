/* accel_terrain.c — the terrain as Embree grid geometry (see accel_terrain.h). */
#include "render/accel_terrain.h"

#include <math.h>
#include <stdlib.h>

#include "geometry/cutout.h"
#include "geometry/terrain_mesh.h"
#include "geometry/texture_lookup.h"

/* Where a grid hit lies: the tessellation's triangle, and the point's position in its cell
 * (fx east, fy north, both in [0, 1]) as Embree's grid coordinates give it. */
typedef struct terrain_hit {
    uint32_t t;
    double fx, fy;
} terrain_hit;

static terrain_hit terrain_hit_of(const sylva_heightfield *hf, unsigned tile, float u, float v)
{
    uint32_t tiles_x = (hf->nx - 2) / ACCEL_TERRAIN_TILE + 1;
    uint32_t i0 = (tile % tiles_x) * ACCEL_TERRAIN_TILE, r0 = (tile / tiles_x) * ACCEL_TERRAIN_TILE;
    uint32_t w = hf->nx - 1 - i0 < ACCEL_TERRAIN_TILE ? hf->nx - 1 - i0 : ACCEL_TERRAIN_TILE;
    uint32_t h = hf->ny - 1 - r0 < ACCEL_TERRAIN_TILE ? hf->ny - 1 - r0 : ACCEL_TERRAIN_TILE;
    double gx = (double)u * w, gy = (double)v * h;
    uint32_t ci = gx <= 0 ? 0 : (uint32_t)gx, cr = gy <= 0 ? 0 : (uint32_t)gy;
    if (ci >= w) ci = w - 1;
    if (cr >= h) cr = h - 1;
    terrain_hit th = {.fx = gx - ci, .fy = 1.0 - (gy - cr)};
    if (th.fx > 1) th.fx = 1;
    if (th.fy < 0) th.fy = 0;
    /* vertex row r is node row ny - 1 - r: the cell between rows r0 + cr and the next one south */
    uint32_t i = i0 + ci, j = hf->ny - 2 - (r0 + cr);
    th.t = terrain_triangle_of_cell(hf, i, j, th.fy > th.fx);
    return th;
}

/* Barycentrics (bu, bv) of the triangle's second and third corners at (fx, fy) of its cell. */
static void cell_barycentrics(uint32_t t, double fx, double fy, double *bu, double *bv)
{
    if (t & 1) *bu = fx, *bv = fy - fx; /* (i, j), (i+1, j+1), (i, j+1) */
    else *bu = fx - fy, *bv = fy;       /* (i, j), (i+1, j), (i+1, j+1) */
}

/* The material of terrain triangle t. */
static const material *terrain_material_of(const scene *s, uint32_t t)
{
    int32_t id = terrain_triangle_material(s->terrain, t, s->terrain_material);
    return &s->materials[id >= 0 && (uint32_t)id < s->n_materials ? (uint32_t)id : (uint32_t)s->default_material];
}

/* Rejects the hits where a cut-out terrain material's texture is transparent. */
static void terrain_cutout_filter(const struct RTCFilterFunctionNArguments *args)
{
    const geom_info *g = args->geometryUserPtr;
    const scene *s = g->scene;
    const sylva_heightfield *hf = s->terrain;
    const unsigned n = args->N;
    const float *hit = (const float *)args->hit; /* RTCHitN: Ng x, y, z, u, v, primID, ... */
    for (unsigned q = 0; q < n; q++) {
        if (args->valid[q] != -1) continue;
        unsigned tile = ((const unsigned *)args->hit)[5 * n + q];
        terrain_hit th = terrain_hit_of(hf, tile, hit[3 * n + q], hit[4 * n + q]);
        const material *mt = terrain_material_of(s, th.t);
        if (!cutout_material(s, mt)) continue;
        uint32_t k[3];
        float uv[3][2];
        double bu, bv;
        terrain_triangle_nodes(hf, th.t, k);
        for (int c = 0; c < 3; c++) terrain_node_vertex(hf, k[c] % hf->nx, k[c] / hf->nx, NULL, NULL, uv[c]);
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
    const sylva_heightfield *hf = s->terrain;
    const material *last = NULL;
    uint32_t nt = 2 * (hf->nx - 1) * (hf->ny - 1);
    for (uint32_t t = 0; t < nt; t += 2) {
        const material *m = terrain_material_of(s, t);
        if (m == last) continue;
        last = m;
        if (cutout_material(s, m)) return 1;
    }
    return 0;
}

int accel_terrain_add(accel *a, RTCScene rs, unsigned id, err_buf *err)
{
    const sylva_heightfield *hf = a->scene->terrain;
    uint32_t nx = hf->nx, ny = hf->ny;
    size_t nv = (size_t)nx * ny;
    /* one float more: Embree reads the last vertex with a 16-byte load */
    a->terrain_vertices = malloc((nv * 3 + 1) * sizeof(float));
    if (!a->terrain_vertices) return err_nomem(err, "out of memory for the vertices of a %u x %u terrain", nx, ny);
    for (uint32_t r = 0; r < ny; r++)
        for (uint32_t i = 0; i < nx; i++)
            terrain_node_vertex(hf, i, ny - 1 - r, a->terrain_vertices + ((size_t)r * nx + i) * 3, NULL, NULL);
    a->terrain_vertices[nv * 3] = 0.0f;
    uint32_t tiles_x = (nx - 2) / ACCEL_TERRAIN_TILE + 1, tiles_y = (ny - 2) / ACCEL_TERRAIN_TILE + 1;
    RTCGeometry geom = rtcNewGeometry(a->device, RTC_GEOMETRY_TYPE_GRID);
    if (!geom) return accel_device_error(a, err) ? -1 : err_set(err, "Embree could not create a grid geometry");
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, a->terrain_vertices, 0,
                               3 * sizeof(float), (unsigned)nv);
    struct RTCGrid *tiles = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_GRID, 0, RTC_FORMAT_GRID,
                                                    sizeof(struct RTCGrid), (size_t)tiles_x * tiles_y);
    if (!tiles) {
        rtcReleaseGeometry(geom);
        return accel_device_error(a, err) ? -1 : err_nomem(err, "out of memory for the terrain's grid tiles");
    }
    for (uint32_t ty = 0; ty < tiles_y; ty++)
        for (uint32_t tx = 0; tx < tiles_x; tx++) {
            uint32_t i0 = tx * ACCEL_TERRAIN_TILE, r0 = ty * ACCEL_TERRAIN_TILE;
            uint32_t w = nx - 1 - i0 < ACCEL_TERRAIN_TILE ? nx - 1 - i0 : ACCEL_TERRAIN_TILE;
            uint32_t h = ny - 1 - r0 < ACCEL_TERRAIN_TILE ? ny - 1 - r0 : ACCEL_TERRAIN_TILE;
            tiles[(size_t)ty * tiles_x + tx] = (struct RTCGrid){.startVertexID = r0 * nx + i0, .stride = nx,
                                                                .width = (unsigned short)(w + 1),
                                                                .height = (unsigned short)(h + 1)};
        }
    geom_info *g = &a->top_geoms[id];
    *g = (geom_info){.kind = GEOM_TERRAIN, .scene = a->scene, .alpha = terrain_has_cutouts(a->scene)};
    rtcSetGeometryUserData(geom, g);
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

/* Triangle t's corners and the barycentrics of ray (org, d) on its plane (Moeller and
 * Trumbore, in double precision); 0 when the ray runs along the triangle. */
static int ray_barycentrics(const sylva_heightfield *hf, uint32_t t, const double org[3], const double d[3],
                            uint32_t k[3], float p[3][3], double *bu, double *bv)
{
    terrain_triangle_nodes(hf, t, k);
    for (int c = 0; c < 3; c++) terrain_node_vertex(hf, k[c] % hf->nx, k[c] / hf->nx, p[c], NULL, NULL);
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
    const sylva_heightfield *hf = s->terrain;
    terrain_hit th = terrain_hit_of(hf, rh->hit.primID, rh->hit.u, rh->hit.v);
    uint32_t k[3];
    float p[3][3], n[3][3], uv[3][2];
    double d[3] = {rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z};
    double org[3] = {rh->ray.org_x, rh->ray.org_y, rh->ray.org_z};
    /* The barycentrics again, from the ray and the triangle in double precision. Embree's grid
     * coordinates are single precision over a whole tile, so near a cell's edge or diagonal they
     * may name the neighbouring triangle: then the triangle of this cell or the next ones that
     * the ray meets inside is taken. Where the ray runs along the triangle, Embree's grid
     * coordinates stand. */
    double bu, bv;
    int along = !ray_barycentrics(hf, th.t, org, d, k, p, &bu, &bv);
    if (along) {
        cell_barycentrics(th.t, th.fx, th.fy, &bu, &bv);
    } else if (outside(bu, bv) > 1e-9) {
        uint32_t cell = th.t / 2, ci = cell % (hf->nx - 1), cj = cell / (hf->nx - 1), best = th.t;
        double best_out = outside(bu, bv);
        for (int dj = -1; dj <= 1; dj++)
            for (int di = -1; di <= 1; di++)
                for (uint32_t half = 0; half < 2; half++) {
                    int64_t i = (int64_t)ci + di, j = (int64_t)cj + dj;
                    if (i < 0 || j < 0 || i >= hf->nx - 1 || j >= hf->ny - 1) continue;
                    uint32_t t = terrain_triangle_of_cell(hf, (uint32_t)i, (uint32_t)j, half);
                    double u2, v2;
                    if (t != th.t && ray_barycentrics(hf, t, org, d, k, p, &u2, &v2) && outside(u2, v2) < best_out)
                        best = t, best_out = outside(u2, v2);
                }
        th.t = best;
        ray_barycentrics(hf, th.t, org, d, k, p, &bu, &bv);
    }
    for (int c = 0; c < 3; c++) terrain_node_vertex(hf, k[c] % hf->nx, k[c] / hf->nx, NULL, n[c], uv[c]);
    bu = bu < 0 ? 0 : bu > 1 ? 1 : bu;
    bv = bv < 0 ? 0 : bv > 1 - bu ? 1 - bu : bv;
    float fu = (float)bu, fv = (float)bv, fw = 1.0f - fu - fv;
    vec3 p0 = vec_of(p[0]), p1 = vec_of(p[1]), p2 = vec_of(p[2]);
    h->ng = v3_norm(v3_cross(v3_sub(p1, p0), v3_sub(p2, p0)));
    h->ns = v3_norm(v3_add(v3_add(v3_scale(vec_of(n[0]), fw), v3_scale(vec_of(n[1]), fu)), v3_scale(vec_of(n[2]), fv)));
    if (!(v3_dot(h->ns, h->ns) > 0.5f)) h->ns = h->ng;
    h->t = rh->ray.tfar;
    h->p = v3_add(v3_add(v3_scale(p0, fw), v3_scale(p1, fu)), v3_scale(p2, fv));
    h->u = fw * uv[0][0] + fu * uv[1][0] + fv * uv[2][0];
    h->v = fw * uv[0][1] + fu * uv[1][1] + fv * uv[2][1];
    h->mat = terrain_material_of(s, th.t);
    h->albedo = h->mat->albedo;
    if (h->mat->texture >= 0) {
        float rgba[4];
        texture_sample(&s->textures[h->mat->texture], h->u, h->v, rgba);
        h->albedo = v3_mul(h->albedo, v3(rgba[0], rgba[1], rgba[2]));
    }
    h->instance_id = 0, h->species_id = 0;
    h->kind = GEOM_TERRAIN;
}
