/* study_index.c — DIR/index.html (study_index.h): the viewpoints' places and nearest structures,
 * the files found in each viewpoint's folder, the map with its marks, written as one page. */
#include "study/study_index.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io/atomic_file.h"
#include "scene_file/host_schema.h"
#include "study/study_frames.h"
#include "util/html_text.h"

#define MARK_RADIUS 11 /* pixels of a viewpoint's mark on the key map */
/* On the map page (ztv/ztv_map.h: A3 landscape, 420 mm across), a viewpoint is a numbered red dot
 * 2 mm across with a white rim to 2.2 mm: the page's mark is a ring just round it, its number
 * the page's own. */
#define MAP_PAGE_MM 420.0
#define MAP_DOT_RING_MM 2.3

/* The products whose PNG is a view (PRODUCT_FRAME.png), in the order the page lists them. */
static const study_product views_rendered[] = {STUDY_EXISTING, STUDY_PROPOSED, STUDY_WIRELINE};
#define N_RENDERED (sizeof views_rendered / sizeof *views_rendered)

/* A viewpoint as the page shows it. */
typedef struct index_view {
    const scene_viewpoint *v;
    uint32_t number;
    double e, n;               /* map coordinates */
    const char *nearest;       /* the nearest structure's name, or NULL: no structure */
    double distance, bearing;  /* metres, degrees from grid north */
} index_view;

/* Where the map's pixels are: a world file's six numbers (x = a col + c, y = e row + f at pixel
 * centres), the picture's size. */
typedef struct index_map {
    char picture[64];          /* relative to DIR, "" when the study has no map */
    int georeferenced;
    double a, e, c, f;
    uint32_t width, height;
} index_map;

static int is_file(const char *dir, const char *rel)
{
    char path[ATOMIC_PATH_MAX];
    struct stat st;
    if (snprintf(path, sizeof path, "%s/%s", dir, rel) >= (int)sizeof path) return 0;
    return !stat(path, &st) && S_ISREG(st.st_mode);
}

/* A relative URL: every byte but letters, digits, '-', '.', '_', '~' and '/' percent-encoded. */
static void put_url(FILE *f, const char *s)
{
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') || strchr("-._~/", *p))
            fputc(*p, f);
        else
            fprintf(f, "%%%02X", *p);
    }
}

static void nearest_structure(const scene_file *sf, index_view *iv)
{
    iv->nearest = NULL, iv->distance = INFINITY, iv->bearing = NAN;
    const double *p = iv->v->camera.position;
    for (uint32_t k = 0; k < sf->n_objects; k++) {
        const object_spec *o = &sf->objects[k];
        if (!o->development) continue;
        double dx = o->position[0] - p[0], dy = o->position[1] - p[1], d = hypot(dx, dy);
        if (d >= iv->distance) continue;
        iv->nearest = o->name ? o->name : "", iv->distance = d;
        double b = atan2(dx, dy) * 180.0 / M_PI;
        iv->bearing = b < 0 ? b + 360.0 : b;
    }
}

/* The width and height of a PNG from its header; 0 when it is none. */
static int png_size(const char *path, uint32_t *w, uint32_t *h)
{
    unsigned char head[24];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(head, 1, sizeof head, f) : 0;
    if (f) fclose(f);
    if (n < 24 || memcmp(head, "\x89PNG\r\n\x1a\n", 8) || memcmp(head + 12, "IHDR", 4)) return -1;
    *w = (uint32_t)head[16] << 24 | (uint32_t)head[17] << 16 | (uint32_t)head[18] << 8 | head[19];
    *h = (uint32_t)head[20] << 24 | (uint32_t)head[21] << 16 | (uint32_t)head[22] << 8 | head[23];
    return 0;
}

/* The map picture: the screened mode's, else bare earth's; georeferenced by its world file. */
static void find_map(const char *dir, index_map *m)
{
    static const char *const modes[] = {"all", "vegetation", "canopy", "bare"};
    memset(m, 0, sizeof *m);
    char path[ATOMIC_PATH_MAX];
    for (size_t k = 0; k < sizeof modes / sizeof *modes && !m->picture[0]; k++) {
        snprintf(m->picture, sizeof m->picture, "ztv/ztv_%s.png", modes[k]);
        snprintf(path, sizeof path, "%s/%s", dir, m->picture);
        if (!is_file(dir, m->picture) || png_size(path, &m->width, &m->height)) m->picture[0] = '\0';
    }
    if (!m->picture[0]) return;
    snprintf(path, sizeof path, "%s/%.*sgw", dir, (int)strlen(m->picture) - 2, m->picture);
    FILE *f = fopen(path, "r");
    double v[6];
    int got = 0;
    while (f && got < 6 && fscanf(f, "%lf", &v[got]) == 1) got++;
    if (f) fclose(f);
    if (got == 6 && v[0] != 0 && v[3] != 0 && v[1] == 0 && v[2] == 0)
        m->georeferenced = 1, m->a = v[0], m->e = v[3], m->c = v[4], m->f = v[5];
}

