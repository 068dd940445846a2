/* ztv_cover.c — observers under crowns and inside objects. */
#include "ztv/ztv_cover.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ztv/ztv_grid.h"

/* A prototype's footprint: its horizontal extent and the highest point over each bin. */
typedef struct footprint {
    float lo[2], size[2];
    float top[ZTV_FOOTPRINT * ZTV_FOOTPRINT]; /* -INFINITY where nothing stands */
} footprint;

/* A plant as the cover test sees it: the inverse of its transform's linear part and the grid
 * rows its footprint reaches. */
typedef struct plant_reach {
    uint32_t instance;
    uint32_t j0, j1;         /* rows [j0, j1] */
    uint32_t i0, i1;         /* columns [i0, i1] */
} plant_reach;

/* An object's bounding box on the grid. */
typedef struct object_box {
    uint32_t i0, i1, j0, j1;
    float zhi;
} object_box;

struct ztv_cover {
    const scene *scene;
    const accel *accel;
    ztv_grid grid;
    footprint *feet;          /* per prototype; owned */
    plant_reach *plants;      /* sorted by j0; owned */
    uint32_t n_plants;
    uint32_t max_rows;        /* most rows one plant reaches */
    object_box *objects;      /* per scene object; owned */
    uint32_t n_objects;
};

static void footprint_build(footprint *f, const mesh *m)
{
    float lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t v = 0; v < m->nv; v++)
        for (int a = 0; a < 2; a++) lo[a] = fminf(lo[a], m->pos[3 * v + a]), hi[a] = fmaxf(hi[a], m->pos[3 * v + a]);
    for (uint32_t b = 0; b < ZTV_FOOTPRINT * ZTV_FOOTPRINT; b++) f->top[b] = -INFINITY;
    if (!m->nv) {
        f->lo[0] = f->lo[1] = 0, f->size[0] = f->size[1] = 0;
        return;
    }
    for (int a = 0; a < 2; a++) f->lo[a] = lo[a], f->size[a] = fmaxf(hi[a] - lo[a], 1e-6f);
    for (uint32_t t = 0; t < m->nt; t++) {
        float tlo[2] = {INFINITY, INFINITY}, thi[2] = {-INFINITY, -INFINITY}, ztop = -INFINITY;
        for (int c = 0; c < 3; c++) {
            const float *p = &m->pos[3 * m->tri[3 * t + c]];
            for (int a = 0; a < 2; a++) tlo[a] = fminf(tlo[a], p[a]), thi[a] = fmaxf(thi[a], p[a]);
            ztop = fmaxf(ztop, p[2]);
        }
        int b0[2], b1[2];
        for (int a = 0; a < 2; a++) {
            b0[a] = (int)floorf((tlo[a] - f->lo[a]) / f->size[a] * ZTV_FOOTPRINT);
            b1[a] = (int)floorf((thi[a] - f->lo[a]) / f->size[a] * ZTV_FOOTPRINT);
            b0[a] = b0[a] < 0 ? 0 : b0[a] >= (int)ZTV_FOOTPRINT ? (int)ZTV_FOOTPRINT - 1 : b0[a];
            b1[a] = b1[a] < 0 ? 0 : b1[a] >= (int)ZTV_FOOTPRINT ? (int)ZTV_FOOTPRINT - 1 : b1[a];
        }
        for (int y = b0[1]; y <= b1[1]; y++)
            for (int x = b0[0]; x <= b1[0]; x++) {
                float *top = &f->top[y * ZTV_FOOTPRINT + x];
                *top = fmaxf(*top, ztop);
            }
    }
}

