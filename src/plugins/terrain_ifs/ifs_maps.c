/* ifs_maps.c — building the maps w_{n,m} (8)-(12) and the alias table of R. */
#include "ifs_maps.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sylva/plugin.h"

void ifs_maps_free(ifs_maps *m)
{
    if (!m) return;
    free(m->probability), free(m->alias_cell);
    free(m->alias_threshold);
    free(m);
}

/* Vose's alias method over the normalised probabilities. */
static int build_alias(ifs_maps *m, plugin_err *err)
{
    uint32_t n = m->n_maps;
    double *scaled = malloc((size_t)n * sizeof *scaled); /* owned here */
    uint32_t *small = malloc((size_t)n * sizeof *small), *large = malloc((size_t)n * sizeof *large);
    m->alias_cell = malloc((size_t)n * sizeof *m->alias_cell);
    m->alias_threshold = malloc((size_t)n * sizeof *m->alias_threshold);
    int rc = SYLVA_OK;
    if (!scaled || !small || !large || !m->alias_cell || !m->alias_threshold) {
        rc = plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the probability table of %u maps", n);
        goto done;
    }
    uint32_t ns = 0, nl = 0;
    for (uint32_t c = 0; c < n; c++) {
        scaled[c] = m->probability[c] * n;
        if (scaled[c] < 1.0) small[ns++] = c;
        else large[nl++] = c;
    }
    while (ns && nl) {
        uint32_t s = small[--ns], l = large[--nl];
        m->alias_cell[s] = l;
        m->alias_threshold[s] = (uint32_t)(scaled[s] * 4294967296.0);
        scaled[l] = scaled[l] + scaled[s] - 1.0;
        if (scaled[l] < 1.0) small[ns++] = l;
        else large[nl++] = l;
    }
    /* What is left holds (up to rounding) probability 1: always keep it. */
    while (nl) {
        uint32_t c = large[--nl];
        m->alias_cell[c] = c, m->alias_threshold[c] = UINT32_MAX;
    }
    while (ns) {
        uint32_t c = small[--ns];
        m->alias_cell[c] = c, m->alias_threshold[c] = UINT32_MAX;
    }
done:
    free(scaled), free(small), free(large);
    return rc;
}

int ifs_maps_build(const ifs_dtm *dtm, const ifs_maps_params *p, ifs_maps **out, plugin_err *err)
{
    *out = NULL;
    int rc = ifs_dtm_check_size(dtm->nx, dtm->ny, err);
    if (rc) return rc;
    uint32_t nx = dtm->nx, ny = dtm->ny, ncx = nx - 1, ncy = ny - 1, n = ncx * ncy;
    if (!p->alpha_field && !(p->alpha > -1.0 && p->alpha < 1.0))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "alpha %g is outside (-1, 1); the maps must contract in z", p->alpha);
    for (uint32_t c = 0; p->alpha_field && c < n; c++)
        if (!(p->alpha_field[c] > -1.0 && p->alpha_field[c] < 1.0))
            return plugin_fail(err, SYLVA_ERR_PARAM,
                            "alpha of cell (%u, %u) is %g; every alpha must be inside (-1, 1)",
                            c % ncx, c / ncx, p->alpha_field[c]);
    double wsum = 0.0;
    for (uint32_t c = 0; p->probability && c < n; c++) {
        double w = p->probability[c];
        if (!(w >= 0.0 && isfinite(w)))
            return plugin_fail(err, SYLVA_ERR_PARAM,
                            "probability of cell (%u, %u) is %g; weights must be finite and >= 0",
                            c % ncx, c / ncx, w);
        wsum += w;
    }
    if (p->probability && !(wsum > 0.0))
        return plugin_fail(err, SYLVA_ERR_PARAM,
                        "every probability weight is 0; at least one cell must have a positive "
                        "weight");

    ifs_maps *m = calloc(1, sizeof *m); /* owned by the caller */
    if (!m) return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the IFS maps");
    *m = (ifs_maps){.mode = p->mode, .nx = nx, .ny = ny, .ncx = ncx, .ncy = ncy, .n_maps = n,
                    .su = 1.0 / ncx, .sv = 1.0 / ncy, .width = ncx * dtm->dx,
                    .depth = ncy * dtm->dy, .uniform = !p->probability,
                    .node_z = dtm->z, .alpha_field = p->alpha_field, .alpha = p->alpha};
    if (p->probability && !(m->probability = malloc((size_t)n * sizeof *m->probability))) {
        ifs_maps_free(m);
        return plugin_fail(err, SYLVA_ERR_NOMEM, "out of memory for the probabilities of %u IFS maps",
                        n);
    }
    const double *z = dtm->z;
#define Z(i, j) z[(size_t)(j) * nx + (i)]
    m->z11 = Z(0, 0), m->zn1 = Z(ncx, 0), m->znm = Z(ncx, ncy), m->z1m = Z(0, ncy);
    double z11 = m->z11, zn1 = m->zn1, znm = m->znm, z1m = m->z1m;
    double bound = 0.0;
    for (uint32_t c = 0; c < n; c++) {
        ifs_map w = ifs_maps_cell(m, c);
        double corner = fmax(fmax(fabs(w.c0), fabs(w.c0 + w.cu)),
                             fmax(fabs(w.c0 + w.cv), fabs(w.c0 + w.cu + w.cv + w.cuv)));
        if (corner > bound) bound = corner;
        if (fabs(w.alpha) > m->alpha_max) m->alpha_max = fabs(w.alpha);
        if (m->probability) m->probability[c] = p->probability[c] / wsum;
    }
    for (uint32_t j = 0; j < ny; j++)
        for (uint32_t i = 0; i < nx; i++) {
            double u = (double)i / ncx, v = (double)j / ncy;
            double plane = (1 - v) * ((1 - u) * z11 + u * zn1) + v * ((1 - u) * z1m + u * znm);
            m->corner_departure = fmax(m->corner_departure, fabs(Z(i, j) - plane));
        }
#undef Z
    /* |F| <= corner + alpha_max |z| on the unit square keeps |z| <= bound / (1 - alpha_max). */
    m->z_bound = bound / (1.0 - m->alpha_max);
    if (!m->uniform && (rc = build_alias(m, err))) {
        ifs_maps_free(m);
        return rc;
    }
    *out = m;
    return SYLVA_OK;
}

void ifs_map_paper_coefficients(const ifs_maps *m, uint32_t n, uint32_t cell_m, double x1, double y1,
                                double *a, double *b, double *e, double *c)
{
    ifs_map map = ifs_maps_cell(m, cell_m * m->ncx + n);
    const ifs_map *w = &map;
    double W = m->width, H = m->depth;
    *a = w->cu / W - w->cuv * y1 / (W * H);
    *b = w->cv / H - w->cuv * x1 / (W * H);
    *e = w->cuv / (W * H);
    *c = w->c0 - w->cu * x1 / W - w->cv * y1 / H + w->cuv * x1 * y1 / (W * H);
}
