/* curved_ray.c — the chain of chords along a camera ray's curved path (curved_ray.h). Every
 * number is a double until the chord is handed to Embree, so the chain is the same on every
 * thread and for every tile order. */
#include "render/curved_ray.h"

#include <math.h>

void curved_rays_init(curved_rays *cr, const earth_settings *earth, const camera *c, const float lo[3],
                      const float hi[3])
{
    *cr = (curved_rays){.origin = {c->origin.x, c->origin.y, c->origin.z}};
    if (!earth || !earth->curvature || earth->refraction == 1.0) return;
    cr->on = 1;
    cr->lift = (1.0 - earth->refraction) / (2.0 * earth->radius);
    cr->tolerance = CURVED_RAY_PIXEL_SHARE * camera_smallest_pixel_angle(c);
    for (int k = 0; k < 3; k++) {
        double margin = 1.0 + 1e-3 * ((double)hi[k] - (double)lo[k]);
        cr->lo[k] = (double)lo[k] - margin;
        cr->hi[k] = (double)hi[k] + margin;
    }
}

/* The largest root of a t^2 + b t + c = 0 (a != 0), or -INFINITY when there is none. */
static double largest_root(double a, double b, double c)
{
    double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return -INFINITY;
    double r1 = (-b + sqrt(disc)) / (2.0 * a), r2 = (-b - sqrt(disc)) / (2.0 * a);
    return fmax(r1, r2);
}

/* The path parameter after which P(t) stays outside the bounds for good (<= 0: it never comes
 * inside ahead of the camera). Horizontally the path is a straight line; vertically a parabola
 * that, for a > 0, leaves through the top and, for a < 0, through the bottom. */
static double path_end(const curved_rays *cr, const double d[3], double a)
{
    const double *o = cr->origin;
    double t_end = INFINITY;
    for (int k = 0; k < 2; k++) {
        if (d[k] > 0.0) t_end = fmin(t_end, (cr->hi[k] - o[k]) / d[k]);
        else if (d[k] < 0.0) t_end = fmin(t_end, (cr->lo[k] - o[k]) / d[k]);
        else if (o[k] < cr->lo[k] || o[k] > cr->hi[k]) return -INFINITY;
    }
    double bound = a > 0.0 ? cr->hi[2] : cr->lo[2];
    return fmin(t_end, largest_root(a, d[2], o[2] - bound));
}

void curved_path_begin(curved_path *p, const curved_rays *cr, vec3 d)
{
    *p = (curved_path){.d = {d.x, d.y, d.z}, .cr = cr};
    p->a = cr->on ? cr->lift * (p->d[0] * p->d[0] + p->d[1] * p->d[1]) : 0.0;
    if (p->a == 0.0) {
        p->straight = 1;
        return;
    }
    p->t_first = cr->tolerance / fabs(p->a);
    p->t_end = path_end(cr, p->d, p->a);
}

static void path_point(const curved_path *p, double t, double out[3])
{
    for (int k = 0; k < 3; k++) out[k] = p->cr->origin[k] + t * p->d[k];
    out[2] += p->a * t * t;
}

int curved_path_next(curved_path *p, vec3 *org, vec3 *dir, float *len, double *t0, double *dt)
{
    if (p->straight) {
        if (p->chords++) return 0;
        const double *o = p->cr->origin;
        *org = v3((float)o[0], (float)o[1], (float)o[2]);
        *dir = v3((float)p->d[0], (float)p->d[1], (float)p->d[2]);
        *len = INFINITY, *t0 = 0.0, *dt = 0.0;
        return 1;
    }
    if (!(p->t < p->t_end)) return 0;
    /* Chord error |a| L^2 / 4 seen from distance t: at most tol when L = 2 sqrt(t t_first). */
    double t1 = p->chords == 0 ? p->t_first : p->t + 2.0 * sqrt(p->t * p->t_first);
    if (t1 > p->t_end || p->chords + 1 >= CURVED_RAY_MAX_CHORDS) t1 = p->t_end;
    double a[3], b[3], v[3];
    path_point(p, p->t, a);
    path_point(p, t1, b);
    for (int k = 0; k < 3; k++) v[k] = b[k] - a[k];
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    *org = v3((float)a[0], (float)a[1], (float)a[2]);
    *dir = v3((float)(v[0] / l), (float)(v[1] / l), (float)(v[2] / l));
    *len = (float)l, *t0 = p->t, *dt = t1 - p->t;
    p->t = t1;
    p->chords++;
    return 1;
}
