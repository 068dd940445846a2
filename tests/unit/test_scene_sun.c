/* test_scene_sun.c — the sun placed by date and time: ISO 8601 instants with their offsets read
 * into UTC (days, months and leap days carried), the site frame's map-to-longitude/latitude
 * conversion, the sun: section's date_time with latitude/longitude or with a site origin (the
 * SPA paper's example instant and place), and the refusals with file:line:column. */
#include "harness.h"
#include "work_dir.h"
#include "scene_file/scene_file.h"
#include "site/site_frame.h"
#include "season/sun_position.h"

static void check_parse(const char *text, int y, int mo, int d, int h, int mi, double s)
{
    sun_utc t;
    err_buf err = {{0}};
    int rc = sun_utc_parse(text, &t, &err);
    CHECK_INT(rc, 0);
    if (rc) {
        fprintf(stderr, "%s\n", err.msg);
        return;
    }
    if (t.year != y || t.month != mo || t.day != d || t.hour != h || t.minute != mi ||
        fabs(t.second - s) > 1e-9) {
        fprintf(stderr, "%s: %04d-%02d-%02d %02d:%02d:%g UTC\n", text, t.year, t.month, t.day,
                t.hour, t.minute, t.second);
        CHECK(0);
    }
}

static void check_refused(const char *text, const char *why)
{
    sun_utc t;
    err_buf err = {{0}};
    CHECK_INT(sun_utc_parse(text, &t, &err), -1);
    CHECK_STR_CONTAINS(err.msg, why);
}

TEST(iso_8601_to_utc)
{
    check_parse("2026-06-21T14:30:00+01:00", 2026, 6, 21, 13, 30, 0);
    check_parse("2026-06-21T13:30:00Z", 2026, 6, 21, 13, 30, 0);
    check_parse("2026-06-21T13:30Z", 2026, 6, 21, 13, 30, 0);
    check_parse("2003-10-17T12:30:30-07:00", 2003, 10, 17, 19, 30, 30);
    check_parse("2026-01-01T00:30:00+01:00", 2025, 12, 31, 23, 30, 0);  /* back into last year */
    check_parse("2024-02-28T23:00:00-05:00", 2024, 2, 29, 4, 0, 0);     /* a leap day */
    check_parse("2023-02-28T23:00:00-05:00", 2023, 3, 1, 4, 0, 0);      /* none that year */
    check_parse("2026-03-29T01:15:30.25+0530", 2026, 3, 28, 19, 45, 30.25);
    check_parse("2026-06-21T14:30:00+01", 2026, 6, 21, 13, 30, 0);
    check_refused("2026-06-21T14:30:00", "gives no UTC offset");
    check_refused("2026-06-21 14:30:00+01:00", "has no time");
    check_refused("21/06/2026 14:30", "does not begin with a date YYYY-MM-DD");
    check_refused("2026-02-30T12:00:00Z", "is not a date in the calendar");
    check_refused("2026-06-21T24:00:00Z", "is not a time of day");
    check_refused("2026-06-21T14:30:00+15:00", "UTC offset");
    check_refused("2026-06-21T14:30:00Z trailing", "goes on after");
    check_refused("", "does not begin with a date");
}

/* The inverse of PROJ's quick-start example: 691875.63 E, 6098907.83 N in UTM 32N is 12 E,
 * 55 N; and map -> lon/lat -> map comes back to the millimetre. */
TEST(site_to_lonlat)
{
    err_buf err = {{0}};
    site_frame *f = site_frame_new("EPSG:32632", NULL, &err);
    CHECK(f != NULL);
    if (!f) return;
    double ll[2] = {0, 0}, map[2] = {0, 0};
    CHECK_INT(site_frame_to_lonlat(f, 691875.63, 6098907.83, ll, &err), 0);
    CHECK_NEAR(ll[0], 12.0, 1e-7);
    CHECK_NEAR(ll[1], 55.0, 1e-7);
    CHECK_INT(site_frame_from_lonlat(f, 9.5, 47.25, map, &err), 0);
    CHECK_INT(site_frame_to_lonlat(f, map[0], map[1], ll, &err), 0);
    CHECK_NEAR(ll[0], 9.5, 1e-9);
    CHECK_NEAR(ll[1], 47.25, 1e-9);
    CHECK_INT(site_frame_to_lonlat(f, 1e30, 1e30, ll, &err), -1);
    CHECK_STR_CONTAINS(err.msg, "cannot be converted into longitude/latitude");
    site_frame_free(f);
}

/* Loads text with a camera appended (after it, so the text's lines keep their numbers). */
static scene_file *load(const char *text, err_buf *err)
{
    char full[2048];
    snprintf(full, sizeof full, "%scamera: {position: [0, -10, 2], look_at: [0, 0, 0]}\n", text);
    const char *path = work_file("scene.yaml", full);
    CHECK(path != NULL);
    return path ? scene_file_load(path, NULL, err) : NULL;
}

static scene_file *load_ok(const char *text)
{
    err_buf err = {{0}};
    scene_file *sf = load(text, &err);
    if (!sf) fprintf(stderr, "%s\n", err.msg);
    CHECK(sf != NULL);
    return sf;
}

