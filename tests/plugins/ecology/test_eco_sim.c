/* test_eco_sim.c — the simulation: Algorithm 8's grid search against all pairs, self-thinning
 * on uniform terrain, a species outside its optimum dying out, the same seeds giving the same
 * plants on any thread count, save -> load -> continue equal to an uninterrupted run, and bad
 * input (unknown species, a growth area outside the terrain, a damaged state file). */
#include <dirent.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include "eco_fixture.h"
#include "eco_growth.h"
#include "work_dir.h"

static double flat(double x, double y) { return 0.0; }
static double hills(double x, double y) { return 8 * sin(x / 17.0) * cos(y / 23.0) + 0.05 * x; }

/* A small uniform terrain: 60 x 60 m. */
static sylva_heightfield small_flat(void) { return fixture_heightfield(31, 31, 0, 0, 2, flat); }

static void run_years(fixture_host *f, eco_sim *s, uint32_t years)
{
    for (uint32_t y = 0; y < years; y++) CHECK_INT(eco_sim_step(s, &f->rnd, &f->fail), 0);
}

/* Algorithm 8 by brute force over all pairs; equal power goes to the older plant, then to the
 * one earlier in the run's order. */
static int dominated_by_any(const eco_sim *s, uint32_t ja, uint32_t qa)
{
    const eco_plant *a = &s->pop[ja].plants[qa];
    for (uint32_t j = 0; j < s->n_species; j++)
        for (uint32_t q = 0; q < s->pop[j].n; q++) {
            const eco_plant *b = &s->pop[j].plants[q];
            double dx = a->x - b->x, dy = a->y - b->y, dz = a->z - b->z, rr = a->r + b->r;
            int stronger = a->power < b->power ||
                           (a->power == b->power && (b->age > a->age || (b->age == a->age && (j < ja || (j == ja && q < qa)))));
            if (dx * dx + dy * dy + dz * dz < rr * rr && stronger) return 1;
        }
    return 0;
}

TEST(dominance_grid_equals_all_pairs)
{
    fixture_host f;
    fixture_host_init(&f, 7);
    sylva_heightfield hf = fixture_heightfield(41, 41, 0, 0, 2, hills);
    eco_config cfg = fixture_config(20); /* K = 4 m, radii up to R_s = 6 m: N_opt = 3 */
    const char *names[] = {"beech", "shrub", "spruce"};
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 3, names, NULL, &s), 0);
    CHECK_INT(s->n_opt, 3);
    uint32_t checked = 0, dominated = 0;
    for (int y = 0; y < 60; y++) {
        run_years(&f, s, 1);
        /* eco_sim_step removed the dead after the search; search again for the living */
        CHECK_INT(eco_find_dominance(s, &f.fail), 0);
        for (uint32_t j = 0; j < s->n_species; j++)
            for (uint32_t q = 0; q < s->pop[j].n; q++) {
                const eco_plant *a = &s->pop[j].plants[q];
                CHECK_INT(a->dominated, dominated_by_any(s, j, q));
                checked++, dominated += a->dominated;
            }
    }
    CHECK(checked > 5000);
    CHECK(dominated > 500); /* the test saw real competition */
    eco_sim_free(s);
    free(hf.z);
    fixture_host_release(&f);
}

TEST(single_species_self_thins)
{
    fixture_host f;
    fixture_host_init(&f, 3);
    sylva_heightfield hf = small_flat();
    eco_config cfg = fixture_config(30);
    /* fast to seed, slow to grow large; a dominated plant dies within the year (p_m = 1) */
    const char *keys[] = {"t_m", "t_a", "t_f", "r_s", "g_s", "p_m", "h_m", NULL};
    const double vals[] = {3, 60, 400, 8, 6, 1, 0.2};
    fixture_block *b = fixture_species_block(keys, vals);
    const char *names[] = {"tree"};
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, &b, &s), 0);
    uint32_t peak = 0, peak_year = 0;
    double radius_at_peak = 0, late_count = 0, late_radius = 0;
    for (uint32_t y = 1; y <= 150; y++) {
        run_years(&f, s, 1);
        double rsum = 0;
        for (uint32_t q = 0; q < s->pop[0].n; q++) rsum += s->pop[0].plants[q].r;
        double mean = s->pop[0].n ? rsum / s->pop[0].n : 0;
        if (s->pop[0].n > peak) peak = s->pop[0].n, peak_year = y, radius_at_peak = mean;
        if (y > 90) late_count += s->pop[0].n / 60.0, late_radius += mean / 60.0;
    }
    fprintf(stderr, "  peak %u plants in year %u (mean radius %.2f m); years 91-150: %.0f plants, mean radius %.2f m\n",
            peak, peak_year, radius_at_peak, late_count, late_radius);
    CHECK(peak > 80);                          /* the terrain filled */
    CHECK(peak_year < 60);
    CHECK(late_count < 0.7 * peak);            /* then the count fell ... */
    CHECK(late_radius > 1.5 * radius_at_peak); /* ... while the plants grew */
    eco_sim_free(s);
    free(b), free(hf.z);
    fixture_host_release(&f);
}