/* The first file of a viewpoint there is, for its mark's link: a sheet, else an image. */
static int first_file(const char *dir, const index_view *iv, char *out, size_t n)
{
    static const char *const exts[] = {"pdf", "png"};
    for (int f = 0; f < (int)STUDY_FRAMES; f++)
        for (int e = 0; e < 2; e++) {
            snprintf(out, n, "%s/sheet_%s.%s", iv->v->name, study_frame_of(f)->name, exts[e]);
            if (is_file(dir, out)) return 0;
        }
    for (int f = 0; f < (int)STUDY_FRAMES; f++)
        for (size_t p = 0; p < N_RENDERED; p++) {
            snprintf(out, n, "%s/%s_%s.png", iv->v->name, host_study_products[views_rendered[p]],
                     study_frame_of(f)->name);
            if (is_file(dir, out)) return 0;
        }
    return -1;
}

/* A mark at (x, y) in the SVG's units, linked to the viewpoint's first file (or its row): a numbered
 * disc, or (ring 1) a ring round the number the picture shows. */
static void put_mark(FILE *f, const char *dir, const index_view *iv, double x, double y, double r, int ring)
{
    char target[ATOMIC_PATH_MAX];
    fputs("<a href=\"", f);
    if (!first_file(dir, iv, target, sizeof target)) put_url(f, target);
    else fprintf(f, "#vp%u", iv->number);
    fprintf(f, "\"><title>");
    html_text(f, iv->v->name);
    fprintf(f, "</title><circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" class=\"%s\"/>", x, y, r, ring ? "ring" : "mark");
    if (!ring)
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%.1f\" class=\"num\">%u</text>", x, y + 0.35 * r, r * 1.1,
                iv->number);
    fputs("</a>\n", f);
}

static void put_map_picture(FILE *f, const char *dir, const index_map *m, const index_view *views, uint32_t n)
{
    fprintf(f, "<svg class=\"map\" viewBox=\"0 0 %u %u\" width=\"%u\" role=\"img\" aria-label=\"ZTV map\">\n"
               "<image href=\"", m->width, m->height, m->width);
    put_url(f, m->picture);
    fprintf(f, "\" x=\"0\" y=\"0\" width=\"%u\" height=\"%u\"/>\n", m->width, m->height);
    double r = MAP_DOT_RING_MM * m->width / MAP_PAGE_MM;
    for (uint32_t k = 0; k < n; k++) {
        double x = (views[k].e - m->c) / m->a + 0.5, y = (views[k].n - m->f) / m->e + 0.5;
        if (x >= 0 && y >= 0 && x <= m->width && y <= m->height) put_mark(f, dir, &views[k], x, y, r, 1);
    }
    fputs("</svg>\n", f);
    char pdf[sizeof m->picture];
    snprintf(pdf, sizeof pdf, "%.*spdf", (int)strlen(m->picture) - 3, m->picture);
    fputs("<p>The map page at full size: <a href=\"", f);
    put_url(f, m->picture);
    fputs("\">PNG</a>", f);
    if (is_file(dir, pdf)) {
        fputs(", <a href=\"", f);
        put_url(f, pdf);
        fputs("\">PDF</a>", f);
    }
    fputs(" (A3). Each ringed viewpoint links to its sheet, else to its first view.</p>\n", f);
}

/* A scale bar of a round length near `about` metres (1, 2 or 5 times a power of ten) in the key
 * map's lower left corner, at scale pixels a metre, and a north arrow (grid north: up). */
static void put_scale_bar(FILE *f, double about, double scale)
{
    double ten = pow(10, floor(log10(about))), step = about / ten >= 5 ? 5 * ten : about / ten >= 2 ? 2 * ten : ten;
    double len = step * scale;
    fprintf(f, "<path d=\"M20 770 h%.1f M20 764 v12 M%.1f 764 v12\" stroke=\"#000\" stroke-width=\"2\"/>\n"
               "<text x=\"20\" y=\"758\" class=\"name\">%g %s</text>\n"
               "<path d=\"M770 60 l-8 16 h16 z\" fill=\"#000\"/><text x=\"770\" y=\"50\" class=\"name\" "
               "text-anchor=\"middle\">N</text>\n",
            len, 20 + len, step >= 1000 ? step / 1000 : step, step >= 1000 ? "km" : "m");
}

/* A key map drawn here: the structures as triangles and the viewpoints' marks, north up, framed
 * round them all with a margin, with a scale bar and a north arrow. */
