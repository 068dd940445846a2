/* test_wp_species.c — the Weber-Penn species reader: every Arbaro, shamanDevel and Helios species
 * of the shared data loads with the files' values; malformed XML, unknown names and values out
 * of range are refused at their exact line and column. */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "wp_species_read.h"

/* Reads `text` as file "t.xml", expects refusal with a message containing the needles. */
static void expect_refused(const char *text, const char *needle1, const char *needle2)
{
    wp_species_list l;
    plugin_err err = { 0 };
    int rc = wp_species_read_buffer("t.xml", text, strlen(text), &l, &err);
    if (rc == 0) fprintf(stderr, "accepted:\n%s\n", text);
    else fprintf(stderr, "refused: %s\n", err.msg);
    CHECK(rc < 0);
    CHECK_STR_CONTAINS(err.msg, needle1);
    if (needle2) CHECK_STR_CONTAINS(err.msg, needle2);
    CHECK(l.count == 0 && l.items == NULL);
}

/* Reads `text`, expecting success; the caller frees *l. */
static void expect_read(const char *text, wp_species_list *l)
{
    plugin_err err = { 0 };
    int rc = wp_species_read_buffer("t.xml", text, strlen(text), l, &err);
    if (rc) fprintf(stderr, "refused: %s\n", err.msg);
    CHECK_INT(rc, 0);
}

/* Loads every .xml of the shared folder `sub`; returns how many. */
static int load_folder(const char *sub)
{
    const char *dir = harness_shared_data(sub);
    if (!dir) return -1;
    char path[4096];
    snprintf(path, sizeof path, "%s", dir);
    DIR *d = opendir(path);
    CHECK(d != NULL);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t k = strlen(e->d_name);
        if (k < 5 || strcmp(e->d_name + k - 4, ".xml") != 0) continue;
        char file[8192];
        snprintf(file, sizeof file, "%s/%s", path, e->d_name);
        wp_species_list l;
        plugin_err err = { 0 };
        int rc = wp_species_read_file(file, &l, &err);
        if (rc) fprintf(stderr, "%s\n", err.msg);
        CHECK_INT(rc, 0);
        CHECK(rc || l.count == 1);
        wp_species_list_free(&l);
        n++;
    }
    if (d) closedir(d);
    return n;
}

TEST(arbaro_files_load)
{
    int a = load_folder("weber-penn/arbaro"), t = load_folder("weber-penn/arbaro/test"),
        s = load_folder("weber-penn/arbaro-shamanDevel");
    if (a < 0 || s < 0) SKIP("no ../shared/data/weber-penn");
    printf("arbaro: %d files, arbaro/test: %d, arbaro-shamanDevel: %d, all loaded\n", a, t, s);
    CHECK_INT(a, 16);
    CHECK_INT(s, 26);
}

/* The species `name` of the shared file `sub`, read into *l (freed by the caller), or NULL. */
static const wp_params *shared_species(const char *sub, const char *name, wp_species_list *l)
{
    const char *path = harness_shared_data(sub);
    if (!path) return NULL;
    plugin_err err = { 0 };
    int rc = wp_species_read_file(path, l, &err);
    if (rc) fprintf(stderr, "%s\n", err.msg);
    CHECK_INT(rc, 0);
    const wp_params *p = wp_species_find(l, name);
    CHECK(p != NULL);
    return p;
}

TEST(helios_library_loads)
{
    wp_species_list l;
    if (!shared_species("weber-penn/helios/WeberPennTreeLibrary.xml", "Almond", &l)) SKIP("no ../shared/data/weber-penn");
    printf("helios: %zu species:", l.count);
    for (size_t i = 0; i < l.count; i++) printf(" %s", l.items[i].species);
    printf("\nhelios fields noted and not used: %s\n", l.ignored);
    CHECK_INT((int)l.count, 9);
    CHECK(wp_species_find(&l, "Walnut") != NULL);
    CHECK_STR_CONTAINS(l.ignored, "LeafFile");
    CHECK_STR_CONTAINS(l.ignored, "WoodFile");
    wp_species_list_free(&l);
}

