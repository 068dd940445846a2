/* test_eco_growth.c — favourability, vigour, power, growth phases, death age and N_opt against
 * hand-computed values; reading species blocks (profiles, overrides, bad ages). */
#include "eco_fixture.h"
#include "eco_growth.h"

TEST(favourability_by_hand)
{
    CHECK_NEAR(eco_favourability(0.55, 0.5, 0.1, 2), 1.0, 0);       /* inside the tolerance */
    CHECK_NEAR(eco_favourability(0.6, 0.5, 0.1, 2), 1.0, 1e-12);     /* on its edge */
    CHECK_NEAR(eco_favourability(0.7, 0.5, 0.1, 2), 0.6, 1e-12);     /* 1 - 0.2 * 2 */
    CHECK_NEAR(eco_favourability(0.3, 0.5, 0.1, 2), 0.6, 1e-12);     /* either side */
    CHECK_NEAR(eco_favourability(0.9, 0.5, 0.1, 3), 0.0, 0);         /* 1 - 1.2, clamped */
    CHECK_NEAR(eco_favourability(1.0, 0.0, 0.0, 0), 1.0, 0);         /* no harm */
    CHECK_NEAR(eco_slope_favourability(0.2, 2), 0.84, 1e-12);        /* 1 - (2 * 0.2)^2 */
    CHECK_NEAR(eco_slope_favourability(0.6, 2), 0.0, 0);             /* 1 - 1.44, clamped */
    CHECK_NEAR(eco_slope_favourability(0.0, 5), 1.0, 0);
}

TEST(vigour_and_power_by_hand)
{
    eco_species sp = eco_profiles[ECO_PROFILE_GENERIC];
    sp.opt[ECO_FAV_ALTITUDE] = 0.5, sp.tol[ECO_FAV_ALTITUDE] = 0.1, sp.harm[ECO_FAV_ALTITUDE] = 2;
    sp.opt[ECO_FAV_HUMIDITY] = 0.2, sp.tol[ECO_FAV_HUMIDITY] = 0.1, sp.harm[ECO_FAV_HUMIDITY] = 1;
    sp.opt[ECO_FAV_WINDINESS] = 1.0, sp.tol[ECO_FAV_WINDINESS] = 0.2, sp.harm[ECO_FAV_WINDINESS] = 4;
    sp.opt[ECO_FAV_SUNNINESS] = 0.5, sp.tol[ECO_FAV_SUNNINESS] = 0.05, sp.harm[ECO_FAV_SUNNINESS] = 10;
    sp.harm[ECO_FAV_SLOPE] = 2;
    /* factors in map order: altitude, slope, humidity, windiness, sunniness */
    const float f[5] = {0.7f, 0.2f, 0.5f, 0.5f, 0.52f};
    double fav[5];
    eco_favourabilities(&sp, f, fav);
    CHECK_NEAR(fav[ECO_FAV_ALTITUDE], 1 - 0.2 * 2, 1e-6);  /* 0.6 */
    CHECK_NEAR(fav[ECO_FAV_SLOPE], 0.84, 1e-6);
    CHECK_NEAR(fav[ECO_FAV_HUMIDITY], 1 - 0.3 * 1, 1e-6);  /* 0.7 */
    CHECK_NEAR(fav[ECO_FAV_WINDINESS], 0.0, 0);            /* 1 - 0.5 * 4 */
    CHECK_NEAR(fav[ECO_FAV_SUNNINESS], 1.0, 0);            /* within 0.05 */
    double v = eco_vigour(fav);
    CHECK_NEAR(v, (0.6 + 0.84 + 0.7 + 0.0 + 1.0) / 5, 1e-6); /* 0.628 */
    CHECK_NEAR(eco_power(v, 0.5, 150.0 / 300.0), 0.628 * 0.5 * 0.5, 1e-6);
}

TEST(growth_phases)
{
    eco_species sp = eco_profiles[ECO_PROFILE_GENERIC];
    sp.t_m = 10, sp.t_a = 30, sp.h_m = 0.4;
    CHECK_NEAR(eco_growth(&sp, 0, 1), 0.04, 1e-12);   /* h_m / t_m */
    CHECK_NEAR(eco_growth(&sp, 9, 1), 0.04, 1e-12);
    CHECK_NEAR(eco_growth(&sp, 10, 1), 0.03, 1e-12);  /* (1 - h_m) / (t_a - t_m) */
    CHECK_NEAR(eco_growth(&sp, 29, 1), 0.03, 1e-12);
    CHECK_NEAR(eco_growth(&sp, 30, 1), 0.0, 0);       /* aged: no growth */
    CHECK_NEAR(eco_growth(&sp, 5, 0.5), 0.02, 1e-12); /* scaled by vigour */
    double h = 0;
    for (int t = 0; t < 10; t++) h += eco_growth(&sp, t, 1);
    CHECK_NEAR(h, 0.4, 1e-12); /* h_m at maturity */
    for (int t = 10; t < 60; t++) h += eco_growth(&sp, t, 1);
    CHECK_NEAR(h, 1.0, 1e-12); /* full grown at t_a, and no more */
}