static void put_key_map(FILE *f, const scene_file *sf, const char *dir, const double origin[3],
                        const index_view *views, uint32_t n)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t k = 0; k < n; k++)
        lo[0] = fmin(lo[0], views[k].e), lo[1] = fmin(lo[1], views[k].n), hi[0] = fmax(hi[0], views[k].e),
        hi[1] = fmax(hi[1], views[k].n);
    for (uint32_t k = 0; k < sf->n_objects; k++) {
        if (!sf->objects[k].development) continue;
        double e = origin[0] + sf->objects[k].position[0], nn = origin[1] + sf->objects[k].position[1];
        lo[0] = fmin(lo[0], e), lo[1] = fmin(lo[1], nn), hi[0] = fmax(hi[0], e), hi[1] = fmax(hi[1], nn);
    }
    double span = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), 1.0), margin = 0.1 * span;
    double size = span + 2 * margin, scale = 800.0 / size, r = MARK_RADIUS;
    fprintf(f, "<svg class=\"map\" viewBox=\"0 0 800 800\" width=\"800\" role=\"img\" aria-label=\"key map\">\n"
               "<rect width=\"800\" height=\"800\" fill=\"#eef2e6\" stroke=\"#666\"/>\n");
#define PX(e) (((e) - lo[0] + margin) * scale)
#define PY(nn) ((hi[1] + margin - (nn)) * scale)
    for (uint32_t k = 0; k < sf->n_objects; k++) {
        if (!sf->objects[k].development) continue;
        double x = PX(origin[0] + sf->objects[k].position[0]), y = PY(origin[1] + sf->objects[k].position[1]);
        fprintf(f, "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"#000\"/>\n<text x=\"%.1f\" y=\"%.1f\" "
                   "class=\"name\">", x, y - 7, x - 6, y + 5, x + 6, y + 5, x + 9, y + 4);
        html_text(f, sf->objects[k].name);
        fputs("</text>\n", f);
    }
    for (uint32_t k = 0; k < n; k++) put_mark(f, dir, &views[k], PX(views[k].e), PY(views[k].n), r, 0);
    put_scale_bar(f, size / 4, scale);
#undef PX
#undef PY
    fputs("</svg>\n", f);
}

static void put_links(FILE *f, const char *dir, const index_view *iv)
{
    char rel[ATOMIC_PATH_MAX];
    int any = 0;
    static const char *const exts[] = {"pdf", "png"};
    for (int fr = 0; fr < (int)STUDY_FRAMES; fr++) {
        const char *frame = study_frame_of(fr)->name;
        for (int e = 0; e < 2; e++) {
            snprintf(rel, sizeof rel, "%s/sheet_%s.%s", iv->v->name, frame, exts[e]);
            if (!is_file(dir, rel)) continue;
            fputs(any++ ? " <a href=\"" : "<a href=\"", f);
            put_url(f, rel);
            fprintf(f, "\">sheet %s (%s)</a>", frame, exts[e]);
        }
        for (size_t p = 0; p < N_RENDERED; p++) {
            const char *product = host_study_products[views_rendered[p]];
            snprintf(rel, sizeof rel, "%s/%s_%s.png", iv->v->name, product, frame);
            if (!is_file(dir, rel)) continue;
            fputs(any++ ? " <a href=\"" : "<a href=\"", f);
            put_url(f, rel);
            fprintf(f, "\">%s %s</a>", product, frame);
        }
    }
    if (!any) fputs("none yet", f);
}