TEST(values_match_files)
{
    wp_species_list l;
    const wp_params *p = shared_species("weber-penn/arbaro/ca_black_oak.xml", "ca_black_oak", &l);
    if (!p) SKIP("no ../shared/data/weber-penn");
    CHECK_INT(p->levels, 3);
    CHECK_INT(p->base_splits, 2);
    CHECK_INT(p->shape, 2);
    CHECK_NEAR(p->ratio, 0.018, 1e-12);
    CHECK_NEAR(p->attraction_up, 0.8, 1e-12);
    CHECK_INT(p->lobes, 5);
    wp_species_list_free(&l);
    p = shared_species("weber-penn/helios/WeberPennTreeLibrary.xml", "Almond", &l);
    if (!p) SKIP("no ../shared/data/weber-penn/helios");
    CHECK_INT(p->shape, 6);
    CHECK_INT(p->base_splits, 3);
    CHECK_NEAR(p->base_split_size, 0.2, 1e-12);
    CHECK_NEAR(p->level[1].length, 0.65, 1e-12);
    CHECK_NEAR(p->level[3].length, 0.3, 1e-12);
    CHECK_NEAR(p->level[0].curve, -85, 1e-12);
    CHECK_INT(p->level[0].curve_res, 8);
    CHECK_INT(p->level[1].branches, 34);
    CHECK_NEAR(p->level[1].branch_dist, 1, 0); /* not in Helios: Arbaro's default */
    wp_species_list_free(&l);
    p = shared_species("weber-penn/arbaro-shamanDevel/oak_1.xml", "black_tupelo", &l);
    if (!p) SKIP("no ../shared/data/weber-penn/arbaro-shamanDevel");
    CHECK_INT(p->levels, 4);
    CHECK_STR_CONTAINS(p->bark_texture, ".jpg");
    wp_species_list_free(&l);
}

TEST(defaults_from_table)
{
    wp_params p;
    wp_params_defaults(&p);
    CHECK_INT(p.levels, 3);
    CHECK_NEAR(p.scale, 10, 0);
    CHECK_NEAR(p.level[0].length, 1, 0);
    CHECK_NEAR(p.level[1].down_angle, 30, 0);
    CHECK_INT(p.level[2].curve_res, 1);
    CHECK_INT(p.level[1].branches, 10);
    CHECK(strcmp(p.species, "default") == 0 && strcmp(p.leaf_shape, "0") == 0);
    wp_species_list l;
    expect_read("<?xml version=1.0?>\n<arbaro><species name='x'><param name=\"1Length\" value='0.3'/></species></arbaro>", &l);
    CHECK_NEAR(l.items[0].level[1].length, 0.3, 0);
    CHECK_NEAR(l.items[0].level[2].length, 0.5, 0);
    wp_species_list_free(&l);
}

TEST(malformed_xml_refused)
{
    expect_refused("<arbaro>\n  <species name='a'>\n    <param name='Shape' value='2'>\n  </species>\n</arbaro>\n",
                   "t.xml:4:3: end tag </species> does not match <param> at line 3 column 5", "write </param>");
    expect_refused("<arbaro>\n <species name='a\n", "t.xml:2:17: attribute value not closed", NULL);
    expect_refused("<arbaro><species name=a/></arbaro>", "t.xml:1:23: attribute value must be quoted", NULL);
    expect_refused("<?xml version='1.0'\n<arbaro/>", "t.xml:1:1: the '<?xml' declaration is not closed", NULL);
    expect_refused("<arbaro>\n<!-- open\n", "t.xml:2:1: comment not closed", NULL);
    expect_refused("<arbaro></arbaro>\n<x/>", "t.xml:2:1: text after the root element", NULL);
    expect_refused("<helios><WeberPennTree label='A'><Shape>1 &nbsp;</Shape></WeberPennTree></helios>",
                   "t.xml:1:43: unknown entity", NULL);
    expect_refused("<arbaro><species name='a\nb&x;'/></arbaro>", "t.xml:2:2: unknown entity", NULL);
    expect_refused("<arbaro><species name='a' name='b'/></arbaro>", "t.xml:1:27: attribute 'name' given twice", NULL);
    char deep[400] = "";
    for (int i = 0; i < 40; i++) strcat(deep, "<a>");
    expect_refused(deep, "nested deeper than 32", NULL);
    expect_refused("", "t.xml:1:1: expected the root element", NULL);
}

TEST(out_of_range_refused)
{
    expect_refused("<arbaro>\n<species name='a'>\n  <param name='Shape' value='9'/>\n</species></arbaro>",
                   "t.xml:3:30: 'Shape' must be an integer in [0, 8], got 9", NULL);
    expect_refused("<arbaro><species name='a'>\n<param name='2Taper' value='3.5'/></species></arbaro>",
                   "t.xml:2:29: '2Taper' must be a number in [0, 2.99999999], got 3.5", NULL);
    expect_refused("<arbaro><species name='a'>\n<param name='Levels' value='2.5'/></species></arbaro>",
                   "t.xml:2:29: 'Levels' must be an integer in [0, 9], got '2.5'", NULL);
    expect_refused("<helios>\n<WeberPennTree label='A'>\n  <nLength>1 0.5\n  -2 0.3</nLength>\n</WeberPennTree></helios>",
                   "t.xml:4:3: 'nLength' must be a number in [1e-07, inf) at level 2, got -2", NULL);
    expect_refused("<helios><WeberPennTree label='A'>\n<nRotate>1 2 3</nRotate></WeberPennTree></helios>",
                   "t.xml:2:10: <nRotate> takes 4 values, one per level 0 to 3, got 3", NULL);
    expect_refused("<helios><WeberPennTree label='A'>\n<Scale> </Scale></WeberPennTree></helios>",
                   "<Scale> takes 1 value, got 0", NULL);
}