TEST(death_age_and_n_opt)
{
    eco_species sp = eco_profiles[ECO_PROFILE_GENERIC];
    sp.t_m = 20, sp.t_f = 150;
    CHECK_NEAR(eco_death_age(&sp, 0.0), 20, 0);
    CHECK_NEAR(eco_death_age(&sp, 0.5), 85, 1e-12);
    CHECK_INT(eco_n_opt(7, 10), 2);  /* ceil(14 / 10) */
    CHECK_INT(eco_n_opt(5, 10), 1);  /* ceil(10 / 10) */
    CHECK_INT(eco_n_opt(5.5, 4), 3); /* ceil(11 / 4) */
    CHECK_INT(eco_n_opt(10, 2.5), 8);
}

TEST(profiles_by_name_and_overrides)
{
    fixture_host f;
    fixture_host_init(&f, 1);
    eco_species sp;
    fixture_block *none = fixture_species_block(NULL, NULL);
    CHECK_INT(fixture_species_read(&f, &none->params, "spruce", &sp), 0);
    CHECK_NEAR(sp.t_f, eco_profiles[ECO_PROFILE_SPRUCE].t_f, 0);
    CHECK_INT(fixture_species_read(&f, &none->params, "oak", &sp), 0);
    CHECK_NEAR(sp.r_s, eco_profiles[ECO_PROFILE_GENERIC].r_s, 0);
    const char *keys[] = {"profile", "t_m", "altitude_opt", NULL};
    const double vals[] = {ECO_PROFILE_SHRUB, 2, 0.9};
    fixture_block *b = fixture_species_block(keys, vals);
    CHECK_INT(fixture_species_read(&f, &b->params, "beech", &sp), 0);
    CHECK_NEAR(sp.t_m, 2, 0);                                   /* given */
    CHECK_NEAR(sp.opt[ECO_FAV_ALTITUDE], 0.9, 0);                /* given */
    CHECK_NEAR(sp.t_a, eco_profiles[ECO_PROFILE_SHRUB].t_a, 0);  /* from the profile named */
    CHECK_NEAR(sp.g_s, eco_profiles[ECO_PROFILE_SHRUB].g_s, 0);
    free(none), free(b);
    fixture_host_release(&f);
}

TEST(ages_out_of_order_are_refused)
{
    fixture_host f;
    fixture_host_init(&f, 1);
    eco_species sp;
    const char *k1[] = {"t_m", "t_a", NULL};
    const double v1[] = {50, 40};
    fixture_block *b = fixture_species_block(k1, v1);
    CHECK(fixture_species_read(&f, &b->params, "beech", &sp) != 0);
    CHECK(f.fail.where == &b->params); /* the plugin file reports it at the key's place */
    CHECK_STR_CONTAINS(f.fail.param, "t_m");
    CHECK_STR_CONTAINS(f.fail.msg, "t_m = 50 years is not before t_a = 40 years");
    free(b);
    const char *k2[] = {"t_f", NULL};
    const double v2[] = {30};
    b = fixture_species_block(k2, v2); /* generic t_a = 60 */
    CHECK(fixture_species_read(&f, &b->params, "oak", &sp) != 0);
    CHECK_STR_CONTAINS(f.fail.param, "t_f");
    CHECK_STR_CONTAINS(f.fail.msg, "t_a <= t_f");
    free(b);
    fixture_host_release(&f);
}

TEST(every_profile_is_valid)
{
    for (int p = 0; p < ECO_N_PROFILES; p++) {
        const eco_species *s = &eco_profiles[p];
        CHECK(s->t_m > 0 && s->t_m < s->t_a && s->t_a <= s->t_f);
        CHECK(s->h_m > 0 && s->h_m <= 1 && s->r_s > 0 && s->r_s <= 20);
        CHECK(s->p_s >= 0 && s->p_s <= 1 && s->p_m >= 0 && s->p_m <= 1 && s->g_s >= 0 && s->g_s <= 100);
    }
    /* the schema's defaults are the generic profile's */
    for (uint32_t i = 0; i < ECO_SPECIES_KEYS; i++)
        if (!strcmp(eco_species_schema[i].name, "t_m")) CHECK_NEAR(eco_species_schema[i].def, 20, 0);
}

TEST_LIST(TEST_CASE(favourability_by_hand), TEST_CASE(vigour_and_power_by_hand), TEST_CASE(growth_phases),
          TEST_CASE(death_age_and_n_opt), TEST_CASE(profiles_by_name_and_overrides),
          TEST_CASE(ages_out_of_order_are_refused), TEST_CASE(every_profile_is_valid))