TEST(species_outside_its_optimum_dies_out)
{
    fixture_host f;
    fixture_host_init(&f, 11);
    sylva_heightfield hf = small_flat(); /* altitude and humidity 0.5, windiness 1 everywhere */
    eco_config cfg = fixture_config(30);
    const char *kgood[] = {"t_m", "g_s", NULL};
    const double vgood[] = {10, 2};
    const char *kbad[] = {"t_m", "g_s", "env_death", "altitude_opt", "altitude_tol", "altitude_harm", "humidity_opt",
                          "humidity_tol", "humidity_harm", "windiness_opt", "windiness_tol", "windiness_harm", NULL};
    const double vbad[] = {10, 2, 0.5, 1.0, 0.1, 3, 0.0, 0.1, 3, 0.0, 0.1, 3};
    fixture_block *blocks[2] = {fixture_species_block(kgood, vgood), fixture_species_block(kbad, vbad)};
    const char *names[] = {"fits", "misfit"};
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 2, names, blocks, &s), 0);
    run_years(&f, s, 120);
    uint32_t oldest = 0;
    for (uint32_t q = 0; q < s->pop[1].n; q++) oldest = s->pop[1].plants[q].age > oldest ? s->pop[1].plants[q].age : oldest;
    fprintf(stderr, "  after 120 years: %u fitting plants, %u misfits (the oldest %u years)\n", s->pop[0].n,
            s->pop[1].n, oldest);
    CHECK(s->pop[0].n > 100);
    CHECK(s->pop[1].n <= 3);  /* only this year's arrivals from outside */
    CHECK(oldest < 10);       /* none lived to maturity */
    CHECK_NEAR(s->pop[1].n ? s->pop[1].plants[0].v : 0.4, 0.4, 1e-6); /* vigour (0+1+0+0+1)/5 */
    eco_sim_free(s);
    free(blocks[0]), free(blocks[1]), free(hf.z);
    fixture_host_release(&f);
}

static eco_sim *grown(fixture_host *f, const sylva_heightfield *hf, unsigned threads, uint32_t years)
{
    eco_config cfg = fixture_config(25);
    cfg.threads = cfg.factors.threads = threads;
    const char *names[] = {"beech", "maple", "spruce", "shrub"};
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(f, hf, &cfg, 4, names, NULL, &s), 0);
    if (s) run_years(f, s, years);
    return s;
}

TEST(same_seeds_same_plants_any_threads)
{
    fixture_host f;
    fixture_host_init(&f, 5);
    sylva_heightfield hf = fixture_heightfield(41, 41, 0, 0, 2, hills);
    eco_sim *a = grown(&f, &hf, 1, 70), *b = grown(&f, &hf, 1, 70), *c = grown(&f, &hf, 3, 70);
    CHECK(eco_sim_count(a) > 500);
    CHECK(fixture_same_plants(a, b));
    CHECK(fixture_same_plants(a, c));
    /* another scene seed gives another forest */
    fixture_host g;
    fixture_host_init(&g, 6);
    eco_sim *d = grown(&g, &hf, 1, 70);
    CHECK(!fixture_same_plants(a, d));
    eco_sim_free(a), eco_sim_free(b), eco_sim_free(c), eco_sim_free(d);
    free(hf.z);
    fixture_host_release(&f);
    fixture_host_release(&g);
}

