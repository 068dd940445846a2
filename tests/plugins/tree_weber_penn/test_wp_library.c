/* test_wp_library.c — the Weber–Penn species library (the files of scenes/species/weber_penn/)
 * through the real host: every file loads in a scene with an ecology (so its tree blocks
 * validate against tree_weber_penn's schema and its ecology blocks against the ecology's), every
 * woody species gives every ecology key in order (t_m < t_a <= t_f) and has a row in the
 * ecology's table of sources, and every species builds and grows, at its tallest variant, to
 * the model height that docs/species-library.md gives for it. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "work_dir.h"
#include "plugin/plugin_host.h"
#include "scene/scene.h"
#include "scene_build/scene_build.h"
#include "scene_file/scene_file.h"

#define LIBRARY WP_SOURCE_DIR "/scenes/species/weber_penn"
#define TABLE_DOC WP_SOURCE_DIR "/docs/species-library.md"
#define ECOLOGY_DOC WP_SOURCE_DIR "/docs/models/ecology.md"
#define MAX_FILES 32
#define DOC_BYTES (256 * 1024)

static char table_doc[DOC_BYTES], ecology_doc[DOC_BYTES];

/* The library's files, sorted by name; their count. */
static int library_files(char names[MAX_FILES][128])
{
    int n = 0;
    DIR *d = opendir(LIBRARY);
    CHECK(d != NULL);
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 6 || strcmp(e->d_name + len - 5, ".yaml") || n == MAX_FILES) continue;
        snprintf(names[n++], 128, "%s", e->d_name);
    }
    if (d) closedir(d);
    qsort(names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    return n;
}

/* The scene that includes library file `name` on a small flat site with an ecology of no years
 * (its plants are not the point: the section makes the species' ecology blocks valid). */
