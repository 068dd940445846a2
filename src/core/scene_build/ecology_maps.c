/* ecology_maps.c — factor maps and plant maps on a raster canvas. */
#include "scene_build/ecology_maps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/raster_canvas.h"
#include "scene/heightfield.h"

static void factor_color(const char *name, uint8_t rgb[3])
{
    static const struct {
        const char *name;
        uint8_t rgb[3];
    } colors[] = {{"humidity", {40, 200, 60}},  {"windiness", {240, 220, 40}}, {"sunniness", {230, 50, 30}},
                  {"altitude", {230, 200, 150}}, {"water", {40, 110, 230}}};
    memcpy(rgb, (const uint8_t[3]){220, 220, 220}, 3);
    for (size_t i = 0; i < sizeof colors / sizeof colors[0]; i++)
        if (name && !strcmp(name, colors[i].name)) memcpy(rgb, colors[i].rgb, 3);
}

int factor_map_write(const char *path, const sylva_ecology_factor_map *map, err_buf *err)
{
    uint32_t longer = map->nx > map->ny ? map->nx : map->ny;
    uint32_t s = longer >= 512 ? 1 : (512 + longer - 1) / longer;
    if ((uint64_t)map->nx * s > 16384 || (uint64_t)map->ny * s > 16384)
        return err_set(err, "%s: a factor map of %u x %u patches is too large for an image", path, map->nx, map->ny);
    static const uint8_t dark[3] = {15, 15, 15};
    uint8_t full[3];
    factor_color(map->name, full);
    canvas c;
    if (canvas_init(&c, map->nx * s, map->ny * s, dark, err)) return -1;
    for (uint32_t k = 0; k < map->ny; k++)
        for (uint32_t i = 0; i < map->nx; i++) {
            double v = map->values[(size_t)k * map->nx + i];
            v = v < 0 ? 0 : v > 1 ? 1 : v;
            uint8_t col[3];
            for (int q = 0; q < 3; q++) col[q] = (uint8_t)lround(dark[q] + v * (full[q] - dark[q]));
            int y0 = (int)((map->ny - 1 - k) * s); /* north up */
            canvas_rect(&c, (int)(i * s), y0, (int)((i + 1) * s) - 1, y0 + (int)s - 1, col);
        }
    int rc = canvas_write_png(&c, path, err);
    canvas_free(&c);
    return rc;
}

typedef struct plant_order {
    double r;
    uint32_t i;
} plant_order;

static int larger_first(const void *a, const void *b)
{
    const plant_order *x = a, *y = b;
    if (x->r != y->r) return x->r > y->r ? -1 : 1;
    return x->i < y->i ? -1 : x->i > y->i;
}

/* 1 when (x, y) falls on a water patch of the map. */
static int on_water_patch(const sylva_ecology_factor_map *w, double x, double y)
{
    if (!w || !w->values || !(w->dx > 0) || !(w->dy > 0)) return 0;
    double gi = (x - w->x0) / w->dx, gk = (y - w->y0) / w->dy;
    if (!(gi >= 0 && gk >= 0 && gi < w->nx && gk < w->ny)) return 0;
    return w->values[(size_t)gk * w->nx + (size_t)gi] >= 0.5f;
}

int plant_map_write(const char *path, const sylva_heightfield *t, const sylva_ecology_factor_map *water,
                    const sylva_ecology_plant_record *plants, uint32_t n_plants, const char *const *names,
                    uint32_t n_species, uint32_t year, err_buf *err)
{
    double lx = (t->nx - 1) * t->dx, ly = (t->ny - 1) * t->dy;
    double scale = 800.0 / (lx > ly ? lx : ly); /* pixels per metre */
    uint32_t w = (uint32_t)fmax(1, lround(lx * scale)), h = (uint32_t)fmax(1, lround(ly * scale));
    static const uint8_t black[3] = {0, 0, 0}, ink[3] = {255, 255, 255};
    canvas c;
    if (canvas_init(&c, w, h, black, err)) return -1;
    double zlo = t->z[0], zhi = t->z[0];
    for (size_t q = 1; q < (size_t)t->nx * t->ny; q++) zlo = fmin(zlo, t->z[q]), zhi = fmax(zhi, t->z[q]);
    double span = zhi > zlo ? zhi - zlo : 1, e = 1.0 / scale;
    for (uint32_t py = 0; py < h; py++)
        for (uint32_t px = 0; px < w; px++) {
            double x = t->x0 + (px + 0.5) / scale, y = t->y0 + ly - (py + 0.5) / scale;
            double z = heightfield_height_clamped(t, x, y), a = (z - zlo) / span;
            double gx = (heightfield_height_clamped(t, x + e, y) - heightfield_height_clamped(t, x - e, y)) / (2 * e);
            double gy = (heightfield_height_clamped(t, x, y + e) - heightfield_height_clamped(t, x, y - e)) / (2 * e);
            double shade = 0.75 + 0.25 * (-gx + gy) / sqrt(1 + gx * gx + gy * gy); /* light from the north-west */
            uint8_t col[3];
            if ((t->has_water && z < t->water_level) || on_water_patch(water, x, y)) {
                col[0] = 40, col[1] = 80, col[2] = 160;
            } else {
                double base[3] = {95 + 90 * a, 105 + 80 * a, 75 + 85 * a};
                for (int q = 0; q < 3; q++) col[q] = (uint8_t)fmin(255, fmax(0, base[q] * shade));
            }
            memcpy(c.rgb + 3 * ((size_t)py * w + px), col, 3);
        }
    plant_order *order = malloc((n_plants ? n_plants : 1) * sizeof *order);
    uint32_t *count = calloc(n_species ? n_species : 1, sizeof *count);
    if (!order || !count) {
        free(order), free(count), canvas_free(&c);
        return err_nomem(err, "out of memory for the map of %u plants", n_plants);
    }
    for (uint32_t i = 0; i < n_plants; i++) order[i] = (plant_order){plants[i].radius, i};
    qsort(order, n_plants, sizeof *order, larger_first);
    for (uint32_t q = 0; q < n_plants; q++) {
        const sylva_ecology_plant_record *p = &plants[order[q].i];
        uint8_t col[3];
        canvas_series_color(p->species, col);
        if (p->species < n_species) count[p->species]++;
        double px = (p->position[0] - t->x0) * scale, py = (ly - (p->position[1] - t->y0)) * scale;
        canvas_disc(&c, px, py, fmax(p->radius * scale, 1.0), col);
    }
    char label[128];
    snprintf(label, sizeof label, "year %u", year);
    canvas_rect(&c, 4, 4, 12 + canvas_text_width(label, 2), 20, black);
    canvas_text(&c, 8, 6, label, 2, ink);
    for (uint32_t s = 0; s < n_species; s++) {
        uint8_t col[3];
        canvas_series_color(s, col);
        snprintf(label, sizeof label, "%s %u", names[s] ? names[s] : "?", count[s]);
        int y = 28 + 14 * (int)s;
        canvas_rect(&c, 4, y - 2, 26 + canvas_text_width(label, 1), y + 9, black);
        canvas_rect(&c, 8, y, 15, y + 7, col);
        canvas_text(&c, 20, y, label, 1, ink);
    }
    free(order), free(count);
    int rc = canvas_write_png(&c, path, err);
    canvas_free(&c);
    return rc;
}
