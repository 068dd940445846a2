/* blossom.c — flowers on a species' plants as a particle system sampled at a day (see blossom.h;
 * the model in docs/models/leaves_bark_blossom.md). */
#include "season/blossom.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "util/rng.h"

void blossom_params_default(blossom_params *p)
{
    *p = (blossom_params){.first_day = 100, .last_day = 120, .lifetime_min = 6, .lifetime_max = 12,
                          .per_point = 0.5, .max_per_plant = 1500, .speed_max = 0.002,
                          .size_min = 0.006, .size_max = 0.01, .bud_size = 0.3, .opening = 0.3,
                          .aspect_min = 0.7, .colour_open = {0.85f, 0.62f, 0.7f},
                          .colour_faded = {0.7f, 0.6f, 0.5f}, .colour_jitter = 0.25,
                          .max_instances = 20000000};
}

static int finite_in(double v, double lo, double hi) { return isfinite(v) && v >= lo && v <= hi; }

int blossom_params_check(const blossom_params *p, err_buf *err)
{
    if (!isfinite(p->first_day) || !isfinite(p->last_day) || !(p->last_day > p->first_day))
        return err_set(err, "blossom: the season %g to %g: last_day must be a number after first_day",
                       p->first_day, p->last_day);
    if (!finite_in(p->lifetime_min, 1e-6, 1e6) || !finite_in(p->lifetime_max, p->lifetime_min, 1e6))
        return err_set(err, "blossom: lifetime %g to %g days: need 0 < lifetime_min <= lifetime_max <= 1e6",
                       p->lifetime_min, p->lifetime_max);
    if (!finite_in(p->per_point, 0, 1e3))
        return err_set(err, "blossom: per_point %g: need a number in [0, 1000]", p->per_point);
    if (!finite_in(p->speed_max, 0, 10))
        return err_set(err, "blossom: speed_max %g m/day: need a number in [0, 10]", p->speed_max);
    if (!finite_in(p->size_min, 1e-6, 10) || !finite_in(p->size_max, p->size_min, 10))
        return err_set(err, "blossom: size %g to %g m: need 0 < size_min <= size_max <= 10", p->size_min,
                       p->size_max);
    if (!finite_in(p->bud_size, 1e-6, 1))
        return err_set(err, "blossom: bud_size %g: need a share in (0, 1]", p->bud_size);
    if (!finite_in(p->opening, 1e-6, 1))
        return err_set(err, "blossom: opening %g: need a share of the lifetime in (0, 1]", p->opening);
    if (!finite_in(p->aspect_min, 1e-3, 1))
        return err_set(err, "blossom: aspect_min %g: need a number in (0, 1]", p->aspect_min);
    if (!finite_in(p->colour_jitter, 0, 1))
        return err_set(err, "blossom: colour_jitter %g: need a share in [0, 1]", p->colour_jitter);
    for (int c = 0; c < 3; c++)
        if (!finite_in(p->colour_open[c], 0, 1) || !finite_in(p->colour_faded[c], 0, 1))
            return err_set(err, "blossom: colours must be linear RGB with each channel in [0, 1]");
    return 0;
}

static double uniform(sylva_rng *r, double lo, double hi) { return lo + (hi - lo) * rng_next_double(r); }

/* A uniformly distributed unit vector (Archimedes: z uniform in [-1, 1], angle uniform). */
static vec3 unit_vector(sylva_rng *r)
{
    double z = uniform(r, -1, 1), a = uniform(r, 0, 2 * M_PI), s = sqrt(fmax(0.0, 1 - z * z));
    return v3((float)(s * cos(a)), (float)(s * sin(a)), (float)z);
}

uint32_t blossom_particle_count(const blossom_params *p, uint64_t seed, uint32_t plant, uint32_t n_points)
{
    sylva_rng r;
    rng_stream(&r, seed, "blossom count", plant);
    double want = p->per_point * n_points + rng_next_double(&r); /* stochastic rounding */
    return want >= (double)p->max_per_plant ? p->max_per_plant : (uint32_t)want;
}