TEST(stream_seeds_change_only_their_purpose)
{
    fixture_host f;
    fixture_host_init(&f, 5);
    sylva_heightfield hf = small_flat();
    eco_config cfg = fixture_config(30);
    const char *names[] = {"shrub"};
    eco_sim *a = NULL, *b = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, NULL, &a), 0);
    cfg.stream_seeds[ECO_RNG_DEATH_AGE] = 42;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, NULL, &b), 0);
    run_years(&f, a, 1), run_years(&f, b, 1);
    /* the first seedling lands at the same place, with another death age */
    CHECK(a->pop[0].n >= 1 && b->pop[0].n >= 1);
    CHECK_NEAR(a->pop[0].plants[0].x, b->pop[0].plants[0].x, 0);
    CHECK(a->pop[0].plants[0].t_max != b->pop[0].plants[0].t_max);
    eco_sim_free(a), eco_sim_free(b);
    free(hf.z);
    fixture_host_release(&f);
}

TEST(save_load_continue_equals_uninterrupted)
{
    fixture_host f;
    fixture_host_init(&f, 9);
    sylva_heightfield hf = fixture_heightfield(41, 41, 0, 0, 2, hills);
    char path[256];
    snprintf(path, sizeof path, "/tmp/sylva_eco_state_%ld.bin", (long)getpid());
    eco_sim *whole = grown(&f, &hf, 2, 80);
    eco_sim *first = grown(&f, &hf, 2, 35);
    CHECK_INT(eco_sim_save(first, path, &f.fail), 0);
    eco_sim *second = grown(&f, &hf, 1, 0);
    CHECK_INT(eco_sim_load(second, path, &f.fail), 0);
    CHECK_INT(second->year, 35);
    CHECK(fixture_same_plants(first, second));
    run_years(&f, second, 45);
    CHECK(eco_sim_count(whole) > 500);
    CHECK(fixture_same_plants(whole, second));
    /* a damaged file is refused and leaves the run as it was */
    FILE *fp = fopen(path, "r+b");
    fseek(fp, 100, SEEK_SET);
    fputc(0x5a, fp);
    fclose(fp);
    CHECK(eco_sim_load(second, path, &f.fail) != 0);
    CHECK_STR_CONTAINS(f.fail.msg, "damaged");
    CHECK(fixture_same_plants(whole, second));
    /* a state from another species list is refused */
    CHECK_INT(eco_sim_save(first, path, &f.fail), 0);
    eco_config cfg = fixture_config(25);
    const char *names[] = {"beech"};
    eco_sim *other = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, NULL, &other), 0);
    CHECK(eco_sim_load(other, path, &f.fail) != 0);
    CHECK_STR_CONTAINS(f.fail.msg, "saved from another terrain");
    CHECK(eco_sim_load(other, "/nonexistent/state.bin", &f.fail) == SYLVA_ERR_IO);
    remove(path);
    eco_sim_free(whole), eco_sim_free(first), eco_sim_free(second), eco_sim_free(other);
    free(hf.z);
    fixture_host_release(&f);
}

/* A state cut short anywhere says one true thing: how many bytes the file holds and which part
 * of the state, at which bytes, it ends inside; bytes added after the checksum and a damaged body
 * are told apart from it. */