/* The SPA paper's instant and place (sea-level air here, so the elevation differs from the
 * paper's 820 mbar by under 0.005 degree). */
TEST(sun_by_date_and_place)
{
    scene_file *sf = load_ok("sun:\n  date_time: \"2003-10-17T12:30:30-07:00\"\n"
                             "  latitude: 39.742476\n  longitude: -105.1786\n");
    if (!sf) return;
    const sun_settings *s = &sf->sun;
    CHECK_NEAR(s->azimuth_deg, 194.34024, 0.01);
    CHECK_NEAR(s->elevation_deg, 90.0 - 50.11162, 0.015);
    CHECK(!strcmp(s->date_time_utc, "2003-10-17T19:30:30Z"));
    CHECK_NEAR(s->latitude_deg, 39.742476, 1e-12);
    double a = s->azimuth_deg * M_PI / 180, e = s->elevation_deg * M_PI / 180;
    CHECK_NEAR(s->direction[0], sin(a) * cos(e), 1e-12);
    CHECK_NEAR(s->direction[1], cos(a) * cos(e), 1e-12);
    CHECK_NEAR(s->direction[2], sin(e), 1e-12);
    scene_file_free(sf);
}

/* With a site, the sun is placed from the site origin: the same place given as map coordinates
 * in UTM zone 13N puts the sun where latitude/longitude did. */
TEST(sun_from_site_origin)
{
    err_buf err = {{0}};
    site_frame *f = site_frame_new("EPSG:32613", NULL, &err);
    CHECK(f != NULL);
    if (!f) return;
    double map[2];
    CHECK_INT(site_frame_from_lonlat(f, -105.1786, 39.742476, map, &err), 0);
    site_frame_free(f);
    char text[512];
    snprintf(text, sizeof text,
             "site: {crs: \"EPSG:32613\", origin: [%.4f, %.4f]}\n"
             "sun: {date_time: \"2003-10-17T19:30:30Z\"}\n", map[0], map[1]);
    scene_file *sf = load_ok(text);
    if (!sf) return;
    CHECK_NEAR(sf->sun.latitude_deg, 39.742476, 1e-8);
    CHECK_NEAR(sf->sun.longitude_deg, -105.1786, 1e-8);
    CHECK_NEAR(sf->sun.azimuth_deg, 194.34024, 0.01);
    scene_file_free(sf);
}

static void check_scene_refused(const char *text, uint32_t line, uint32_t column, const char *why)
{
    err_buf err = {{0}};
    scene_file *sf = load(text, &err);
    CHECK(sf == NULL);
    scene_file_free(sf);
    CHECK_STR_CONTAINS(err.msg, why);
    char place[64];
    snprintf(place, sizeof place, "scene.yaml:%u:%u: ", line, column);
    CHECK_STR_CONTAINS(err.msg, place);
}

TEST(sun_date_refusals)
{
    check_scene_refused("sun:\n  date_time: \"2026-06-21T14:30:00+01:00\"\n  azimuth: 120\n"
                        "  latitude: 50\n  longitude: 0\n",
                        3, 12, "the sun takes 'date_time' or 'azimuth', not both");
    check_scene_refused("sun:\n  direction: [0, 1, 1]\n  date_time: \"2026-06-21T14:30:00Z\"\n"
                        "  latitude: 50\n  longitude: 0\n",
                        3, 14, "'date_time' or 'direction', not both");
    check_scene_refused("sun:\n  date_time: \"2026-06-21 14:30\"\n  latitude: 50\n  longitude: 0\n",
                        2, 14, "for example date_time: \"2026-06-21T14:30:00+01:00\"");
    check_scene_refused("sun:\n  date_time: \"2026-06-21T14:30:00\"\n  latitude: 50\n  longitude: 0\n",
                        2, 14, "gives no UTC offset");
    check_scene_refused("sun:\n  date_time: \"2026-06-21T14:30:00Z\"\n  latitude: 50\n",
                        2, 14, "needs 'latitude' and 'longitude'");
    check_scene_refused("sun:\n  azimuth: 100\n  latitude: 50\n", 3, 13,
                        "'latitude' places the sun only with 'date_time'");
    check_scene_refused("site: {crs: \"EPSG:32632\", origin: [691875, 6098907]}\n"
                        "sun: {date_time: \"2026-06-21T14:30:00Z\", longitude: 12}\n",
                        2, 53, "the scene has a site: the sun is placed from its origin");
    check_scene_refused("sun: {date_time: \"1850-06-21T14:30:00Z\", latitude: 50, longitude: 0}\n",
                        1, 18, "outside 1900..2100");
    check_scene_refused("sun: {date_time: \"2026-06-21T14:30:00Z\", latitude: 95, longitude: 0}\n",
                        1, 52, "'latitude' must be in [-90, 90]");
}

TEST_LIST(TEST_CASE(iso_8601_to_utc), TEST_CASE(site_to_lonlat), TEST_CASE(sun_by_date_and_place),
          TEST_CASE(sun_from_site_origin), TEST_CASE(sun_date_refusals))