void blossom_particle_draw(const blossom_params *p, uint64_t seed, uint32_t plant, uint32_t k,
                           uint32_t n_points, blossom_particle *out)
{
    sylva_rng r;
    rng_stream(&r, rng_combine(seed, plant), "blossom particle", k);
    uint32_t pt = (uint32_t)(rng_next_double(&r) * n_points);
    out->point = pt < n_points ? pt : n_points - 1;
    out->birth = uniform(&r, p->first_day, p->last_day);
    out->lifetime = uniform(&r, p->lifetime_min, p->lifetime_max);
    out->velocity = v3_scale(unit_vector(&r), (float)uniform(&r, 0, p->speed_max));
    out->normal = unit_vector(&r);
    out->size = uniform(&r, p->size_min, p->size_max);
    out->aspect = uniform(&r, p->aspect_min, 1);
    out->tint = rng_next_double(&r);
}

blossom_state blossom_particle_at(const blossom_params *p, const blossom_particle *q, double day)
{
    blossom_state st = {0};
    double t = day - q->birth;
    st.alive = t >= 0 && t < q->lifetime;
    if (!st.alive) return st;
    st.age = t / q->lifetime;
    st.offset = v3_scale(q->velocity, (float)t);
    double open = fmin(1.0, st.age / p->opening);
    st.radius = q->size * (p->bud_size + (1 - p->bud_size) * open);
    st.colour = (1 - p->colour_jitter) * st.age + p->colour_jitter * q->tint;
    return st;
}

vec3 blossom_colour(const blossom_params *p, double c)
{
    float w = (float)fmin(1.0, fmax(0.0, c));
    const float *a = p->colour_open, *b = p->colour_faded;
    return v3(a[0] + (b[0] - a[0]) * w, a[1] + (b[1] - a[1]) * w, a[2] + (b[2] - a[2]) * w);
}

static uint32_t material_is_leaf(const scene *s, const mesh *m, uint32_t t)
{
    return s->materials[scene_triangle_material(s, m, t)].bsdf == SYLVA_BSDF_LEAF;
}

int blossom_crown_points(const scene *s, uint32_t proto, float **pts, uint32_t *n, err_buf *err)
{
    const mesh *m = s->prototypes[proto].mesh;
    *pts = NULL, *n = 0;
    if (!m || m->nt == 0) return 0;
    uint32_t leaves = 0;
    for (uint32_t t = 0; t < m->nt; t++) leaves += material_is_leaf(s, m, t);
    float lo[3], hi[3];
    mesh_bounds(m, lo, hi);
    float upper = 0.5f * (lo[2] + hi[2]);
    float *out = malloc((size_t)m->nt * 3 * sizeof *out); /* owned by the caller */
    if (!out) return err_set(err, "blossom: out of memory for %u crown points", m->nt);
    uint32_t k = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
        float c[3] = {0, 0, 0};
        for (int v = 0; v < 3; v++)
            for (int a = 0; a < 3; a++) c[a] += m->pos[3 * m->tri[3 * t + v] + a] / 3.0f;
        if (leaves ? !material_is_leaf(s, m, t) : c[2] < upper) continue;
        out[3 * k] = c[0], out[3 * k + 1] = c[1], out[3 * k + 2] = c[2];
        k++;
    }
    if (k == 0) return free(out), 0;
    *pts = out, *n = k;
    return 0;
}