/* Grid columns [*i0, *i1] and rows [*j0, *j1] whose centres fall in [lo, hi]; 0 when none. */
static int grid_span(const ztv_grid *g, const double lo[2], const double hi[2], uint32_t *i0, uint32_t *i1,
                     uint32_t *j0, uint32_t *j1)
{
    double a0 = ceil((lo[0] - g->x0) / g->cell), a1 = floor((hi[0] - g->x0) / g->cell);
    double b0 = ceil((g->y0 - hi[1]) / g->cell), b1 = floor((g->y0 - lo[1]) / g->cell);
    a0 = fmax(a0, 0), b0 = fmax(b0, 0), a1 = fmin(a1, g->nx - 1.0), b1 = fmin(b1, g->ny - 1.0);
    if (a1 < a0 || b1 < b0) return 0;
    *i0 = (uint32_t)a0, *i1 = (uint32_t)a1, *j0 = (uint32_t)b0, *j1 = (uint32_t)b1;
    return 1;
}

static int by_first_row(const void *pa, const void *pb)
{
    const plant_reach *a = pa, *b = pb;
    if (a->j0 != b->j0) return a->j0 < b->j0 ? -1 : 1;
    return a->instance < b->instance ? -1 : a->instance > b->instance;
}

static void plants_index(ztv_cover *c)
{
    const scene *s = c->scene;
    for (uint32_t k = 0; k < s->n_instances; k++) {
        const instance *in = &s->instances[k];
        const footprint *f = &c->feet[in->prototype];
        if (f->size[0] <= 0) continue;
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int corner = 0; corner < 4; corner++) {
            vec3 p = xf_point(&in->xf, v3(f->lo[0] + (corner & 1) * f->size[0], f->lo[1] + (corner >> 1) * f->size[1], 0));
            lo[0] = fmin(lo[0], p.x), lo[1] = fmin(lo[1], p.y), hi[0] = fmax(hi[0], p.x), hi[1] = fmax(hi[1], p.y);
        }
        plant_reach r = {.instance = k};
        if (!grid_span(&c->grid, lo, hi, &r.i0, &r.i1, &r.j0, &r.j1)) continue;
        c->plants[c->n_plants++] = r;
        if (r.j1 - r.j0 + 1 > c->max_rows) c->max_rows = r.j1 - r.j0 + 1;
    }
    qsort(c->plants, c->n_plants, sizeof *c->plants, by_first_row);
}

static void objects_index(ztv_cover *c)
{
    const scene *s = c->scene;
    for (uint32_t o = 0; o < s->n_objects; o++) {
        object_box *b = &c->objects[c->n_objects];
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        scene_object_bounds(s, o, lo, hi);
        if (!(lo[0] <= hi[0]) || !grid_span(&c->grid, lo, hi, &b->i0, &b->i1, &b->j0, &b->j1)) continue;
        b->zhi = (float)hi[2];
        c->n_objects++;
    }
}

ztv_cover *ztv_cover_new(const scene *s, const accel *a, const ztv_grid *g, err_buf *err)
{
    ztv_cover *c = calloc(1, sizeof *c);
    if (!c) goto nomem;
    c->scene = s, c->accel = a, c->grid = *g;
    c->feet = calloc(s->n_prototypes ? s->n_prototypes : 1, sizeof *c->feet);
    c->plants = calloc(s->n_instances ? s->n_instances : 1, sizeof *c->plants);
    c->objects = calloc(s->n_objects ? s->n_objects : 1, sizeof *c->objects);
    if (!c->feet || !c->plants || !c->objects) goto nomem;
    for (uint32_t p = 0; p < s->n_prototypes; p++) footprint_build(&c->feet[p], s->prototypes[p].mesh);
    plants_index(c);
    objects_index(c);
    return c;
nomem:
    ztv_cover_free(c);
    err_nomem(err, "out of memory for the plants' footprints (%u plants)", s->n_instances);
    return NULL;
}

void ztv_cover_free(ztv_cover *c)
{
    if (!c) return;
    free(c->feet), free(c->plants), free(c->objects);
    free(c);
}