TEST(cut_short_state_says_where)
{
    fixture_host f;
    fixture_host_init(&f, 9);
    sylva_heightfield hf = fixture_heightfield(41, 41, 0, 0, 2, hills);
    char path[256], cut[300];
    snprintf(path, sizeof path, "/tmp/sylva_eco_state_%ld.bin", (long)getpid());
    snprintf(cut, sizeof cut, "%s.cut", path);
    eco_sim *run = grown(&f, &hf, 2, 20), *back = grown(&f, &hf, 1, 0);
    CHECK_INT(eco_sim_save(run, path, &f.fail), 0);
    FILE *fp = fopen(path, "rb");
    CHECK(fp != NULL);
    if (!fp) return;
    static unsigned char bytes[1 << 22];
    size_t size = fread(bytes, 1, sizeof bytes, fp);
    fclose(fp);
    CHECK(size > 200 && size < sizeof bytes);
    /* where the file is cut, and what it must then say it ends inside */
    struct { size_t at; const char *part; } cuts[] = {
        {5, "the mark SYLVAECO (bytes 1 to 8)"},
        {10, "the format version and byte-order mark (bytes 9 to 12)"},
        {20, "the fingerprint of the scene that saved it (bytes 17 to 24)"},
        {26, "the species count and year (bytes 25 to 28)"},
        {36, "the name of species 0"},
        {size / 2, "plant "},
        {size - 3, "the checksum (bytes"},
    };
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        fp = fopen(cut, "wb");
        fwrite(bytes, 1, cuts[k].at, fp);
        fclose(fp);
        CHECK(eco_sim_load(back, cut, &f.fail) != 0);
        char holds[64];
        snprintf(holds, sizeof holds, "the file holds %zu bytes and ends inside ", cuts[k].at);
        CHECK_STR_CONTAINS(f.fail.msg, "the ecology state is cut short");
        CHECK_STR_CONTAINS(f.fail.msg, holds);
        CHECK_STR_CONTAINS(f.fail.msg, cuts[k].part);
        CHECK(!strstr(f.fail.msg, "checksum does not match") && !strstr(f.fail.msg, "format 0") &&
              !strstr(f.fail.msg, "holds 0 species"));
    }
    /* bytes after the checksum */
    fp = fopen(cut, "wb");
    fwrite(bytes, 1, size, fp);
    fputs("xyz", fp);
    fclose(fp);
    CHECK(eco_sim_load(back, cut, &f.fail) != 0);
    char msg[160];
    snprintf(msg, sizeof msg, "ends with its checksum at byte %zu, but the file holds %zu bytes", size, size + 3);
    CHECK_STR_CONTAINS(f.fail.msg, msg);
    /* a whole file whose checksum does not match: damaged, not cut short */
    bytes[size - 1] ^= 0x40;
    fp = fopen(cut, "wb");
    fwrite(bytes, 1, size, fp);
    fclose(fp);
    CHECK(eco_sim_load(back, cut, &f.fail) != 0);
    CHECK_STR_CONTAINS(f.fail.msg, "is damaged: it is whole");
    CHECK_INT(back->year, 0); /* nothing taken over */
    remove(cut), remove(path);
    eco_sim_free(run), eco_sim_free(back);
    free(hf.z);
    fixture_host_release(&f);
}

/* 1 when the file at path holds exactly `text`. */
static int file_holds(const char *path, const char *text)
{
    char buf[256] = "";
    FILE *fp = fopen(path, "rb");
    size_t n = fp ? fread(buf, 1, sizeof buf - 1, fp) : 0;
    if (fp) fclose(fp);
    return n == strlen(text) && !memcmp(buf, text, n);
}

/* Entries of the work folder. */
static int work_entries(void)
{
    int n = 0;
    DIR *d = opendir(work_dir());
    for (struct dirent *e; d && (e = readdir(d));) n += e->d_name[0] != '.';
    if (d) closedir(d);
    return n;
}

TEST(save_never_writes_through_a_planted_link)
{
    fixture_host f;
    fixture_host_init(&f, 9);
    sylva_heightfield hf = fixture_heightfield(21, 21, 0, 0, 2, hills);
    eco_sim *s = grown(&f, &hf, 1, 10), *back = grown(&f, &hf, 1, 0);
    char victim[1200], state[1200], planted[1300];
    snprintf(victim, sizeof victim, "%s", work_file("victim.txt", "keep me\n"));
    snprintf(state, sizeof state, "%s", work_path("state.bin"));
    /* A link at the name the temporary file used to take (the state's path, ".tmp-", the pid). */
    snprintf(planted, sizeof planted, "%s.tmp-%ld", state, (long)getpid());
    CHECK(symlink(victim, planted) == 0);
    CHECK_INT(eco_sim_save(s, state, &f.fail), 0);
    CHECK(file_holds(victim, "keep me\n"));
    struct stat st;
    CHECK(lstat(state, &st) == 0 && S_ISREG(st.st_mode));
    CHECK(s && back && eco_sim_load(back, state, &f.fail) == 0 && fixture_same_plants(s, back));
    /* A link planted at the state's own name is replaced, not written through. */
    unlink(state);
    CHECK(symlink(victim, state) == 0);
    CHECK_INT(eco_sim_save(s, state, &f.fail), 0);
    CHECK(file_holds(victim, "keep me\n"));
    CHECK(lstat(state, &st) == 0 && S_ISREG(st.st_mode));
    CHECK_INT(work_entries(), 3); /* victim, link, state: no temporary left */
    /* A save that cannot take its name (a folder stands there) removes its temporary. */
    char folder[1200];
    snprintf(folder, sizeof folder, "%s", work_path("folder"));
    CHECK(mkdir(folder, 0700) == 0);
    CHECK_INT(eco_sim_save(s, folder, &f.fail), SYLVA_ERR_IO);
    CHECK_STR_CONTAINS(f.fail.msg, "cannot write the ecology state");
    CHECK_INT(work_entries(), 4);
    eco_sim_free(s), eco_sim_free(back);
    free(hf.z);
    fixture_host_release(&f);
}

