/* scene_file_site.c — the site section: the scene's CRS (given as EPSG:NNNN or WKT, or taken
 * from the DTM the terrain block names) and the map coordinates of the local origin (given, or
 * the DTM footprint's centre rounded to whole metres). It is read before every section that
 * gives positions, and opens the site frame they convert map coordinates with. Without a site
 * section the scene is in local metres only and nothing here runs. */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

#include <math.h>
#include <stdio.h>

#include "site/site_dtm.h"

/* The DTM the terrain's plugin block names with `dtm:`, as an absolute path, or NULL. */
static const ynode *dtm_node(const loader *L)
{
    const ynode *ter = ynode_get(L->root, "terrain");
    const ynode *dtm = ter && ter->kind == YNODE_MAPPING ? ynode_get(ter, "dtm") : NULL;
    return dtm && dtm->kind == YNODE_SCALAR && dtm->text[0] ? dtm : NULL;
}

/* The CRS text of the site when `crs:` is left out: the DTM's CRS, or the UTM zone of its centre
 * when it is geographic (said in an info line). */
static const char *crs_from_dtm(loader *L, const ynode *dtm, const char *path, const site_dtm *d)
{
    if (!d->crs_wkt) {
        sf_located(L->err, L->file, dtm->line, dtm->column,
                   "the site's CRS is taken from the DTM, but '%s' names no CRS; give site: crs: "
                   "EPSG:NNNN (or WKT)", path);
        return NULL;
    }
    if (!d->geographic) return d->crs_wkt;
    int epsg = site_utm_epsg(d->centre[0], d->centre[1]);
    if (!(L->flags & SCENE_FILE_QUIET))
        fprintf(stderr,
                "sylva: site: the DTM '%s' is in degrees (%s); the site CRS is the UTM zone of its "
                "centre (%.4f, %.4f): EPSG:%d (give site: crs: to choose another)\n",
                path, d->crs_name, d->centre[0], d->centre[1], epsg);
    const char *text = sf_arena_printf(L->a, "EPSG:%d", epsg);
    if (!text) sf_out_of_memory(L);
    return text;
}

/* The DTM footprint's centre in the site CRS, rounded to whole metres. */
static int origin_from_dtm(loader *L, const ynode *dtm, const char *path, const site_dtm *d,
                           double origin[3])
{
    double map[2] = {d->centre[0], d->centre[1]};
    err_buf why = {{0}};
    if (d->crs_wkt && site_frame_from_crs(L->site, d->crs_wkt, d->centre[0], d->centre[1], map, &why))
        return sf_located(L->err, L->file, dtm->line, dtm->column,
                          "the centre of the DTM '%s': %s; give site: origin: [E, N]", path, why.msg);
    origin[0] = round(map[0]), origin[1] = round(map[1]), origin[2] = 0.0;
    return 0;
}

/* The latitude of the site origin, which the terrain's biome and the ecology's sun path read. */
static int origin_latitude(loader *L, const ynode_pair *pr, site_settings *site)
{
    double lonlat[2];
    err_buf why = {{0}};
    if (site_frame_to_lonlat(L->site, site->origin[0], site->origin[1], lonlat, &why))
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "the site origin has no latitude: %s; give an origin inside the CRS's area",
                          err_sentence(&why));
    site->latitude_deg = lonlat[1];
    return 0;
}

static int read_site(loader *L, const ynode_pair *pr, site_dtm *d)
{
    const sylva_params *p;
    param_scope scope = {L->file, L->dir, "site", NULL, 0, pr->key_line, pr->key_column};
    if (params_validate(L->a, pr->value, host_schema_site.params, host_schema_site.n_params, &scope, &p,
                        L->err))
        return -1;
    const sylva_value *crs = sylva_param(p, "crs"), *origin = sylva_param(p, "origin");
    const ynode *dtm = dtm_node(L);
    const char *path = dtm ? param_resolve_path(L->a, L->dir, dtm->text) : NULL;
    if (dtm && !path) return sf_out_of_memory(L);
    if (!crs->is_set && !dtm)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "'site' gives no 'crs', and the terrain names no DTM file ('dtm:') to take "
                          "it from; give crs: EPSG:NNNN (a projected CRS in metres, such as the "
                          "site's UTM zone) or WKT");
    if (!origin->is_set && !dtm)
        return sf_located(L->err, L->file, pr->key_line, pr->key_column,
                          "'site' gives no 'origin', and the terrain names no DTM file ('dtm:') "
                          "whose centre it would be; give origin: [E, N] (map coordinates near the "
                          "middle of the scene)");
    if (dtm && (!crs->is_set || !origin->is_set)) {
        err_buf why = {{0}};
        if (site_dtm_read(path, d, &why))
            return why.status == ERR_NOMEM ? sf_out_of_memory(L)
                                           : sf_located(L->err, L->file, dtm->line, dtm->column, "%s", why.msg);
    }
    const char *text = crs->is_set ? crs->s : crs_from_dtm(L, dtm, path, d);
    if (!text) return -1;
    /* A geographic CRS given as the site's: its origin (or the DTM's centre) is longitude and
     * latitude, which names the UTM zone to suggest. */
    const double *near = origin->is_set ? origin->list : d->geographic ? d->centre : NULL;
    err_buf why = {{0}};
    if (!(L->site = site_frame_new(text, near, &why))) {
        if (why.status == ERR_NOMEM) return sf_out_of_memory(L);
        if (crs->is_set) return sf_located(L->err, L->file, crs->line, crs->column, "%s", why.msg);
        return sf_located(L->err, L->file, dtm->line, dtm->column,
                          "the site's CRS is taken from the DTM '%s': %s; or give site: crs:", path,
                          why.msg);
    }
    site_settings *site = &L->sf->site;
    site->crs_wkt = arena_strdup(L->a, site_frame_wkt(L->site));
    site->crs_name = arena_strdup(L->a, site_frame_name(L->site));
    if (!site->crs_wkt || !site->crs_name) return sf_out_of_memory(L);
    if (origin->is_set)
        for (uint32_t k = 0; k < origin->len; k++) site->origin[k] = origin->list[k];
    else if (origin_from_dtm(L, dtm, path, d, site->origin))
        return -1;
    return origin_latitude(L, pr, site);
}

int sf_read_site(loader *L)
{
    const ynode_pair *pr = ynode_get_pair(L->root, "site");
    if (!pr) return 0;
    site_dtm d = {0};
    int rc = read_site(L, pr, &d);
    site_dtm_release(&d);
    return rc;
}