static void put_table(FILE *f, const char *dir, const index_view *views, uint32_t n)
{
    fputs("<table>\n<tr><th>No.</th><th>Viewpoint</th><th>Easting</th><th>Northing</th><th>Nearest structure</th>"
          "<th>Distance (m)</th><th>Bearing (&deg;)</th><th>Files</th></tr>\n", f);
    for (uint32_t k = 0; k < n; k++) {
        const index_view *iv = &views[k];
        fprintf(f, "<tr id=\"vp%u\"><td>%u</td><td>", iv->number, iv->number);
        html_text(f, iv->v->name);
        fprintf(f, "</td><td>%.0f</td><td>%.0f</td><td>", iv->e, iv->n);
        if (iv->nearest) {
            html_text(f, iv->nearest);
            fprintf(f, "</td><td>%.0f</td><td>%.1f</td><td>", iv->distance, iv->bearing);
        } else {
            fputs("&ndash;</td><td>&ndash;</td><td>&ndash;</td><td>", f);
        }
        put_links(f, dir, iv);
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n", f);
}

static const char style[] =
    "<style>\n"
    "body{font-family:sans-serif;margin:24px;color:#222;background:#fff}\n"
    "h1{font-size:22px}h2{font-size:17px;margin-top:28px}\n"
    ".map{max-width:100%;height:auto;border:1px solid #999}\n"
    ".mark{fill:#fff;stroke:#000;stroke-width:2}.num{text-anchor:middle;font-weight:bold;fill:#000}\n"
    ".name{font-size:12px;fill:#000}\n"
    ".ring{fill:#ffd400;fill-opacity:0;stroke:#ffd400;stroke-width:4}\n"
    "a:hover .mark{fill:#ffd400}a:hover .ring{fill-opacity:0.6}\n"
    "table{border-collapse:collapse;margin-top:12px}td,th{border:1px solid #bbb;padding:4px 8px;text-align:left}\n"
    "th{background:#eee}tr:target{background:#fff3b0}\n"
    "</style>\n";

static int write_page(FILE *f, const scene_file *sf, const char *dir, const double origin[3],
                      const index_view *views, uint32_t n)
{
    const char *base = strrchr(sf->path, '/');
    base = base ? base + 1 : sf->path;
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Study: ", f);
    html_text(f, base);
    fprintf(f, "</title>\n%s</head>\n<body>\n<h1>Study: ", style);
    html_text(f, base);
    fprintf(f, "</h1>\n<p>%u viewpoint%s", n, n == 1 ? "" : "s");
    if (sf->site.crs_name) {
        fputs("; coordinates in ", f);
        html_text(f, sf->site.crs_name);
    }
    fputs(".</p>\n", f);
    index_map m;
    find_map(dir, &m);
    fputs("<h2>Zone of theoretical visibility</h2>\n", f);
    if (m.picture[0] && m.georeferenced) put_map_picture(f, dir, &m, views, n);
    else put_key_map(f, sf, dir, origin, views, n);
    if (m.picture[0] && !m.georeferenced) { /* the map itself, below the key map */
        fputs("<p><a href=\"", f);
        put_url(f, m.picture);
        fputs("\"><img class=\"map\" alt=\"ZTV map\" src=\"", f);
        put_url(f, m.picture);
        fprintf(f, "\" width=\"%u\"></a></p>\n", m.width);
    }
    fputs("<h2>Viewpoints</h2>\n", f);
    put_table(f, dir, views, n);
    fputs("</body>\n</html>\n", f);
    return ferror(f) ? -1 : 0;
}

/* 1 when the file at path holds exactly the n bytes of text. */
static int same_bytes(const char *path, const char *text, size_t n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    int same = 1;
    char buf[4096];
    size_t at = 0, got;
    while (same && (got = fread(buf, 1, sizeof buf, f)) > 0) {
        same = at + got <= n && !memcmp(buf, text + at, got);
        at += got;
    }
    fclose(f);
    return same && at == n;
}

int study_index_write(const scene_file *sf, const study_views *views, const char *dir, err_buf *err)
{
    double origin[3] = {0, 0, 0};
    if (sf->site.crs_wkt) memcpy(origin, sf->site.origin, sizeof origin);
    index_view *iv = calloc(views->n ? views->n : 1, sizeof *iv); /* owned here */
    if (!iv) return err_nomem(err, "out of memory for the study's index");
    for (uint32_t k = 0; k < views->n; k++) {
        iv[k] = (index_view){.v = views->views[k], .number = scene_file_viewpoint_number(sf, views->views[k]),
                             .e = origin[0] + views->views[k]->camera.position[0],
                             .n = origin[1] + views->views[k]->camera.position[1]};
        nearest_structure(sf, &iv[k]);
    }
    char path[ATOMIC_PATH_MAX], *page = NULL; /* page: owned here (open_memstream) */
    size_t len = 0;
    int rc = snprintf(path, sizeof path, "%s/index.html", dir) >= (int)sizeof path
                 ? err_fail(err, ERR_USAGE, "%s: the path is too long", dir) : 0;
    FILE *mem = rc ? NULL : open_memstream(&page, &len);
    if (!rc && !mem) rc = err_nomem(err, "out of memory for the study's index");
    if (!rc) {
        int failed = write_page(mem, sf, dir, origin, iv, views->n);
        failed |= fclose(mem) != 0;
        if (failed) rc = err_nomem(err, "out of memory for the study's index");
    }
    if (!rc && !same_bytes(path, page, len)) { /* an index that says the same is left as it is */
        atomic_file af = {.fd = -1};
        FILE *f = atomic_file_open_stream(&af, path, err);
        if (!f) rc = -1;
        else if (fwrite(page, 1, len, f) != len) {
            atomic_file_abort(&af);
            rc = err_fail(err, ERR_OUTPUT, "%s: cannot write the study's index", path);
        } else {
            rc = atomic_file_commit(&af, err);
        }
    }
    free(page);
    free(iv);
    return rc;
}
