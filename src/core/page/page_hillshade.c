/* page_hillshade.c — a hillshade's grey from a grid of heights (page_hillshade.h). */
#include "page/page_hillshade.h"

#include <math.h>
#include <stddef.h>

uint8_t page_hillshade(const float *z, uint32_t w, uint32_t h, double spacing, uint32_t u, uint32_t v)
{
    size_t k = (size_t)v * w + u;
    double zc = z[k];
    int has_w = u > 0 && isfinite(z[k - 1]), has_e = u + 1 < w && isfinite(z[k + 1]);
    int has_n = v > 0 && isfinite(z[k - w]), has_s = v + 1 < h && isfinite(z[k + w]);
    double zw = has_w ? z[k - 1] : zc, ze = has_e ? z[k + 1] : zc;
    double zn = has_n ? z[k - w] : zc, zs = has_s ? z[k + w] : zc;
    double nw = has_w + has_e, nn = has_n + has_s;
    double dzdx = nw > 0 ? (ze - zw) / (nw * spacing) : 0; /* east */
    double dzdy = nn > 0 ? (zn - zs) / (nn * spacing) : 0; /* north */
    double len = sqrt(dzdx * dzdx + dzdy * dzdy + 1);
    const double s = sqrt(0.5), sun[3] = {-0.5, 0.5, s}; /* azimuth 315, altitude 45 */
    double lit = (-dzdx * sun[0] - dzdy * sun[1] + sun[2]) / len;
    if (!(lit > 0)) lit = 0;
    /* level ground (lit = sqrt 1/2) comes out HILLSHADE_FLAT_GREY; fully lit 255 */
    double grey = HILLSHADE_FLAT_GREY + (lit - s) * (255 - HILLSHADE_FLAT_GREY) / (1 - s);
    if (lit < s) grey = 70 + lit / s * (HILLSHADE_FLAT_GREY - 70);
    return (uint8_t)lround(grey);
}
