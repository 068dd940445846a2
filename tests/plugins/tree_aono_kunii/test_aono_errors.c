/* test_aono_errors.c — bad input to tree_aono_kunii gives one clear sentence at the right place:
 * the schema's checks (negative or absurd levels, ratios of 1 or more) and create()'s and
 * generate()'s own (segment limits, ratios from dimensions, controllers on tips, angle laws,
 * pattern and list lengths, settings that would not be read). */
#include <math.h>
#include <string.h>

#include "aono_fixture.h"
#include "harness.h"

/* Opens a fixture on `yaml`, expects failure with `status` (-1: the schema) and a message
 * containing each of the needles. */
static void expect_refused(const char *yaml, int status, const char *needle1, const char *needle2)
{
    aono_fixture fx;
    int rc = aono_fixture_open(&fx, yaml, 1);
    if (rc != status) fprintf(stderr, "for:\n%sgot status %d (%s)\n", yaml, rc, fx.err.msg);
    CHECK_INT(rc, status);
    CHECK_STR_CONTAINS(fx.err.msg, needle1);
    if (needle2) CHECK_STR_CONTAINS(fx.err.msg, needle2);
    CHECK(fx.state == NULL);
    aono_fixture_close(&fx);
}

TEST(levels_negative_and_absurd)
{
    expect_refused("levels: -3\n", -1, "test.yaml:1:9", "'levels' must be an integer in [1, 30], got -3");
    expect_refused("levels: 1000\n", -1, "'levels' must be an integer in [1, 30]", "got 1000");
    expect_refused("levels: 2.5\n", -1, "'levels'", "integer");
    /* within the schema's range but too many segments for the pattern */
    expect_refused("levels: 25\npattern: dichotomous\nfi: [20, 30]\n", SYLVA_ERR_PARAM, "test.yaml:1:9: 'levels'",
                   "use at most 19 levels with this pattern");
    expect_refused("levels: 14\npattern: ternary\nfi: [20, 30, 0]\nri: [0.5, 0.5, 0.8]\n", SYLVA_ERR_PARAM,
                   "up to 7174453 segments", "at most 12 levels");
}

TEST(ratios_of_one_or_more)
{
    expect_refused("ri: [0.9, 1.2]\n", -1, "'ri'", "(0, 1)");
    expect_refused("ri: [1, 0.8]\n", -1, "'ri'", "(0, 1)");
    expect_refused("ri_method: random\nri_range: [0.5, 1]\n", -1, "'ri_range'", "(0, 1)");
    expect_refused("ri_method: random\nri_range: [0.8, 0.5]\n", SYLVA_ERR_PARAM, "'ri_range'", "is empty");
    /* (23): H0 >= H gives R1 <= 0 */
    expect_refused("ri_method: dimensions\nheight: 10\ntrunk_length: 12\n", SYLVA_ERR_PARAM, "'trunk_length'",
                   "below the height H = 10 m");
    /* (24): L = 30, h = 16, R1 = 0.8 gives R2 = 1.5 */
    expect_refused("ri_method: dimensions\nheight: 20\ntrunk_length: 4\ncrown_diameter: 30\n", SYLVA_ERR_PARAM,
                   "'crown_diameter'", "R2 = (L/h) R1 = (30 / 16) x 0.8 = 1.5");
}

/* The monopodial leader (child 1, φ = 0) of a trunk of 5 m with RI(1) = 0.9 ends at (0, 0, 9.5). */
TEST(controller_on_a_tip)
{
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx,
                                "levels: 3\ntrunk_length: 5\nfi: [0, 45]\nri: [0.9, 0.8]\n"
                                "controllers:\n  - {position: [30, 0, 0], fac: 1}\n  - {position: [0, 0, 9.5], fac: -2}\n",
                                1),
              0);
    mesh *m = NULL;
    CHECK_INT(aono_fixture_generate(&fx, 1.0, &m, NULL), SYLVA_ERR_PARAM);
    CHECK_STR_CONTAINS(fx.err.msg, "test.yaml:7:16: 'position': controller 2 at (0, 0, 9.5)");
    CHECK_STR_CONTAINS(fx.err.msg, "lies on the tip of a level-1 branch");
    mesh_free(m);
    aono_fixture_close(&fx);
    expect_refused("controllers: [{position: [1, 2, 3], fac: 0}]\n", SYLVA_ERR_PARAM, "'fac'", "fac > 0");
    expect_refused("controllers: [{position: [1, 2, 3]}]\n", -1, "fac", "missing");
}

TEST(pattern_and_angles)
{
    expect_refused("pattern: ternary\n", SYLVA_ERR_PARAM, "'fi'", "pattern ternary has 3 children, so fi needs 3");
    expect_refused("pattern: ternary\nfi: [30, 30, 0]\n", SYLVA_ERR_PARAM, "'ri'", "ri needs 3 ratios");
    expect_refused("fi: [10, 45]\n", SYLVA_ERR_PARAM, "'fi'", "FI(1) must be the constant 0");
    expect_refused("fi: [0, 200]\n", -1, "'fi'", "[0, 180]");
    expect_refused("fi_laws: [{child: 2, law: linear, points: [[1, 40], [2, 30], [3, 20]]}]\n", SYLVA_ERR_PARAM,
                   "'points'", "exactly two points");
    expect_refused("fi_laws: [{child: 1, law: exponential, points: [[0, 40], [4, 20]]}]\n", SYLVA_ERR_PARAM,
                   "'fi_laws'", "must be the constant 0");
    expect_refused("pattern: dichotomous\nfi: [20, 30]\nfi_laws: [{child: 3, law: quadratic, points: [[1, 40], [2, 30], [3, 25]]}]\n",
                   SYLVA_ERR_PARAM, "'child'", "children 1 to 2, not 3");
    expect_refused("pattern: dichotomous\nfi: [20, 30]\nfi_laws: [{child: 2, law: quadratic, points: [[1, 40], [1, 30], [2, 25]]}]\n",
                   SYLVA_ERR_PARAM, "'points'", "three different levels");
    expect_refused("pattern: monopodal\n", -1, "'pattern'", "did you mean 'monopodial'");
}

