/* ztv_sight.c — a sightline over the curved Earth as a chain of Embree occlusion rays. */
#include "ztv/ztv_sight.h"

#include <math.h>

void ztv_sight_init(ztv_sight *s, RTCScene scene, const earth_settings *earth)
{
    s->scene = scene;
    s->c = earth && earth->curvature ? (1.0 - earth->refraction) / (2.0 * earth->radius) : 0.0;
}

uint32_t ztv_sight_chords(const ztv_sight *s, const double o[3], const double t[3])
{
    double span = hypot(t[0] - o[0], t[1] - o[1]);
    /* c (span / n)^2 / 4 <= sag */
    double n = ceil(span * sqrt(fabs(s->c) / (4.0 * ZTV_SIGHT_SAG)));
    return n < 1 ? 1u : n > 4096 ? 4096u : (uint32_t)n;
}

/* The point at share u of the way from o to t on the sagging sightline. */
static void sight_point(const ztv_sight *s, const double o[3], const double t[3], double span2, double u,
                        double p[3])
{
    for (int k = 0; k < 3; k++) p[k] = o[k] + u * (t[k] - o[k]);
    p[2] -= s->c * span2 * u * (1.0 - u);
}

int ztv_sight_clear(const ztv_sight *s, const double o[3], const double t[3], unsigned mask, uint64_t *rays)
{
    uint32_t n = ztv_sight_chords(s, o, t);
    double span2 = (t[0] - o[0]) * (t[0] - o[0]) + (t[1] - o[1]) * (t[1] - o[1]);
    double a[3] = {o[0], o[1], o[2]}, b[3];
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (uint32_t i = 1; i <= n; i++) {
        sight_point(s, o, t, span2, (double)i / n, b);
        double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        double far = i == n ? len - ZTV_SIGHT_GAP : len;
        if (far > 0) {
            /* the first chord leaves the observer a gap away too: an eye at height 0 is on the ground */
            float near = i == 1 ? (float)fmin(ZTV_SIGHT_GAP, 0.5 * far) : 0.0f;
            struct RTCRay ray = {.org_x = (float)a[0], .org_y = (float)a[1], .org_z = (float)a[2], .tnear = near,
                                 .dir_x = (float)(d[0] / len), .dir_y = (float)(d[1] / len),
                                 .dir_z = (float)(d[2] / len), .time = 0.0f, .tfar = (float)far, .mask = mask,
                                 .id = 0, .flags = 0};
            rtcOccluded1(s->scene, &ctx, &ray);
            if (rays) (*rays)++;
            if (ray.tfar < 0) return 0; /* Embree marks an occluded ray with tfar = -inf */
        }
        a[0] = b[0], a[1] = b[1], a[2] = b[2];
    }
    return 1;
}