/* The petal: a unit octagon in the XY plane facing +Z, all of material `mat`. */
static mesh *petal_mesh(int32_t mat, err_buf *err)
{
    float pos[3 * (BLOSSOM_DISC_SIDES + 1)] = {0, 0, 0}, nrm[3 * (BLOSSOM_DISC_SIDES + 1)];
    uint32_t tri[3 * BLOSSOM_DISC_SIDES];
    for (uint32_t v = 0; v <= BLOSSOM_DISC_SIDES; v++) nrm[3 * v] = 0, nrm[3 * v + 1] = 0, nrm[3 * v + 2] = 1;
    for (uint32_t k = 0; k < BLOSSOM_DISC_SIDES; k++) {
        double a = 2 * M_PI * k / BLOSSOM_DISC_SIDES;
        pos[3 * (k + 1)] = (float)cos(a), pos[3 * (k + 1) + 1] = (float)sin(a), pos[3 * (k + 1) + 2] = 0;
        tri[3 * k] = 0, tri[3 * k + 1] = k + 1, tri[3 * k + 2] = (k + 1) % BLOSSOM_DISC_SIDES + 1;
    }
    mesh *m = mesh_new(); /* owned by the caller, then by the scene's prototype */
    if (!m) return err_set(err, "blossom: out of memory for the petal mesh"), NULL;
    if (mesh_append(m, pos, nrm, NULL, BLOSSOM_DISC_SIDES + 1, tri, NULL, mat, BLOSSOM_DISC_SIDES, err)) {
        mesh_free(m);
        return NULL;
    }
    return m;
}

/* The petal species of `plant_species`: BLOSSOM_COLOURS discs along the colour ramp. Returns the first
 * prototype's index, or -1 with err set. */
static int32_t add_petals(scene *s, uint32_t plant_species, const blossom_params *p, err_buf *err)
{
    char name[256];
    snprintf(name, sizeof name, "blossom %s", s->species[plant_species].name ? s->species[plant_species].name : "");
    int32_t sp = scene_add_species(s, name, err);
    if (sp < 0) return -1;
    s->species[sp].ground_cover = 1; /* not a plant: no canopy, no crown proxy */
    int32_t first = -1;
    for (uint32_t v = 0; v < BLOSSOM_COLOURS; v++) {
        vec3 c = blossom_colour(p, (v + 0.5) / BLOSSOM_COLOURS);
        char mname[300];
        snprintf(mname, sizeof mname, "%s %u", name, v);
        sylva_material_desc d = {.size = sizeof d, .name = mname, .bsdf = SYLVA_BSDF_LEAF,
                                 .albedo = {c.x, c.y, c.z},
                                 .transmittance = {0.4f * c.x, 0.4f * c.y, 0.4f * c.z}, .texture = -1};
        int32_t mat = scene_add_material(s, &d, err);
        if (mat < 0) return -1;
        mesh *m = petal_mesh(mat, err);
        if (!m) return -1;
        int32_t pr = scene_add_prototype(s, (uint32_t)sp, v, 1.0, 0.0, m, err);
        if (pr < 0) return -1;
        s->species[sp].n_variants++;
        if (v == 0) first = pr;
    }
    return first;
}

/* The cube root of |det| of xf's linear part: the plant's scale. */
static double xf_scale(const xform3x4 *x)
{
    const float(*m)[4] = x->m;
    double det = m[0][0] * ((double)m[1][1] * m[2][2] - (double)m[1][2] * m[2][1]) -
                 m[0][1] * ((double)m[1][0] * m[2][2] - (double)m[1][2] * m[2][0]) +
                 m[0][2] * ((double)m[1][0] * m[2][1] - (double)m[1][1] * m[2][0]);
    double sc = cbrt(fabs(det));
    return sc > 0 && isfinite(sc) ? sc : 1.0;
}

/* The petal's transform in the plant's frame: centre c, disc across the normal, radii rx, ry. */
static xform3x4 petal_xf(vec3 c, vec3 n, double rx, double ry)
{
    vec3 t, b;
    v3_basis(n, &t, &b);
    float x = (float)rx, y = (float)ry, z = (float)rx;
    return (xform3x4){{{t.x * x, b.x * y, n.x * z, c.x}, {t.y * x, b.y * y, n.y * z, c.y},
                       {t.z * x, b.z * y, n.z * z, c.z}}};
}

