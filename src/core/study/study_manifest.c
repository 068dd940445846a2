/* study_manifest.c — a product's record: its text, its check and its writing (study_manifest.h). */
#include "study/study_manifest.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "io/atomic_file.h"

/* Every field of the camera that the render reads, as exact decimal text. */
static int camera_text(const camera_settings *c, char *out, size_t n)
{
    return snprintf(out, n,
                    "position %.17g %.17g %.17g\neye_above_ground %d %.17g\nlook_at %d %.17g %.17g %.17g %d %.17g\n"
                    "direction %.17g %.17g %.17g\nup %.17g %.17g %.17g\nroll %.17g\nlens %d %.17g %.17g %.17g "
                    "%.17g %.17g\nfocus %.17g %.17g %.17g\n",
                    c->position[0], c->position[1], c->position[2], c->eye_ground.given, c->eye_ground.above,
                    c->has_look_at, c->look_at[0], c->look_at[1], c->look_at[2], c->look_at_ground.given,
                    c->look_at_ground.above, c->direction[0], c->direction[1], c->direction[2], c->up[0], c->up[1],
                    c->up[2], c->roll_deg, c->cylindrical, c->fov_deg, c->focal_length_mm, c->sensor_width_mm,
                    c->k1, c->k2, c->f_number, c->focus_distance, c->vignette);
}

void study_manifest_text(const study_record *r, char out[STUDY_MANIFEST_MAX])
{
    int n = snprintf(out, STUDY_MANIFEST_MAX,
                     "sylva study record 1\nsylva %s\nscene %016llx\nviewpoint %s\nproduct %s\nframe %s\n"
                     "size %u %u\nspp %u\nseed %llu\nseason_day %u\n",
                     SYLVA_VERSION, (unsigned long long)r->scene_digest, r->viewpoint, r->product, r->frame, r->width,
                     r->height, r->spp, (unsigned long long)r->seed, r->season_day);
    if (n > 0 && n < STUDY_MANIFEST_MAX) n += camera_text(r->camera, out + n, STUDY_MANIFEST_MAX - (size_t)n);
    if (r->extra && n > 0 && n < STUDY_MANIFEST_MAX) snprintf(out + n, STUDY_MANIFEST_MAX - (size_t)n, "%s", r->extra);
}

static int regular_file(const char *path)
{
    struct stat st;
    return !stat(path, &st) && S_ISREG(st.st_mode);
}

int study_manifest_current(const char *path, const char *text, const char *png, const char *exr)
{
    if (!regular_file(png) || !regular_file(exr)) return 0;
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    char held[STUDY_MANIFEST_MAX + 1];
    size_t n = fread(held, 1, sizeof held, f);
    fclose(f);
    return n == strlen(text) && !memcmp(held, text, n);
}

int study_manifest_write(const char *path, const char *text, err_buf *err)
{
    atomic_file af = {.fd = -1};
    FILE *f = atomic_file_open_stream(&af, path, err);
    if (!f) return -1;
    if (fputs(text, f) == EOF) {
        atomic_file_abort(&af);
        return err_fail(err, ERR_OUTPUT, "%s: cannot write the study's record", path);
    }
    return atomic_file_commit(&af, err);
}