TEST(growth_area_keeps_plants_inside)
{
    fixture_host f;
    fixture_host_init(&f, 2);
    sylva_heightfield hf = small_flat();
    eco_config cfg = fixture_config(30); /* 2 m patches */
    cfg.area[0] = 5, cfg.area[1] = 10, cfg.area[2] = 14, cfg.area[3] = 19;
    const char *names[] = {"hazel"}; /* the generic profile */
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, NULL, &s), 0);
    CHECK_INT(s->n_growable, 100);
    run_years(&f, s, 30);
    CHECK(s->pop[0].n > 20);
    for (uint32_t q = 0; q < s->pop[0].n; q++) {
        const eco_plant *p = &s->pop[0].plants[q];
        CHECK(p->x >= 10 && p->x <= 30 && p->y >= 20 && p->y <= 40);
    }
    eco_sim_free(s);
    /* a mask: only the western half */
    double mask[2] = {1, 0};
    cfg = fixture_config(30);
    cfg.mask = mask, cfg.mask_rows = 1, cfg.mask_cols = 2;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, NULL, &s), 0);
    CHECK_INT(s->n_growable, 15 * 30);
    run_years(&f, s, 20);
    for (uint32_t q = 0; q < s->pop[0].n; q++) CHECK(s->pop[0].plants[q].x <= 30);
    eco_sim_free(s);
    free(hf.z);
    fixture_host_release(&f);
}

/* Plants per patch in columns [i0, i1] of s's patch grid (i west to east). */
static double column_density(const eco_sim *s, uint32_t i0, uint32_t i1)
{
    uint32_t n = 0;
    for (uint32_t q = 0; q < s->pop[0].n; q++) {
        uint32_t i = s->pop[0].plants[q].patch % s->terrain.ni;
        n += i >= i0 && i <= i1;
    }
    return (double)n / ((i1 - i0 + 1) * (double)s->terrain.nk);
}

/* The growth area's edge fades: across a 30 m band east of a growth area the plants thin out
 * step by step instead of stopping at the rectangle's side, and none grow past the band. */
TEST(growth_area_edge_fades)
{
    fixture_host f;
    fixture_host_init(&f, 2);
    sylva_heightfield hf = fixture_heightfield(201, 161, 0, 0, 1, flat); /* 200 x 160 m */
    eco_config cfg = fixture_config(100);                                 /* 2 m patches, 100 x 80 */
    cfg.area[0] = 0, cfg.area[1] = 0, cfg.area[2] = 49, cfg.area[3] = 79; /* x < 100 m */
    cfg.edge_fade = 30;
    /* quick to seed, so that the stand fills the area within the run */
    const char *keys[] = {"t_m", "t_a", "t_f", "r_s", "g_s", NULL};
    const double vals[] = {3, 30, 300, 4, 4};
    fixture_block *b = fixture_species_block(keys, vals);
    const char *names[] = {"tree"};
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, &b, &s), 0);
    if (!s) goto done;
    /* the chance itself: 1 inside, falling with distance, 0 past 1.5 bands whatever the noise */
    CHECK_NEAR(eco_edge_chance(0, 30, 0.9), 1, 0);
    CHECK(eco_edge_chance(10, 30, 0.5) > eco_edge_chance(20, 30, 0.5));
    CHECK_NEAR(eco_edge_chance(52.51, 30, 0.0), 0, 0);
    run_years(&f, s, 40);
    double inside = column_density(s, 30, 49), near = column_density(s, 51, 56), far = column_density(s, 57, 63),
           beyond = column_density(s, 77, 99);
    fprintf(stderr, "plants per patch: inside %.3f, 4-14 m out %.3f, 16-28 m out %.3f, beyond 54 m %.3f\n", inside,
            near, far, beyond);
    CHECK(inside > 0.2);
    CHECK(near > 0.2 * inside && near < 1.5 * inside);
    CHECK(far > 0.02 * inside && far < near);
    CHECK_NEAR(beyond, 0, 0);
    /* no step: between neighbouring 4-column windows (8 m) the density never drops by half of
     * inside's (a hard edge drops by all of it) */
    for (uint32_t i = 40; i + 7 < 80; i++) {
        double a = column_density(s, i, i + 3), e = column_density(s, i + 4, i + 7);
        if (a - e > 0.5 * inside) fprintf(stderr, "a step at column %u: %.3f to %.3f\n", i + 4, a, e);
        CHECK(a - e <= 0.5 * inside);
    }
    eco_sim_free(s);
