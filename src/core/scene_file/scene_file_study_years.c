/* scene_file_study_years.c — study.years: the years since planting a study of a planting plan is
 * made at, each with its season ("1 winter, 15 summer"), so that `sylva study` gives the sheets a
 * planning assessment asks for: the planting just in, in winter, and established, in summer. */
#include "scene_file/scene_file_loader.h"

#include <stdlib.h>
#include <string.h>

#include "season/phenology.h"

static const char default_years[] = "1 winter, 15 summer";

/* One entry "N SEASON" (or "N": the scene's season) of text, len characters, into y. */
static int read_entry(loader *L, const sylva_value *v, const char *text, size_t len, study_year *y)
{
    char entry[128], *end;
    snprintf(entry, sizeof entry, "%.*s", (int)(len < sizeof entry ? len : sizeof entry - 1), text);
    y->years = strtod(entry, &end);
    if (end == entry || !(y->years >= 0 && y->years <= 10000))
        return sf_located(L->err, L->file, v->line, v->column, "'study.years': '%s' does not start with the years "
                          "since planting (0 to 10000); give entries like \"1 winter, 15 summer\"", entry);
    end += strspn(end, " \t");
    y->day = L->sf->season.day, y->season = L->sf->season.text;
    if (!*end) return 0;
    err_buf why = {{0}};
    if (season_day_parse(end, &y->day, &why))
        return sf_located(L->err, L->file, v->line, v->column, "'study.years': '%s': %s", entry, why.msg);
    y->season = sf_arena_printf(L->a, "%s", end);
    return y->season ? 0 : sf_out_of_memory(L);
}

int sf_read_study_years(loader *L, const sylva_value *v)
{
    study_settings *st = &L->sf->study;
    if (v->is_set && !L->sf->planting.n_features)
        return sf_located(L->err, L->file, v->line, v->column, "'study.years' makes the study at years since "
                          "planting, and the scene has no 'planting:' section");
    if (!L->sf->planting.n_features) return 0;
    const char *text = v->is_set ? v->s : default_years;
    if (!(st->years = arena_alloc(L->a, STUDY_MAX_YEARS * sizeof *st->years))) return sf_out_of_memory(L);
    for (const char *p = text; *p;) {
        p += strspn(p, " ,\t");
        size_t len = strcspn(p, ",");
        if (!len) break;
        if (st->n_years == STUDY_MAX_YEARS)
            return sf_located(L->err, L->file, v->line, v->column, "'study.years' gives more than %u years",
                              STUDY_MAX_YEARS);
        if (read_entry(L, v, p, len, &st->years[st->n_years++])) return -1;
        p += len;
    }
    if (!st->n_years)
        return sf_located(L->err, L->file, v->line, v->column, "'study.years' names no year; give entries like "
                          "\"1 winter, 15 summer\"");
    return 0;
}
