/* ztv_summary.c — cell counts per mode, band, class and development, turned into km² only when
 * written (cell area times count), so the areas add up to the grid's exactly as the counts do. */
#include "ztv/ztv_summary.h"

#include <math.h>
#include <stdlib.h>

#include "util/json_text.h"

typedef struct mode_counts {
    uint64_t band[ZTV_BANDS];                     /* open cells by band of visible fraction */
    uint64_t cls[ZTV_CLASSES];                    /* cells by ztv_class */
    uint64_t development[ZTV_MAX_DEVELOPMENTS];   /* open cells from which development d is seen */
} mode_counts;

/* A screened mode against bare earth, over the cells open on bare earth that see something. */
typedef struct screening_counts {
    uint64_t hidden;        /* open in the screened mode, nothing visible */
    uint64_t partly_hidden; /* open, fewer targets visible than on bare earth, but some */
    uint64_t unchanged;     /* open, as many targets visible as on bare earth */
    uint64_t not_viewpoint; /* under a crown or inside an object in the screened mode */
} screening_counts;

struct ztv_summary {
    const ztv_info *info;          /* borrowed */
    mode_counts mode[ZTV_MODES];
    screening_counts screening[ZTV_MODES];
};

ztv_band ztv_band_of(float f)
{
    if (!(f > 0.0f)) return ZTV_BAND_NONE;
    if (f <= 0.25f) return ZTV_BAND_1_25;
    if (f <= 0.5f) return ZTV_BAND_25_50;
    if (f <= 0.75f) return ZTV_BAND_50_75;
    if (f < 1.0f) return ZTV_BAND_75_100;
    return ZTV_BAND_ALL;
}

const char *ztv_band_label(ztv_band band)
{
    static const char *const labels[ZTV_BANDS] = {"0", "1-25", "25-50", "50-75", "75-<100", "100"};
    return band < ZTV_BANDS ? labels[band] : "?";
}

/* the terrain's edges in the order of ztv_grid.past_edge, as CSV quantities and JSON keys name them */
static const char *const edge_key[ZTV_EDGES] = {"west", "east", "south", "north"};

/* the same bands as names inside identifiers (CSV quantities, JSON keys) */
static const char *const band_key[ZTV_BANDS] = {"0", "1_25", "25_50", "50_75", "75_100", "100"};

const char *ztv_mode_name(ztv_mode mode)
{
    static const char *const names[ZTV_MODES] = {"bare", "vegetation", "all", "canopy"};
    return mode < ZTV_MODES ? names[mode] : "?";
}

ztv_summary *ztv_summary_new(const ztv_info *info, err_buf *err)
{
    ztv_summary *s = calloc(1, sizeof *s); /* owned by the caller: ztv_summary_free */
    if (!s) {
        err_nomem(err, "out of memory for the visibility map's summary");
        return NULL;
    }
    s->info = info;
    return s;
}

void ztv_summary_free(ztv_summary *s) { free(s); }

void ztv_summary_block(ztv_summary *s, const ztv_block *b)
{
    const ztv_info *info = s->info;
    size_t n = (size_t)b->rows * info->grid.nx;
    for (int m = 0; m < ZTV_MODES; m++) {
        const ztv_layer *l = b->layer[m];
        if (!info->computed[m] || !l) continue;
        mode_counts *c = &s->mode[m];
        for (size_t k = 0; k < n; k++) {
            uint8_t cls = l->cls[k] < ZTV_CLASSES ? l->cls[k] : ZTV_OUTSIDE;
            c->cls[cls]++;
            if (cls != ZTV_OPEN) continue;
            c->band[ztv_band_of(l->fraction[k])]++;
            for (uint32_t d = 0; d < info->n_developments && d < ZTV_MAX_DEVELOPMENTS; d++)
                if (l->developments[k] >> d & 1u) c->development[d]++;
        }
    }
    const ztv_layer *bare = b->layer[ZTV_BARE];
    if (!info->computed[ZTV_BARE] || !bare) return;
    for (int m = ZTV_VEGETATION; m < ZTV_MODES; m++) {
        const ztv_layer *l = b->layer[m];
        if (!info->computed[m] || !l) continue;
        screening_counts *c = &s->screening[m];
        for (size_t k = 0; k < n; k++) {
            if (bare->cls[k] != ZTV_OPEN || bare->visible[k] == 0) continue;
            if (l->cls[k] != ZTV_OPEN) c->not_viewpoint++;
            else if (l->visible[k] == 0) c->hidden++;
            else if (l->visible[k] < bare->visible[k]) c->partly_hidden++;
            else c->unchanged++;
        }
    }
}

/* --- writing ------------------------------------------------------------------------------ */

static double km2(const ztv_summary *s, uint64_t cells)
{
    double cell = s->info->grid.cell;
    return (double)cells * cell * cell * 1e-6;
}