done:
    free(b), free(hf.z);
    fixture_host_release(&f);
}

TEST(never_in_water)
{
    fixture_host f;
    fixture_host_init(&f, 4);
    sylva_heightfield hf = fixture_heightfield(31, 31, 0, 0, 2, hills);
    eco_config cfg = fixture_config(30);
    cfg.factors.water_altitude = 0.4;
    const char *names[] = {"hazel"};
    eco_sim *s = NULL;
    CHECK_INT(fixture_sim(&f, &hf, &cfg, 1, names, NULL, &s), 0);
    uint32_t water = 0;
    for (size_t p = 0; p < 900; p++) water += s->terrain.water[p];
    CHECK(water > 100);
    run_years(&f, s, 70);
    CHECK(s->pop[0].n > 50);
    for (uint32_t q = 0; q < s->pop[0].n; q++) CHECK(!eco_in_water(&s->terrain, s->pop[0].plants[q].x, s->pop[0].plants[q].y));
    eco_sim_free(s);
    free(hf.z);
    fixture_host_release(&f);
}

TEST(bad_growth_area_and_species)
{
    fixture_host f;
    fixture_host_init(&f, 1);
    sylva_heightfield hf = small_flat();
    eco_config cfg = fixture_config(30);
    cfg.area[0] = 0, cfg.area[1] = 0, cfg.area[2] = 30, cfg.area[3] = 5; /* i up to 29 */
    const char *names[] = {"shrub", "beech"};
    eco_sim *s = NULL;
    CHECK(fixture_sim(&f, &hf, &cfg, 2, names, NULL, &s) != 0);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(f.fail.msg, "reaches outside the terrain's 30 x 30 patches");
    cfg = fixture_config(30);
    sylva_species_info info[2] = {{.size = sizeof info[0], .name = "shrub", .model_height = 2},
                                  {.size = sizeof info[1], .name = "beech", .model_height = 20}};
    sylva_ecology_request req = {.size = sizeof req, .terrain = &hf, .species = info, .n_species = 2};
    plugin_params top = fixture_reader(&f, NULL);
    CHECK(eco_sim_new(&f.rnd, &top, &cfg, "beech, bech", &req, &s, &f.fail) != 0);
    CHECK_STR_CONTAINS(f.fail.msg, "unknown species 'bech'; the scene's species are shrub, beech");
    CHECK_INT(eco_sim_new(&f.rnd, &top, &cfg, "beech", &req, &s, &f.fail), 0);
    CHECK_INT(s->n_species, 1);
    CHECK_INT(s->request_index[0], 1);
    eco_sim_free(s);
    /* the limit on living plants is an error, never a crash */
    cfg.max_plants = 50;
    CHECK_INT(eco_sim_new(&f.rnd, &top, &cfg, NULL, &req, &s, &f.fail), 0);
    int rc = 0;
    for (int y = 0; y < 200 && !rc; y++) rc = eco_sim_step(s, &f.rnd, &f.fail);
    CHECK_INT(rc, SYLVA_ERR_LIMIT);
    CHECK_STR_CONTAINS(f.fail.msg, "max_plants = 50");
    eco_sim_free(s);
    free(hf.z);
    fixture_host_release(&f);
}

TEST_LIST(TEST_CASE(dominance_grid_equals_all_pairs), TEST_CASE(single_species_self_thins),
          TEST_CASE(species_outside_its_optimum_dies_out), TEST_CASE(same_seeds_same_plants_any_threads),
          TEST_CASE(stream_seeds_change_only_their_purpose), TEST_CASE(save_load_continue_equals_uninterrupted),
          TEST_CASE(save_never_writes_through_a_planted_link), TEST_CASE(cut_short_state_says_where),
          TEST_CASE(growth_area_keeps_plants_inside), TEST_CASE(growth_area_edge_fades), TEST_CASE(never_in_water), TEST_CASE(bad_growth_area_and_species))