TEST(unknown_parameter_refused)
{
    expect_refused("<arbaro><species name='a'>\n  <param name='1Lenght' value='1'/></species></arbaro>",
                   "t.xml:2:16: unknown parameter '1Lenght'; did you mean '1Length'?", NULL);
    expect_refused("<arbaro><species name='a'>\n  <param name='4Length' value='1'/></species></arbaro>",
                   "t.xml:2:16: unknown parameter '4Length'", NULL);
    expect_refused("<helios><WeberPennTree label='A'>\n  <nCurveVV>0 0 0 0</nCurveVV></WeberPennTree></helios>",
                   "t.xml:2:3: unknown parameter 'nCurveVV'; did you mean 'nCurveV'?", NULL);
    expect_refused("<arbaro><species name='a'>\n<param name='Shape' value='1'/>\n<param name='Shape' value='1'/></species></arbaro>",
                   "t.xml:3:14: 'Shape' given twice", NULL);
    expect_refused("<tree/>", "t.xml:1:1: root element <tree>", NULL);
    expect_refused("<arbaro><species name='a'><param name='Species' value='b'/></species></arbaro>",
                   "t.xml:1:40: 'Species' given twice", NULL);
}

TEST(helios_own_fields_noted)
{
    wp_species_list l;
    expect_read("<?xml version=1.0?>\n<helios><WeberPennTree label=\"A\"><LeafFile> a.png </LeafFile>"
                "<BaseSplits> 2 </BaseSplits><nTaper>1 1.5 2 2.5</nTaper></WeberPennTree>"
                "<WeberPennTree label=\"B\"/></helios>",
                &l);
    CHECK_INT((int)l.count, 2);
    CHECK(strcmp(l.ignored, "LeafFile") == 0);
    CHECK_INT(l.items[0].base_splits, 2);
    CHECK_NEAR(l.items[0].level[3].taper, 2.5, 0);
    wp_species_list_free(&l);
}

/* Helios writes zeros for the levels a tree does not grow: checked only where Arbaro reads them. */
TEST(helios_unused_levels)
{
    wp_species_list l;
    expect_read("<helios><WeberPennTree label='A'><Levels>2</Levels>\n<nCurveRes>5 5 0 0</nCurveRes>"
                "<nRotate>0 140 140 0</nRotate></WeberPennTree></helios>",
                &l);
    CHECK_INT(l.items[0].level[2].curve_res, 0);
    wp_species_list_free(&l);
    expect_refused("<helios><WeberPennTree label='A'>\n<nCurveRes>5 5 0 0</nCurveRes>\n<Levels>3</Levels></WeberPennTree></helios>",
                   "t.xml:2:16: 'nCurveRes' must be an integer in [1, 2147483647] at level 2, got 0", NULL);
}

/* docs/models/tree_weber_penn.md lists every row of the table, with its range. */
TEST(doc_lists_every_parameter)
{
    static char doc[1 << 16];
    int found = harness_read_text(WP_DOC_PATH, doc, sizeof doc);
    CHECK(found);
    if (!found) return;
    for (size_t i = 0; i < wp_param_count; i++) {
        char row[96];
        snprintf(row, sizeof row, "| `%s` |", wp_param_table[i].name);
        CHECK_STR_CONTAINS(doc, row);
    }
    CHECK_STR_CONTAINS(doc, "| `nTaper` | radius taper: 0-1 cone, 1-2 spherical, 2-3 periodic | number [0, 2.99999999] | 1 / 1 / 1 / 1 |");
}

TEST_LIST(TEST_CASE(doc_lists_every_parameter), TEST_CASE(helios_unused_levels), TEST_CASE(arbaro_files_load), TEST_CASE(helios_library_loads), TEST_CASE(values_match_files),
          TEST_CASE(defaults_from_table), TEST_CASE(malformed_xml_refused), TEST_CASE(out_of_range_refused),
          TEST_CASE(unknown_parameter_refused), TEST_CASE(helios_own_fields_noted))
