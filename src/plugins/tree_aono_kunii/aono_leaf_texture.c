/* aono_leaf_texture.c — the leaf texture: a blade outline of the chosen shape in alpha, a
 * stalk, a lighter midrib and secondary veins. Near-white texels carry the pattern; the leaf
 * material's albedo carries the colour. */
#include <math.h>

#include "aono_mesh.h"

#define STALK 0.1 /* the bottom tenth of the texture is the stalk */

/* (4σ(1 − σ))^e with σ = s^k: a blade widest at s = 0.5^(1/k), blunter for smaller e. */
static double blade(double s, double k, double e)
{
    double sigma = pow(s, k), w = 4.0 * sigma * (1.0 - sigma);
    return w > 0.0 ? pow(w, e) : 0.0;
}

double aono_leaf_half_width(aono_leaf_shape shape, double s)
{
    if (!(s > 0.0 && s < 1.0)) return 0.0;
    switch (shape) {
    case AONO_LEAF_ELLIPTIC: return blade(s, 1.0, 0.5);
    case AONO_LEAF_OVATE: return blade(s, 0.7, 0.6);
    case AONO_LEAF_OBOVATE: return blade(s, 1.5, 0.6);
    case AONO_LEAF_LANCEOLATE: return blade(s, 0.8, 0.9);
    case AONO_LEAF_CORDATE: {
        /* widest at s = 0.3, rounded lobes at the base, a pointed tip */
        double x = s < 0.3 ? (0.3 - s) / 0.3 : (s - 0.3) / 0.7;
        return s < 0.3 ? sqrt(1.0 - x * x * x * x) : pow(1.0 - x * x, 0.75);
    }
    }
    return 0.0;
}

/* Whether (x, s) — x = |u − ½| / ½ across, s along the blade — lies on the blade. */
static int on_blade(aono_leaf_shape shape, double x, double s)
{
    double hw = aono_leaf_half_width(shape, s);
    if (x > hw) return 0;
    /* the cordate blade's V-shaped sinus at the stalk */
    if (shape == AONO_LEAF_CORDATE && s < 0.12 * (1.0 - x / 0.35)) return 0;
    return 1;
}

void aono_leaf_texture(aono_leaf_shape shape, uint32_t w, uint32_t h, uint8_t *rgba)
{
    for (uint32_t row = 0; row < h; row++) {
        double v = 1.0 - (row + 0.5) / h; /* row 0 is the top: v = 1 */
        for (uint32_t col = 0; col < w; col++) {
            double u = (col + 0.5) / w, x = fabs(u - 0.5) / 0.5;
            uint8_t *t = &rgba[4 * ((size_t)row * w + col)];
            int grey = 0, alpha = 0;
            if (v < STALK) {
                if (x < 0.08) grey = 200, alpha = 255;
            } else {
                double s = (v - STALK) / (1.0 - STALK);
                if (on_blade(shape, x, s)) {
                    double hw = aono_leaf_half_width(shape, s);
                    /* secondary veins leave the midrib toward the tip, about 7 pairs */
                    double phase = (s - 0.55 * x) * 7.0;
                    int vein = phase - floor(phase) < 0.09;
                    grey = x < 0.05 ? 255 : vein ? 247 : x > 0.88 * hw ? 214 : 232;
                    alpha = 255;
                }
            }
            t[0] = t[1] = (uint8_t)grey;
            t[2] = (uint8_t)(grey > 20 ? grey - 20 : grey);
            t[3] = (uint8_t)alpha;
        }
    }
}
