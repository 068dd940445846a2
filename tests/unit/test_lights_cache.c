/* test_lights_cache.c — the lights of several render setups built once (render/lights_cache.h):
 * kept while every input is the same, built anew when one changes (the camera's height only for
 * the physical sky), and then bit for bit what lights_init builds from the same inputs. */
#include "harness.h"

#include <string.h>

#include "render/lights_cache.h"

static sun_settings sun_of(void)
{
    return (sun_settings){.enabled = 1, .direction = {0.4, -0.5, 0.766}, .irradiance = 1.0,
                          .color = {1.0, 0.97, 0.92}, .angular_diameter_deg = 0.53};
}

static sky_settings sky_of(sky_model model)
{
    return (sky_settings){.model = model, .turbidity = 3.0, .visibility_km = 30.0, .density = 1.0, .scale = 1.0,
                          .color = {0.2, 0.3, 0.5}, .ground_albedo = 0.2, .ambient = {0.1, 0.1, 0.1}};
}

/* 1 when a and b hold the same light, table included, to the bit. */
static int same_lights(const lights *a, const lights *b)
{
    size_t cells = (size_t)a->table.nt * a->table.np;
    return !memcmp(&a->summary, &b->summary, sizeof a->summary) && a->table.nt == b->table.nt &&
           a->table.np == b->table.np && (!cells || (!memcmp(a->table.rgb, b->table.rgb, cells * 3 * sizeof(float)) &&
                                                     !memcmp(a->table.pdf, b->table.pdf, cells * sizeof(float))));
}

/* The cache's lights for (sky, camera_z) against lights_init's. */
static void check_as_built(lights_cache *c, const sky_settings *sky, double camera_z, const lights **got)
{
    sun_settings sun = sun_of();
    err_buf err = {{0}};
    *got = lights_cache_get(c, &sun, sky, 180.0, camera_z, 2, &err); /* on two threads, against one */
    CHECK(*got != NULL);
    lights fresh;
    CHECK_INT(lights_init(&fresh, &sun, sky, 180.0, camera_z, 1, &err), 0);
    if (*got) CHECK(same_lights(*got, &fresh));
    lights_free(&fresh);
}

TEST(physical_sky_follows_the_camera_height)
{
    lights_cache *c = lights_cache_new();
    CHECK(c != NULL);
    sky_settings sky = sky_of(SKY_PHYSICAL);
    const lights *first, *again, *higher;
    check_as_built(c, &sky, 70.0, &first);
    check_as_built(c, &sky, 70.0, &again);
    CHECK(first == again); /* kept, not built again */
    double kept = first->summary.atmosphere.altitude;
    check_as_built(c, &sky, 95.0, &higher);
    CHECK(higher->summary.atmosphere.altitude != kept); /* seen from the new height */
    lights_cache_free(c);
}

TEST(other_skies_are_one_for_every_camera)
{
    lights_cache *c = lights_cache_new();
    sky_settings sky = sky_of(SKY_PREETHAM);
    const lights *low, *high, *hazier;
    check_as_built(c, &sky, 2.0, &low);
    check_as_built(c, &sky, 400.0, &high);
    CHECK(low == high);
    float before = low->table.pdf[100];
    sky.turbidity = 5.0; /* another input: built anew */
    check_as_built(c, &sky, 400.0, &hazier);
    CHECK(hazier->table.pdf[100] != before);
    lights_cache_free(c);
    lights_cache_free(NULL);
}

TEST(bad_sky_is_refused)
{
    lights_cache *c = lights_cache_new();
    sky_settings sky = sky_of(SKY_PREETHAM);
    sky.turbidity = 20.0; /* outside the model's range */
    sun_settings sun = sun_of();
    err_buf err = {{0}};
    CHECK(lights_cache_get(c, &sun, &sky, 0.0, 0.0, 0, &err) == NULL);
    CHECK(strstr(err.msg, "turbidity") != NULL);
    sky.turbidity = 3.0; /* and the cache still works */
    CHECK(lights_cache_get(c, &sun, &sky, 0.0, 0.0, 0, &err) != NULL);
    lights_cache_free(c);
}

TEST_LIST(TEST_CASE(physical_sky_follows_the_camera_height), TEST_CASE(other_skies_are_one_for_every_camera),
          TEST_CASE(bad_sky_is_refused))
