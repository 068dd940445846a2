/* scene_file_season.c — the scene's season: key (a season's name or a date) and each species'
 * phenology: block with its blossom: block, read into days of the year (phenology.h). */
#include "scene_file/scene_file.h"
#include "scene_file/scene_file_loader.h"

int sf_read_season(loader *L)
{
    season_settings *s = &L->sf->season;
    s->day = SEASON_SUMMER_DAY, s->text = "summer";
    const ynode_pair *pr = ynode_get_pair(L->root, "season");
    if (!pr) return 0;
    const ynode *v = pr->value;
    if (v->kind != YNODE_SCALAR)
        return sf_located(L->err, L->file, v->line, v->column,
                          "'season' must be spring, summer, autumn, winter or a date YYYY-MM-DD, got %s",
                          ynode_kind_phrase(v));
    err_buf why = {{0}};
    if (season_day_parse(v->text, &s->day, &why))
        return sf_located(L->err, L->file, v->line, v->column, "%s", why.msg);
    s->text = v->text, s->line = v->line, s->column = v->column;
    return 0;
}

int scene_file_use_season(scene_file *sf, const char *text, err_buf *err)
{
    uint32_t day;
    err_buf why = {{0}};
    if (season_day_parse(text, &day, &why)) return err_fail(err, ERR_USAGE, "--season %s: %s", text, why.msg);
    const char *copy = arena_strdup(sf->arena, text);
    if (!copy) return err_fail(err, ERR_NOMEM, "out of memory");
    sf->season = (season_settings){.day = day, .text = copy};
    return 0;
}

/* The blossom: block v (defaults when not given: no blossom). Its ranges are the schema's. */
static void sf_read_blossom(const char *file, const sylva_value *v, struct flowering *out)
{
    const sylva_params *p = v->group;
    out->given = v->is_set;
    out->first = (uint32_t)sylva_param(p, "first_day")->i, out->last = (uint32_t)sylva_param(p, "last_day")->i;
    const sylva_value *open = sylva_param(p, "color"), *faded = sylva_param(p, "faded_color");
    for (int c = 0; c < 3; c++) out->color[c] = open->list[c], out->faded_color[c] = faded->list[c];
    out->size = sylva_param(p, "size")->r, out->per_point = sylva_param(p, "per_point")->r;
    out->max_per_plant = (uint32_t)sylva_param(p, "max_per_plant")->i;
    out->file = file, out->line = v->line, out->column = v->column;
}

int sf_read_phenology(loader *L, const char *file, const char *species, const sylva_value *v, phenology *out)
{
    const sylva_params *p = v->group;
    const sylva_value *out_day = sylva_param(p, "leaf_out"), *fall_day = sylva_param(p, "leaf_fall"),
                      *turn_day = sylva_param(p, "colouring"), *colour = sylva_param(p, "autumn_color");
    out->habit = (leaf_habit)sylva_param(p, "habit")->i;
    out->leaf_out = (uint32_t)out_day->i, out->leaf_fall = (uint32_t)fall_day->i;
    out->colouring = (uint32_t)turn_day->i;
    for (int c = 0; c < 3; c++) out->autumn_color[c] = colour->list[c];
    if (out->habit == HABIT_DECIDUOUS && out->leaf_out == out->leaf_fall)
        return sf_located(L->err, file, fall_day->is_set ? fall_day->line : v->line,
                          fall_day->is_set ? fall_day->column : v->column,
                          "species '%s': leaf_fall (day %u) equals leaf_out; a deciduous species needs "
                          "some days in leaf (an evergreen: habit: evergreen)", species, out->leaf_fall);
    const sylva_value *fresh = sylva_param(p, "fresh_color"), *fresh_days = sylva_param(p, "fresh_days");
    for (int c = 0; c < 3; c++) out->fresh_color[c] = fresh->list[c];
    out->fresh_days = (uint32_t)fresh_days->i;
    sf_read_blossom(file, sylva_param(p, "blossom"), &out->blossom);
    if (out->habit == HABIT_EVERGREEN) {
        const sylva_value *given[] = {out_day, fall_day, turn_day, colour, fresh, fresh_days};
        for (int k = 0; k < 6; k++)
            if (given[k]->is_set)
                return sf_located(L->err, file, given[k]->line, given[k]->column,
                                  "species '%s': leaf days and autumn_color apply to habit: deciduous, as "
                                  "do fresh_color and fresh_days; an evergreen is in leaf all year", species);
        return 0;
    }
    if (!phenology_in_leaf(out, out->colouring))
        return sf_located(L->err, file, turn_day->is_set ? turn_day->line : v->line,
                          turn_day->is_set ? turn_day->column : v->column,
                          "species '%s': colouring (day %u) must fall while the species is in leaf, from "
                          "leaf_out (day %u) to the day before leaf_fall (day %u)", species, out->colouring,
                          out->leaf_out, out->leaf_fall);
    return 0;
}
