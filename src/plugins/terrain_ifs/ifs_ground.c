/* ifs_ground.c — the ground rules and colours from the scene's keys and the biome (ifs_ground.h). */
#include "ifs_ground.h"

#include <math.h>
#include <stdio.h>

/* A height: the older fraction of the DTM's height range when given, else the altitude key when
 * given, else the biome's. */
static double height_key(plugin_params *p, const char *metres, const char *fraction, double zmin,
                         double zmax, double biome_z)
{
    if (plugin_param_given(p, fraction)) {
        double f = plugin_param_real(p, fraction);
        if (!(zmax > zmin)) return f > 0 ? INFINITY : zmin;
        return zmin + f * (zmax - zmin);
    }
    return plugin_param_given(p, metres) ? plugin_param_real(p, metres) : biome_z;
}

static void albedo_key(plugin_params *p, const char *name, const double biome[3], float out[3])
{
    const double *v = plugin_param_given(p, name) ? plugin_param(p, name)->list : biome;
    for (int k = 0; k < 3; k++) out[k] = (float)v[k];
}

static void copy3(double out[3], const double in[3])
{
    for (int k = 0; k < 3; k++) out[k] = in[k];
}

void ifs_ground_resolve(plugin_params *params, double latitude_deg, const ifs_cover_shares *cover,
                        double zmin, double zmax, ifs_ground *out)
{
    int64_t choice = plugin_param_int(params, "biome"); /* 0: auto, else the biome's index + 1 */
    out->biome_auto = choice == 0;
    out->biome = choice == 0 ? ifs_biome_choose(latitude_deg, cover) : (ifs_biome)(choice - 1);
    const ifs_biome_preset *b = ifs_biome_preset_of(out->biome);
    double snow_z, scree_z;
    ifs_biome_heights(out->biome, latitude_deg, &snow_z, &scree_z);
    ifs_surface_rules *r = &out->rules;
    r->snow_z = height_key(params, "snow_altitude", "snow_line", zmin, zmax, snow_z);
    /* scree left to the biome lies below a snow_altitude the scene lowers */
    if (plugin_param_given(params, "snow_altitude") && !plugin_param_given(params, "snow_line"))
        scree_z = fmin(scree_z, r->snow_z);
    r->scree_z = height_key(params, "scree_altitude", "scree_line", zmin, zmax, scree_z);
    r->scree_slope =
        plugin_param_given(params, "scree_slope") ? plugin_param_real(params, "scree_slope") : b->scree_slope;
    r->rock_slope = plugin_param_given(params, "rock_slope") ? plugin_param_real(params, "rock_slope") : b->rock_slope;
    r->dry_humidity = plugin_param_real(params, "dry_humidity");
    albedo_key(params, "grass_albedo", b->grass, out->albedo[IFS_SURFACE_GRASS]);
    albedo_key(params, "dry_grass_albedo", b->dry_grass, out->albedo[IFS_SURFACE_DRY_GRASS]);
    albedo_key(params, "scree_albedo", b->scree, out->albedo[IFS_SURFACE_SCREE]);
    albedo_key(params, "rock_albedo", b->rock, out->albedo[IFS_SURFACE_ROCK]);
    albedo_key(params, "snow_albedo", b->snow, out->albedo[IFS_SURFACE_SNOW]);
    copy3(out->palette.soil_albedo, b->soil);
    copy3(out->palette.wet_soil_albedo, b->wet_soil);
    copy3(out->palette.litter_albedo, b->litter);
    copy3(out->palette.moss_albedo, b->moss);
    copy3(out->palette.lichen_albedo, b->lichen);
}

void ifs_ground_describe(const ifs_ground *g, double latitude_deg, int by_cover, char *buf, unsigned size)
{
    const char *name = ifs_biome_preset_of(g->biome)->name;
    if (!g->biome_auto) snprintf(buf, size, "%s (given)", name);
    else if (by_cover) snprintf(buf, size, "%s (auto, from the land cover at latitude %.2f)", name, latitude_deg);
    else if (isfinite(latitude_deg)) snprintf(buf, size, "%s (auto, site latitude %.2f)", name, latitude_deg);
    else snprintf(buf, size, "%s (auto: the scene has no site)", name);
}
