/* aono_frame.c — the mother branch's dynamic frame (18)–(19) of seed 000, built orthonormal,
 * with the vertical-mother special case, and the child tips (16)–(17) in it. */
#include "aono_frame.h"

#include <math.h>

#include "vec3.h"

#define AONO_DEG (3.14159265358979323846 / 180.0)

int aono_frame_build(const double pa[3], const double pb[3], aono_frame *f)
{
    double d[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    double T = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]); /* (19) */
    if (!(T > 0.0) || !isfinite(T)) return -1;
    double S = sqrt(d[0] * d[0] + d[1] * d[1]);
    for (int k = 0; k < 3; k++) f->z[k] = d[k] / T;
    if (S > 1e-12 * T) {
        /* y' = ẑ × z' / |ẑ × z'| — horizontal; the mirror of the paper's (sin α, −cos α, 0) */
        f->y[0] = -d[1] / S, f->y[1] = d[0] / S, f->y[2] = 0.0;
    } else {
        /* vertical mother: α from the position of P_b about the z axis (the special case) */
        double r = sqrt(pb[0] * pb[0] + pb[1] * pb[1]);
        double scale = fmax(1.0, sqrt(r * r + pb[2] * pb[2]));
        if (r > 1e-9 * scale) {
            f->y[0] = -pb[1] / r, f->y[1] = pb[0] / r, f->y[2] = 0.0;
        } else {
            f->y[0] = 1.0, f->y[1] = 0.0, f->y[2] = 0.0;
        }
        /* exactly vertical: z' is ±ẑ */
        f->z[0] = 0.0, f->z[1] = 0.0, f->z[2] = d[2] > 0.0 ? 1.0 : -1.0;
    }
    vec3_cross(f->z, f->y, f->x);
    return 0;
}

void aono_frame_child(const aono_frame *f, const double pb[3], double rho, double phi_deg,
                      double azimuth_deg, double out[3])
{
    double phi = phi_deg * AONO_DEG, az = azimuth_deg * AONO_DEG;
    double cx = sin(phi) * cos(az), cy = sin(phi) * sin(az), cz = cos(phi); /* (16) */
    for (int k = 0; k < 3; k++) out[k] = pb[k] + rho * (cx * f->x[k] + cy * f->y[k] + cz * f->z[k]); /* (17) */
}