static int screened(const ztv_summary *s, int m)
{
    return m != ZTV_BARE && s->info->computed[m] && s->info->computed[ZTV_BARE];
}

/* The map coordinates of the grid's outer west and north edges. */
static void grid_corner(const ztv_info *info, double *west, double *north)
{
    *west = info->origin[0] + info->grid.x0 - 0.5 * info->grid.cell;
    *north = info->origin[1] + info->grid.y0 + 0.5 * info->grid.cell;
}

static void csv_text(FILE *f, const char *text)
{
    fputc('"', f);
    for (const char *p = text ? text : ""; *p; p++) {
        if (*p == '"') fputc('"', f);
        fputc(*p, f);
    }
    fputc('"', f);
}

static void csv_area(FILE *f, const ztv_summary *s, const char *quantity, int m, const char *dev,
                     uint64_t cells)
{
    fprintf(f, "%s,%s,", quantity, ztv_mode_name((ztv_mode)m));
    if (dev) csv_text(f, dev);
    fprintf(f, ",%.12g,km2\n", km2(s, cells));
}

static const char *development_name(const ztv_info *info, uint32_t d)
{
    return info->development_names && info->development_names[d] ? info->development_names[d] : "";
}

static int stream_status(FILE *f, const char *what, err_buf *err)
{
    return ferror(f) ? err_fail(err, ERR_OUTPUT, "cannot write %s", what) : 0;
}

int ztv_summary_write_csv(const ztv_summary *s, FILE *f, err_buf *err)
{
    const ztv_info *info = s->info;
    double west, north;
    grid_corner(info, &west, &north);
    fputs("quantity,mode,development,value,unit\n", f);
    fprintf(f, "grid_columns,,,%u,cells\n", info->grid.nx);
    fprintf(f, "grid_rows,,,%u,cells\n", info->grid.ny);
    fprintf(f, "cell_size,,,%.12g,m\n", info->grid.cell);
    fprintf(f, "grid_west_edge,,,%.12g,m\n", west);
    fprintf(f, "grid_north_edge,,,%.12g,m\n", north);
    fputs("crs,,,", f);
    csv_text(f, info->crs_name ? info->crs_name : "local metres");
    fputs(",\n", f);
    fprintf(f, "observer_height,,,%.12g,m above ground\n", info->observer_height);
    if (info->ground) {
        fputs("ground,,,", f);
        csv_text(f, info->ground);
        fputs(",\n", f);
    }
    if (isfinite(info->radius)) fprintf(f, "radius,,,%.12g,m\n", info->radius);
    else fputs("radius,,,none,whole grid\n", f);
    for (int e = 0; e < ZTV_EDGES; e++)
        fprintf(f, "radius_past_%s_edge,,,%.12g,m past the terrain\n", edge_key[e], info->grid.past_edge[e]);
    fprintf(f, "earth_curvature,,,%d,1 applied / 0 not\n", info->curvature ? 1 : 0);
    fprintf(f, "refraction_k,,,%.12g,\n", info->refraction);
    fprintf(f, "targets,,,%u,\n", info->n_targets);
    fprintf(f, "developments,,,%u,\n", info->n_developments);
    char quantity[64];
    for (int m = 0; m < ZTV_MODES; m++) {
        if (!info->computed[m]) continue;
        const mode_counts *c = &s->mode[m];
        for (int band = 0; band < ZTV_BANDS; band++) {
            snprintf(quantity, sizeof quantity, "area_visible_%s", band_key[band]);
            csv_area(f, s, quantity, m, NULL, c->band[band]);
        }
        csv_area(f, s, "area_under_crown", m, NULL, c->cls[ZTV_UNDER_CROWN]);
        csv_area(f, s, "area_in_object", m, NULL, c->cls[ZTV_IN_OBJECT]);
        csv_area(f, s, "area_not_computed", m, NULL, c->cls[ZTV_OUTSIDE]);
        csv_area(f, s, "area_no_terrain", m, NULL, c->cls[ZTV_NO_TERRAIN]);
        for (uint32_t d = 0; d < info->n_developments && d < ZTV_MAX_DEVELOPMENTS; d++)
            csv_area(f, s, "area_development_visible", m, development_name(info, d), c->development[d]);
    }
    for (int m = ZTV_VEGETATION; m < ZTV_MODES; m++) {
        if (!screened(s, m)) continue;
        const screening_counts *c = &s->screening[m];
        csv_area(f, s, "area_hidden_by_screening", m, NULL, c->hidden);
        csv_area(f, s, "area_partly_hidden_by_screening", m, NULL, c->partly_hidden);
        csv_area(f, s, "area_still_visible_with_screening", m, NULL, c->unchanged);
        csv_area(f, s, "area_bare_visible_not_a_viewpoint", m, NULL, c->not_viewpoint);
    }
    return stream_status(f, "the summary table", err);
}


