/* test_pov_number.c — numbers for POV-Ray scene text: known spellings, significant digits,
 * rounding, the float round trip over many values, positions read in double precision, and
 * non-finite input. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "harness.h"
#include "pov/pov_number.h"
#include "util/rng.h"

static const char *real(double v, int digits)
{
    static char buf[POV_NUMBER_MAX];
    pov_format_real(buf, v, digits);
    return buf;
}

static const char *shortest(float v)
{
    static char buf[POV_NUMBER_MAX];
    pov_format_float(buf, v);
    return buf;
}

TEST(known_spellings)
{
    CHECK(!strcmp(real(0.0, 7), "0"));
    CHECK(!strcmp(real(-0.0, 7), "0"));
    CHECK(!strcmp(real(1.0, 7), "1"));
    CHECK(!strcmp(real(-2.5, 7), "-2.5"));
    CHECK(!strcmp(real(0.8660254037844386, 7), "0.8660254"));
    CHECK(!strcmp(real(-0.8660254037844386, 3), "-0.866"));
    CHECK(!strcmp(real(123456.789, 7), "123456.8"));
    CHECK(!strcmp(real(1234567.0, 3), "1234567")); /* an integer keeps its digits */
    CHECK(!strcmp(real(0.00012345678, 4), "0.0001235"));
    CHECK(!strcmp(real(9.99999999, 7), "10")); /* rounding carries into a new digit */
    CHECK(!strcmp(real(1e-5, 3), "0.00001"));
    /* outside [1e-5, 1e9): exponent notation, which POV-Ray reads */
    CHECK_NEAR(atof(real(3.5e-7, 7)), 3.5e-7, 1e-15);
    CHECK_NEAR(atof(real(2.5e12, 7)), 2.5e12, 1);
    CHECK(strchr(real(3.5e-7, 7), 'e') != NULL);
}

TEST(significant_digits_bound_the_error)
{
    sylva_rng r;
    rng_stream(&r, 3, "pov number", 0);
    for (int i = 0; i < 20000; i++) {
        double v = (rng_next_double(&r) - 0.5) * pow(10.0, (int)(rng_next_double(&r) * 12) - 4);
        for (int d = 1; d <= 9; d++) {
            double back = atof(real(v, d));
            if (!(fabs(back - v) <= 0.5000001 * pow(10.0, floor(log10(fabs(v))) - d + 1) + 1e-300)) {
                CHECK_NEAR(back, v, pow(10.0, floor(log10(fabs(v))) - d + 1));
                return;
            }
        }
    }
}

TEST(float_round_trip_is_exact_and_short)
{
    CHECK(!strcmp(shortest(0.1f), "0.1"));
    CHECK(!strcmp(shortest(0.2f), "0.2"));
    CHECK(!strcmp(shortest(-3.0f), "-3"));
    CHECK(!strcmp(shortest(1234.567f), "1234.567"));
    CHECK(!strcmp(shortest(0.0f), "0"));
    sylva_rng r;
    rng_stream(&r, 4, "pov float", 0);
    int bad = 0;
    for (int i = 0; i < 200000 && bad < 5; i++) {
        float v = (float)((rng_next_double(&r) - 0.5) * pow(10.0, (int)(rng_next_double(&r) * 16) - 7));
        const char *t = shortest(v);
        if ((float)strtod(t, NULL) != v || strlen(t) > 16) {
            fprintf(stderr, "  %.9g written as %s\n", (double)v, t);
            bad++;
        }
    }
    CHECK_INT(bad, 0);
}

static const char *position(float v)
{
    static char buf[POV_NUMBER_MAX];
    pov_format_position(buf, v);
    return buf;
}

/* A position's text, read in double precision as POV-Ray reads a matrix, lies within
 * POV_POSITION_TOLERANCE of the float: the shortest text where that is so, six decimals where
 * the shortest is a float step off (7 km from the origin, a quarter of a millimetre). */
TEST(position_read_in_double_is_the_float)
{
    CHECK(!strcmp(position(0.25f), "0.25"));
    CHECK(!strcmp(position(-3.0f), "-3"));
    CHECK(!strcmp(position(7.5f), "7.5"));
    CHECK(!strcmp(position(-5129.5522f), "-5129.552246")); /* the float is -5129.55224609375 */
    CHECK(!strcmp(position(251.35411f), "251.354111"));    /* 251.3541107177..., not 251.35411 */
    sylva_rng r;
    rng_stream(&r, 5, "pov position", 0);
    double worst = 0; /* metres between the text read in double and the float */
    size_t longest = 0;
    for (int i = 0; i < 200000; i++) {
        float v = (float)((rng_next_double(&r) - 0.5) * pow(10.0, (int)(rng_next_double(&r) * 12) - 4));
        const char *t = position(v);
        worst = fmax(worst, fabs(strtod(t, NULL) - (double)v));
        longest = strlen(t) > longest ? strlen(t) : longest;
    }
    CHECK(worst <= POV_POSITION_TOLERANCE + 1e-9); /* a tie rounds either way */
    CHECK(longest <= 18);
}

TEST(non_finite_is_refused)
{
    char buf[POV_NUMBER_MAX];
    CHECK_INT(pov_format_real(buf, NAN, 7), -1);
    CHECK(!strcmp(buf, "0"));
    CHECK_INT(pov_format_real(buf, INFINITY, 7), -1);
    CHECK_INT(pov_format_float(buf, -INFINITY), -1);
    CHECK_INT(pov_format_float(buf, NAN), -1);
    CHECK(!strcmp(buf, "0"));
    CHECK_INT(pov_format_position(buf, NAN), -1);
    CHECK(!strcmp(buf, "0"));
}

TEST_LIST(TEST_CASE(known_spellings), TEST_CASE(significant_digits_bound_the_error),
          TEST_CASE(float_round_trip_is_exact_and_short), TEST_CASE(position_read_in_double_is_the_float),
          TEST_CASE(non_finite_is_refused))