TEST(settings_that_would_not_be_read)
{
    expect_refused("pattern: dichotomous\nfi: [20, 30]\nlvt: 2\n", SYLVA_ERR_PARAM, "'lvt'", "unless pattern is monopodial");
    expect_refused("ri_method: random\nri: [0.5, 0.6]\n", SYLVA_ERR_PARAM, "'ri'", "unless ri_method is constant");
    expect_refused("crown_diameter: 9\n", SYLVA_ERR_PARAM, "'crown_diameter'", "unless ri_method is dimensions");
    expect_refused("leaf: maple\n", SYLVA_ERR_PARAM, "'leaf'", "when leaf_count is 0");
    expect_refused("sides: 6\nmin_sides: 8\n", SYLVA_ERR_PARAM, "'min_sides'", "min_sides <= sides");
    expect_refused("leaf_count: 3\nleaf_color: [0.6, 0.5, 0.4]\nleaf_transmittance: [0.5, 0.4, 0.3]\n", SYLVA_ERR_PARAM,
                   "'leaf_transmittance'", "at most 1");
    expect_refused("levels: 12\npattern: dichotomous\nfi: [20, 30]\nleaf_count: 1000\nleaf_levels: 3\n", SYLVA_ERR_PARAM,
                   "'leaf_count'", "lower leaf_count");
    expect_refused("leves: 3\n", -1, "unknown key 'leves'", "did you mean 'levels'");
}

/* The leaf and bark keys: a preset's name or user maps, a bark preset and its angle; each kind
 * of bad value is refused at its place in the file. */
TEST(leaf_and_bark_keys)
{
    expect_refused("leaf_count: 3\nleaf: oak\n", SYLVA_ERR_PARAM, "test.yaml:2:7: 'leaf'",
                   "'oak' is not a leaf; give a preset (beech, maple, spruce, shrub, willow) or affine maps");
    expect_refused("leaf_count: 3\nleaf: \"0.5 0 0 0.5 0 x\"\n", SYLVA_ERR_PARAM, "test.yaml:2:7: 'leaf'", "column");
    expect_refused("leaf_count: 3\nleaf: \"1.2 0 0 0.5 0 0\"\n", SYLVA_ERR_PARAM, "test.yaml:2:7: 'leaf'",
                   "every map must shrink");
    expect_refused("leaf_count: 3\nleaf: \"0.5 0 0 0.5 0.8 0\"\n", SYLVA_ERR_PARAM, "test.yaml:2:7: 'leaf'",
                   "unit square");
    expect_refused("leaf_count: 3\nleaf: \"\"\n", SYLVA_ERR_PARAM, "'leaf'", "is not a leaf");
    expect_refused("leaf_count: 3\nleaf: [1, 2]\n", -1, "test.yaml:2:7", "'leaf'");
    expect_refused("bark: bumpy\n", -1, "test.yaml:1:7: 'bark'", "smooth");
    expect_refused("bark: scaly\nbark_angle: 400\n", -1, "test.yaml:2:13: 'bark_angle'", "[-360, 360]");
    expect_refused("bark_angle: north\n", -1, "'bark_angle'", "number");
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx, "leaf_count: 3\nleaf: willow\nbark: fissured\nbark_angle: -35.5\n", 1), 0);
    aono_config cfg;
    CHECK_INT(aono_fixture_config(&fx, &cfg), 0);
    leaf_affine_maps willow;
    leaf_affine_preset_maps(LEAF_AFFINE_WILLOW, &willow);
    CHECK_INT(cfg.leaf.n, willow.n); /* field by field: padding is not part of the value */
    for (uint32_t i = 0; i < willow.n && i < cfg.leaf.n; i++) {
        const leaf_affine_map *p = &cfg.leaf.map[i], *q = &willow.map[i];
        CHECK(p->a == q->a && p->b == q->b && p->c == q->c && p->d == q->d && p->e == q->e && p->f == q->f &&
              p->p == q->p);
    }
    bark_fractal_params fissured = bark_fractal_preset_params(BARK_FRACTAL_FISSURED);
    CHECK(cfg.bark.radius_inner == fissured.radius_inner && cfg.bark.iterations == fissured.iterations);
    CHECK(fabs(cfg.bark.theta - -35.5 * M_PI / 180.0) < 1e-12);
    aono_config_release(&cfg);
    aono_fixture_close(&fx);
}

/* A valid scene block opens without complaint and every default is usable. */
TEST(defaults_are_valid)
{
    aono_fixture fx;
    CHECK_INT(aono_fixture_open(&fx, "{}\n", 1), 0);
    CHECK(fx.state != NULL);
    mesh *m = NULL;
    double h = 0;
    CHECK_INT(aono_fixture_generate(&fx, 1.0, &m, &h), 0);
    CHECK(m && m->nt > 0 && h > 4.0);
    mesh_free(m);
    aono_fixture_close(&fx);
}

TEST_LIST(TEST_CASE(leaf_and_bark_keys), TEST_CASE(levels_negative_and_absurd), TEST_CASE(ratios_of_one_or_more), TEST_CASE(controller_on_a_tip),
          TEST_CASE(pattern_and_angles), TEST_CASE(settings_that_would_not_be_read), TEST_CASE(defaults_are_valid))