/* 1 when plant r stands over an eye at (x, y, z). */
static int plant_over(const ztv_cover *c, const plant_reach *r, double x, double y, double z)
{
    const instance *in = &c->scene->instances[r->instance];
    const footprint *f = &c->feet[in->prototype];
    const float(*m)[4] = in->xf.m;
    /* the eye in the prototype's frame: solve M q = p - t by the inverse of M */
    double p[3] = {x - m[0][3], y - m[1][3], z - m[2][3]};
    double a = m[0][0], b = m[0][1], cc = m[0][2], d = m[1][0], e = m[1][1], ff = m[1][2], gg = m[2][0],
           h = m[2][1], k = m[2][2];
    double det = a * (e * k - ff * h) - b * (d * k - ff * gg) + cc * (d * h - e * gg);
    if (fabs(det) < 1e-30) return 0;
    double qx = ((e * k - ff * h) * p[0] - (b * k - cc * h) * p[1] + (b * ff - cc * e) * p[2]) / det;
    double qy = (-(d * k - ff * gg) * p[0] + (a * k - cc * gg) * p[1] - (a * ff - cc * d) * p[2]) / det;
    double qz = ((d * h - e * gg) * p[0] - (a * h - b * gg) * p[1] + (a * e - b * d) * p[2]) / det;
    double u = (qx - f->lo[0]) / f->size[0], v = (qy - f->lo[1]) / f->size[1];
    if (u < 0 || u >= 1 || v < 0 || v >= 1) return 0;
    float top = f->top[(uint32_t)(v * ZTV_FOOTPRINT) * ZTV_FOOTPRINT + (uint32_t)(u * ZTV_FOOTPRINT)];
    return top > qz; /* the plant's frame keeps its up axis up: higher there is higher here */
}

void ztv_cover_crowns(const ztv_cover *c, uint32_t j, const float *eye_z, uint8_t *under)
{
    /* the plants whose rows reach j: first rows in [j - max_rows + 1, j] */
    uint32_t lo_row = j + 1 > c->max_rows ? j + 1 - c->max_rows : 0;
    size_t lo = 0, hi = c->n_plants;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (c->plants[mid].j0 < lo_row) lo = mid + 1; else hi = mid;
    }
    for (size_t k = lo; k < c->n_plants && c->plants[k].j0 <= j; k++) {
        const plant_reach *r = &c->plants[k];
        if (r->j1 < j) continue;
        for (uint32_t i = r->i0; i <= r->i1; i++) {
            if (under[i] || isnan(eye_z[i])) continue;
            double x, y;
            ztv_cell_centre(&c->grid, i, j, &x, &y);
            if (plant_over(c, r, x, y, eye_z[i])) under[i] = 1;
        }
    }
}

/* Surfaces of objects met going straight up from p, counted to ZTV_COVER_MAX_CROSSINGS. */
#define ZTV_COVER_MAX_CROSSINGS 64
static int crossings_up(const accel *a, double x, double y, double z)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    int n = 0;
    float from = 0.0f;
    while (n < ZTV_COVER_MAX_CROSSINGS) {
        struct RTCRayHit rh = {.ray = {.org_x = (float)x, .org_y = (float)y, .org_z = (float)z, .tnear = from,
                                       .dir_z = 1.0f, .tfar = INFINITY,
                                       .mask = ACCEL_MASK_OBJECT | ACCEL_MASK_DEVELOPMENT},
                               .hit = {.geomID = RTC_INVALID_GEOMETRY_ID, .instID = {RTC_INVALID_GEOMETRY_ID}}};
        rtcIntersect1(a->top, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
        n++;
        from = nextafterf(rh.ray.tfar, INFINITY) + 1e-4f;
    }
    return n;
}

void ztv_cover_objects(const ztv_cover *c, uint32_t j, const float *eye_z, uint8_t *inside)
{
    for (uint32_t o = 0; o < c->n_objects; o++) {
        const object_box *b = &c->objects[o];
        if (j < b->j0 || j > b->j1) continue;
        for (uint32_t i = b->i0; i <= b->i1; i++) {
            if (inside[i] || isnan(eye_z[i]) || eye_z[i] > b->zhi) continue;
            double x, y;
            ztv_cell_centre(&c->grid, i, j, &x, &y);
            /* odd: inside a closed surface, or under an open one (a roof); even: under or beside
             * closed ones (a blade overhead) */
            if (crossings_up(c->accel, x, y, eye_z[i]) % 2) inside[i] = 1;
        }
    }
}