/* Crown points per prototype, filled on first use. */
typedef struct crown_cache {
    float **pts;     /* [n_prototypes] owned arrays, or NULL */
    uint32_t *n;     /* [n_prototypes] */
    uint8_t *done;   /* [n_prototypes] */
    uint32_t count;
} crown_cache;

static void cache_free(crown_cache *c)
{
    for (uint32_t i = 0; c->pts && i < c->count; i++) free(c->pts[i]);
    free(c->pts), free(c->n), free(c->done);
}

int blossom_add(scene *s, uint32_t plant_species, const blossom_params *p, double day, uint64_t seed,
                blossom_report *rep, err_buf *err)
{
    blossom_report rp = {0};
    if (rep) *rep = rp;
    if (blossom_params_check(p, err)) return -1;
    if (!isfinite(day)) return err_set(err, "blossom: the day %g is not a number", day);
    if (plant_species >= s->n_species)
        return err_set(err, "blossom: species %u: the scene has %u species", plant_species, s->n_species);
    const uint32_t n_plants = s->n_instances, n_protos = s->n_prototypes; /* before the petals */
    crown_cache cc = {calloc(n_protos ? n_protos : 1, sizeof *cc.pts), calloc(n_protos ? n_protos : 1, sizeof *cc.n),
                      calloc(n_protos ? n_protos : 1, 1), n_protos};
    int rc = -1;
    int32_t petal = -1;
    if (!cc.pts || !cc.n || !cc.done) {
        err_set(err, "blossom: out of memory");
        goto done;
    }
    for (uint32_t i = 0; i < n_plants; i++) {
        const instance in = s->instances[i]; /* a copy: adding instances moves the array */
        if (in.prototype >= n_protos || s->prototypes[in.prototype].species != plant_species) continue;
        rp.plants++;
        if (!cc.done[in.prototype]) {
            if (blossom_crown_points(s, in.prototype, &cc.pts[in.prototype], &cc.n[in.prototype], err)) goto done;
            cc.done[in.prototype] = 1;
        }
        const float *pts = cc.pts[in.prototype];
        uint32_t np = cc.n[in.prototype];
        if (np == 0) continue;
        double inv_scale = 1.0 / xf_scale(&in.xf);
        uint32_t count = blossom_particle_count(p, seed, i, np);
        rp.particles += count;
        for (uint32_t k = 0; k < count; k++) {
            blossom_particle q;
            blossom_particle_draw(p, seed, i, k, np, &q);
            blossom_state st = blossom_particle_at(p, &q, day);
            if (!st.alive) continue;
            if (rp.petals >= p->max_instances) {
                err_set(err, "blossom: more than max_instances = %llu petals on day %g; fewer flowers per crown "
                             "point (per_point) or a larger max_instances would do",
                        (unsigned long long)p->max_instances, day);
                goto done;
            }
            if (petal < 0 && (petal = add_petals(s, plant_species, p, err)) < 0) goto done;
            const float *c = pts + 3 * (size_t)q.point;
            vec3 centre = v3_add(v3(c[0], c[1], c[2]), v3_scale(st.offset, (float)inv_scale));
            double rx = st.radius * inv_scale;
            xform3x4 local = petal_xf(centre, q.normal, rx, rx * q.aspect);
            xform3x4 world = xf_compose(&in.xf, &local);
            uint32_t bin = (uint32_t)(st.colour * BLOSSOM_COLOURS);
            if (bin >= BLOSSOM_COLOURS) bin = BLOSSOM_COLOURS - 1;
            if (scene_add_instance(s, (uint32_t)petal + bin, &world, err) < 0) goto done;
            rp.petals++;
        }
    }
    rc = 0;
done:
    cache_free(&cc);
    if (rep) *rep = rp;
    return rc;
}
