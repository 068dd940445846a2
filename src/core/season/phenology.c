/* phenology.c — season names and dates as days of the year, and whether a species is in leaf
 * (phenology.h). */
#include "season/phenology.h"

#include <stdio.h>
#include <string.h>

static int leap_year(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int season_day_parse(const char *text, uint32_t *day, err_buf *err)
{
    static const struct { const char *name; uint32_t day; } named[] = {
        {"spring", SEASON_SPRING_DAY}, {"summer", SEASON_SUMMER_DAY},
        {"autumn", SEASON_AUTUMN_DAY}, {"winter", SEASON_WINTER_DAY}};
    for (size_t i = 0; i < sizeof named / sizeof named[0]; i++)
        if (!strcmp(text, named[i].name)) return *day = named[i].day, 0;
    int y, m, d, used = 0;
    if (strlen(text) == 10 && sscanf(text, "%4d-%2d-%2d%n", &y, &m, &d, &used) == 3 && used == 10 &&
        text[4] == '-' && text[7] == '-') {
        static const int month_days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
        if (m < 1 || m > 12)
            return err_set(err, "season date '%s' has month %d; a month is 01 to 12", text, m);
        int last = month_days[m - 1] + (m == 2 && leap_year(y));
        if (d < 1 || d > last)
            return err_set(err, "season date '%s' has day %d; month %02d of %04d has days 01 to %02d", text, d,
                           m, y, last);
        uint32_t doy = (uint32_t)d;
        for (int k = 0; k < m - 1; k++) doy += (uint32_t)(month_days[k] + (k == 1 && leap_year(y)));
        return *day = doy, 0;
    }
    return err_set(err, "season '%s' is neither a season (spring, summer, autumn or winter) nor a date "
                   "YYYY-MM-DD", text);
}

int phenology_in_leaf(const phenology *p, uint32_t day)
{
    if (p->habit == HABIT_EVERGREEN) return 1;
    if (p->leaf_out <= p->leaf_fall) return day >= p->leaf_out && day < p->leaf_fall;
    return day >= p->leaf_out || day < p->leaf_fall; /* the southern hemisphere: in leaf over new year */
}

double phenology_autumn_share(const phenology *p, uint32_t day)
{
    if (p->habit == HABIT_EVERGREEN || !phenology_in_leaf(p, day)) return 0;
    uint32_t since = (day + 366 - p->colouring) % 366, span = (p->leaf_fall + 366 - p->colouring) % 366;
    if (!span || since >= span) return 0; /* a day in leaf before colouring */
    return (double)since / span;
}

double phenology_fresh_share(const phenology *p, uint32_t day)
{
    if (p->habit == HABIT_EVERGREEN || !p->fresh_days || !phenology_in_leaf(p, day)) return 0;
    uint32_t since = (day + 366 - p->leaf_out) % 366;
    return since >= p->fresh_days ? 0 : 1 - (double)since / p->fresh_days;
}

int phenology_blossom_day(const phenology *p, uint32_t day)
{
    if (!p->blossom.given) return -1;
    uint32_t since = (day + 366 - p->blossom.first) % 366, span = (p->blossom.last + 366 - p->blossom.first) % 366;
    return since <= span ? (int)since : -1;
}

double phenology_fallen_share(const phenology *p, uint32_t day)
{
    if (p->habit == HABIT_EVERGREEN) return 0;
    if (!phenology_in_leaf(p, day)) return 1;
    double f = phenology_autumn_share(p, day);
    return f * f;
}

double meadow_dormancy(uint32_t day)
{
    enum { GREEN_UP = 60, GROWING = 130, CURING = 230, RESTING = 330 };
    if (day == 0 || (day >= GROWING && day <= CURING)) return 0;
    if (day > CURING && day < RESTING) return (double)(day - CURING) / (RESTING - CURING);
    if (day > GREEN_UP && day < GROWING) return (double)(GROWING - day) / (GROWING - GREEN_UP);
    return 1;
}