static const char *scene_of(const char *name)
{
    static char path[1400];
    char text[1024];
    snprintf(text, sizeof text,
             "terrain: {origin: [0, 0], spacing: [10, 10], grid: [[0, 0, 0], [0, 0, 0], [0, 0, 0]]}\n"
             "ecology: {plugin: ecology, years: 0, patches: 4}\n"
             "species:\n"
             "  include: [%s/%s]\n",
             LIBRARY, name);
    snprintf(path, sizeof path, "%s/%s", work_dir(), name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return path;
}

static plugin_registry *registry(void)
{
    err_buf err = {{0}};
    plugin_registry *reg = plugin_registry_open_path(SYLVA_PLUGIN_BUILD_DIR, &err);
    if (!reg) fprintf(stderr, "%s\n", err.msg);
    CHECK(reg != NULL);
    return reg;
}

static scene_file *load(plugin_registry *reg, const char *name)
{
    err_buf err = {{0}};
    scene_file *sf = scene_file_load_with(scene_of(name), reg, SCENE_FILE_NO_CAMERA | SCENE_FILE_QUIET, &err);
    if (!sf) fprintf(stderr, "%s: %s\n", name, err.msg);
    CHECK(sf != NULL);
    return sf;
}

/* The row of species `name` in a doc's table (the line that starts "| `name` |"), or NULL. */
static const char *table_row(const char *doc, const char *name)
{
    char key[160];
    snprintf(key, sizeof key, "\n| `%s` |", name);
    const char *row = strstr(doc, key);
    return row ? row + 1 : NULL;
}

/* Cell `col` (0 the first) of a table row, copied into out. */
static void table_cell(const char *row, int col, char *out, size_t n)
{
    const char *p = row + 1;
    for (int c = 0; c < col && p; c++) p = strchr(p, '|'), p = p ? p + 1 : NULL;
    const char *end = p ? strpbrk(p, "|\n") : NULL;
    size_t len = p && end ? (size_t)(end - p) : 0;
    if (len >= n) len = n - 1;
    memcpy(out, p ? p : "", len);
    out[len] = '\0';
}

/* The docs' column numbers in docs/species-library.md's table. */
enum { COL_FILE = 1, COL_MODEL_HEIGHT = 4, COL_ECOLOGY = 7 };

TEST(every_file_loads_with_its_ecology)
{
    char names[MAX_FILES][128];
    int n = library_files(names);
    CHECK(n >= 6);
    plugin_registry *reg = registry();
    if (!reg) return;
    CHECK(harness_read_text(TABLE_DOC, table_doc, sizeof table_doc));
    CHECK(harness_read_text(ECOLOGY_DOC, ecology_doc, sizeof ecology_doc));
    int n_species = 0, woody = 0;
    for (int i = 0; i < n; i++) {
        scene_file *sf = load(reg, names[i]);
        for (uint32_t k = 0; sf && k < sf->n_species; k++) {
            const species_spec *sp = &sf->species[k];
            const char *row = table_row(table_doc, sp->name);
            char file[128] = "", eco[64] = "";
            if (!row) fprintf(stderr, "%s: no row in docs/species-library.md\n", sp->name);
            CHECK(row != NULL);
            if (!row) continue;
            table_cell(row, COL_FILE, file, sizeof file);
            table_cell(row, COL_ECOLOGY, eco, sizeof eco);
            CHECK_STR_CONTAINS(file, names[i]);
            CHECK(sp->plugin && !strcmp(sp->plugin, "tree_weber_penn"));
            n_species++;
            /* A woody species gives every key, so that no value falls silently to a profile. */
            int given = 0, keys = 0;
            for (uint32_t j = 0; sp->ecology && j < sp->ecology->n; j++) {
                if (!strcmp(sp->ecology->spec[j].name, "profile")) continue;
                keys++;
                given += sp->ecology->values[j].is_set;
            }
            int wants = strstr(eco, "yes") != NULL;
            if (given != (wants ? keys : 0))
                fprintf(stderr, "%s: %d of %d ecology keys given; the table says '%s'\n", sp->name, given, keys, eco);
            CHECK_INT(given, wants ? keys : 0);
            if (!wants) continue;
            woody++;
            double t_m = sylva_param_real(sp->ecology, "t_m"), t_a = sylva_param_real(sp->ecology, "t_a"),
                   t_f = sylva_param_real(sp->ecology, "t_f");
            CHECK(t_m < t_a && t_a <= t_f);
            if (!table_row(ecology_doc, sp->name)) fprintf(stderr, "%s: no row in docs/models/ecology.md\n", sp->name);
            CHECK(table_row(ecology_doc, sp->name) != NULL);
        }
        scene_file_free(sf);
    }
    fprintf(stderr, "%d files, %d species, %d with ecology parameters\n", n, n_species, woody);
    CHECK(n_species >= 17);
    plugin_registry_free(reg);
}

/* "a–b" (an en dash or a hyphen between) into lo and hi; 1 when both were read. */
static int height_range(const char *cell, double *lo, double *hi)
{
    char *end;
    *lo = strtod(cell, &end);
    if (end == cell) return 0;
    while (*end == ' ' || *end == '-' || (unsigned char)*end >= 0x80) end++;
    const char *b = end;
    *hi = strtod(b, &end);
    return end != b;
}

TEST(species_grow_to_their_documented_heights)
{
    char names[MAX_FILES][128];
    int n = library_files(names);
    plugin_registry *reg = registry();
    if (!reg) return;
    CHECK(harness_read_text(TABLE_DOC, table_doc, sizeof table_doc));
    for (int i = 0; i < n; i++) {
        scene_file *sf = load(reg, names[i]);
        err_buf err = {{0}};
        build_options bo = {.quiet = 1, .no_ecology = 1, .threads = 2}; /* the species, not a forest */
        scene *s = sf ? scene_build(sf, reg, &bo, &err) : NULL;
        if (!s) fprintf(stderr, "%s: %s\n", names[i], err.msg);
        CHECK(s != NULL);
        for (uint32_t k = 0; s && k < s->n_species; k++) {
            const species *sp = &s->species[k];
            double tallest = 0;
            for (uint32_t v = 0; v < sp->n_variants; v++)
                if (s->prototypes[sp->first_prototype + v].height > tallest)
                    tallest = s->prototypes[sp->first_prototype + v].height;
            const char *row = table_row(table_doc, sp->name);
            char cell[64] = "";
            double lo = 0, hi = 0;
            if (row) table_cell(row, COL_MODEL_HEIGHT, cell, sizeof cell);
            CHECK(row && height_range(cell, &lo, &hi));
            int inside = tallest >= lo * 0.98 && tallest <= hi * 1.02;
            fprintf(stderr, "  %-20s %u variants, tallest %.2f m (documented %.2f-%.2f m)%s\n", sp->name,
                    sp->n_variants, tallest, lo, hi, inside ? "" : "  <- outside");
            CHECK(sp->n_variants == 4);
            CHECK(inside);
        }
        scene_free(s);
        scene_file_free(sf);
    }
    plugin_registry_free(reg);
}

TEST_LIST(TEST_CASE(every_file_loads_with_its_ecology), TEST_CASE(species_grow_to_their_documented_heights))