/* "key": {"cells": N, "km2": A} */
static void json_area(FILE *f, const ztv_summary *s, const char *indent, const char *key,
                      uint64_t cells, int last)
{
    fprintf(f, "%s", indent);
    json_write_string(f, key);
    fprintf(f, ": {\"cells\": %llu, \"km2\": %.12g}%s\n", (unsigned long long)cells,
            km2(s, cells), last ? "" : ",");
}

int ztv_summary_write_json(const ztv_summary *s, FILE *f, err_buf *err)
{
    const ztv_info *info = s->info;
    double west, north;
    grid_corner(info, &west, &north);
    fputs("{\n", f);
    fprintf(f, "  \"grid\": {\"columns\": %u, \"rows\": %u, \"cell_m\": %.12g, \"west_edge\": %.12g, "
               "\"north_edge\": %.12g},\n",
            info->grid.nx, info->grid.ny, info->grid.cell, west, north);
    fputs("  \"crs\": ", f);
    if (info->crs_name) json_write_string(f, info->crs_name);
    else fputs("null", f);
    fprintf(f, ",\n  \"observer_height_m\": %.12g,\n", info->observer_height);
    if (info->ground) {
        fputs("  \"ground\": ", f);
        json_write_string(f, info->ground);
        fputs(",\n", f);
    }
    if (isfinite(info->radius)) fprintf(f, "  \"radius_m\": %.12g,\n", info->radius);
    else fputs("  \"radius_m\": null,\n", f);
    fputs("  \"radius_past_terrain_m\": {", f);
    for (int e = 0; e < ZTV_EDGES; e++)
        fprintf(f, "%s\"%s\": %.12g", e ? ", " : "", edge_key[e], info->grid.past_edge[e]);
    fputs("},\n", f);
    fprintf(f, "  \"earth_curvature\": %s,\n  \"refraction_k\": %.12g,\n",
            info->curvature ? "true" : "false", info->refraction);
    fprintf(f, "  \"targets\": %u,\n  \"cell_km2\": %.12g,\n", info->n_targets, km2(s, 1));
    fputs("  \"developments\": [", f);
    for (uint32_t d = 0; d < info->n_developments; d++) {
        if (d) fputs(", ", f);
        json_write_string(f, development_name(info, d));
    }
    fputs("],\n  \"modes\": {", f);
    int first = 1;
    char key[64];
    for (int m = 0; m < ZTV_MODES; m++) {
        if (!info->computed[m]) continue;
        const mode_counts *c = &s->mode[m];
        fprintf(f, "%s\n    \"%s\": {\n      \"visible\": {\n", first ? "" : ",", ztv_mode_name((ztv_mode)m));
        first = 0;
        for (int band = 0; band < ZTV_BANDS; band++) {
            snprintf(key, sizeof key, "%s%%", ztv_band_label((ztv_band)band));
            json_area(f, s, "        ", key, c->band[band], band == ZTV_BANDS - 1);
        }
        fputs("      },\n", f);
        json_area(f, s, "      ", "under_crown", c->cls[ZTV_UNDER_CROWN], 0);
        json_area(f, s, "      ", "in_object", c->cls[ZTV_IN_OBJECT], 0);
        json_area(f, s, "      ", "not_computed", c->cls[ZTV_OUTSIDE], 0);
        json_area(f, s, "      ", "no_terrain", c->cls[ZTV_NO_TERRAIN], 0);
        fputs("      \"development_visible\": {", f);
        for (uint32_t d = 0; d < info->n_developments && d < ZTV_MAX_DEVELOPMENTS; d++) {
            fputs(d ? ",\n" : "\n", f);
            fputs("        ", f);
            json_write_string(f, development_name(info, d));
            fprintf(f, ": {\"cells\": %llu, \"km2\": %.12g}", (unsigned long long)c->development[d],
                    km2(s, c->development[d]));
        }
        fputs(info->n_developments ? "\n      }\n    }" : "}\n    }", f);
    }
    fputs("\n  },\n  \"screening\": {", f);
    first = 1;
    for (int m = ZTV_VEGETATION; m < ZTV_MODES; m++) {
        if (!screened(s, m)) continue;
        const screening_counts *c = &s->screening[m];
        fprintf(f, "%s\n    \"%s\": {\n", first ? "" : ",", ztv_mode_name((ztv_mode)m));
        first = 0;
        json_area(f, s, "      ", "hidden", c->hidden, 0);
        json_area(f, s, "      ", "partly_hidden", c->partly_hidden, 0);
        json_area(f, s, "      ", "still_visible", c->unchanged, 0);
        json_area(f, s, "      ", "bare_visible_not_a_viewpoint", c->not_viewpoint, 1);
        fputs("    }", f);
    }
    fputs(first ? "}\n}\n" : "\n  }\n}\n", f);
    return stream_status(f, "the summary", err);
}
