/* exr_write.c — the film's EXR output through the OpenEXR Core C API: one scanline part,
 * ZIP compression (zlib at its fastest level over blocks of 16 scanlines), line order increasing y. R, G, B are
 * converted to half here (half_float.h) when the frame asks for it, so the rounding is ours;
 * the other float layers stay FLOAT and the ids are UINT. The bytes go through our own file
 * descriptor to a temporary name (atomic_file.h) that is renamed into place only after
 * exr_finish has written the chunk table; any failure removes the temporary file. */
#include "io/exr_write.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <openexr.h>

#include "io/atomic_file.h"
#include "io/half_float.h"

/* zlib's fastest level: a render's float layers are mostly noise in their low bits, which no
 * level compresses, so the default level (6) makes the files barely smaller (3.3 against 3.4 MB
 * for a 480 x 320 frame of the wind farm) for more time. */
enum { EXR_ZIP_LEVEL = 1 };

/* EXR_MAX_SIDE keeps a scanline's byte stride (12 bytes per pixel at most) within int32. */
enum { EXR_MAX_CHANNELS = 18, EXR_MAX_SIDE = 1 << 24 };

/* The OpenEXR context's user data: where the bytes go and where the first error is told. */
typedef struct exr_stream {
    int fd;
    const char *path; /* the final path, for messages */
    err_buf *err;
    int reported;     /* err holds a message from the library */
} exr_stream;

/* One output channel: where its value for pixel (0, 0) lives and how far apart pixels are. */
typedef struct exr_channel_src {
    const char *name;
    exr_pixel_type_t type;
    exr_perceptual_treatment_t percept;
    const uint8_t *base;  /* NULL for R, G, B stored as half: those come from the chunk buffer */
    int32_t pixel_stride; /* bytes */
    int rgb_index;        /* 0..2 for a half R, G, B channel, else -1 */
} exr_channel_src;

/* The stream exr_write is writing on this thread, for the error handler: OpenEXRCore calls the
 * handler while it holds the context's lock (a failed write inside exr_encoding_run, say), and
 * exr_get_user_data takes that lock again, which would wait for ever. */
static _Thread_local exr_stream *exr_stream_now;

static void exr_on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    exr_stream *s = exr_stream_now;
    if (!s || s->reported) return;
    s->reported = 1;
    err_set(s->err, "%s: OpenEXR could not write the file: %s (%s)", s->path, msg,
            exr_get_error_code_as_string(code));
}

static int64_t exr_stream_write(exr_const_context_t ctxt, void *userdata, const void *buffer,
                                uint64_t sz, uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    exr_stream *s = userdata;
    const uint8_t *bytes = buffer;
    uint64_t done = 0;
    while (done < sz) {
        ssize_t n = pwrite(s->fd, bytes + done, (size_t)(sz - done), (off_t)(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            error_cb(ctxt, EXR_ERR_WRITE_IO, "writing %llu bytes at offset %llu failed: %s",
                     (unsigned long long)(sz - done), (unsigned long long)(offset + done),
                     n < 0 ? strerror(errno) : "nothing was written");
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)sz;
}

/* Sets err for rc unless the error handler already gave the library's own sentence. */
static int exr_fail(exr_stream *s, exr_result_t rc, const char *step)
{
    if (!s->reported)
        err_set(s->err, "%s: OpenEXR could not write the file (%s): %s", s->path, step,
                exr_get_default_error_message(rc));
    s->reported = 1;
    return -1;
}

static int exr_frame_channels(const exr_frame *f, exr_channel_src *ch)
{
    static const char *const rgb_names[3] = {"R", "G", "B"};
    static const char *const normal_names[3] = {"N.X", "N.Y", "N.Z"};
    static const char *const albedo_names[3] = {"albedo.R", "albedo.G", "albedo.B"};
    static const char *const development_names[3] = {"development.R", "development.G", "development.B"};
    int n = 0;
    for (int c = 0; c < 3 && f->rgb; c++) {
        ch[n++] = (exr_channel_src){rgb_names[c],
                                    f->rgb_half ? EXR_PIXEL_HALF : EXR_PIXEL_FLOAT,
                                    EXR_PERCEPTUALLY_LOGARITHMIC,
                                    f->rgb_half ? NULL : (const uint8_t *)(f->rgb + c),
                                    f->rgb_half ? 3 * (int32_t)sizeof(uint16_t)
                                                : 3 * (int32_t)sizeof(float),
                                    f->rgb_half ? c : -1};
    }
    if (f->depth)
        ch[n++] = (exr_channel_src){"Z", EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)f->depth, sizeof(float), -1};
    for (int c = 0; c < 3 && f->normal; c++)
        ch[n++] = (exr_channel_src){normal_names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)(f->normal + c), 3 * sizeof(float), -1};
    for (int c = 0; c < 3 && f->albedo; c++)
        ch[n++] = (exr_channel_src){albedo_names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)(f->albedo + c), 3 * sizeof(float), -1};
    if (f->instance_id)
        ch[n++] = (exr_channel_src){"id.instance", EXR_PIXEL_UINT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)f->instance_id, sizeof(uint32_t), -1};
    if (f->species_id)
        ch[n++] = (exr_channel_src){"id.species", EXR_PIXEL_UINT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)f->species_id, sizeof(uint32_t), -1};
    if (f->object_id)
        ch[n++] = (exr_channel_src){"id.object", EXR_PIXEL_UINT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)f->object_id, sizeof(uint32_t), -1};
    if (f->development)
        ch[n++] = (exr_channel_src){"development.A", EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)f->development, sizeof(float), -1};
    for (int c = 0; c < 3 && f->development_rgb; c++)
        ch[n++] = (exr_channel_src){development_names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR,
                                    (const uint8_t *)(f->development_rgb + c), 3 * sizeof(float), -1};
    return n;
}

/* Defines the part, writes the header and every chunk. The caller finishes the context. */
static int exr_write_part(exr_context_t ctx, exr_stream *s, const exr_frame *f,
                          const exr_channel_src *ch, int n_ch)
{
    int part = 0;
    exr_result_t rc = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (rc) return exr_fail(s, rc, "adding the image part");
    rc = exr_initialize_required_attr_simple(ctx, part, (int32_t)f->width, (int32_t)f->height,
                                             EXR_COMPRESSION_ZIP);
    if (rc) return exr_fail(s, rc, "setting the image size");
    rc = exr_set_lineorder(ctx, part, EXR_LINEORDER_INCREASING_Y);
    if (rc) return exr_fail(s, rc, "setting the line order");
    rc = exr_set_zip_compression_level(ctx, part, EXR_ZIP_LEVEL);
    if (rc) return exr_fail(s, rc, "setting the compression level");
    for (int i = 0; i < n_ch; i++) {
        rc = exr_add_channel(ctx, part, ch[i].name, ch[i].type, ch[i].percept, 1, 1);
        if (rc) return exr_fail(s, rc, "adding a channel");
    }
    if (f->crs_wkt) {
        static const char *const origin_names[3] = {"siteOriginEasting", "siteOriginNorthing",
                                                    "siteOriginHeight"};
        rc = exr_attr_set_string(ctx, part, "siteCrsWkt", f->crs_wkt);
        if (!rc) rc = exr_attr_set_string(ctx, part, "siteCrsName", f->crs_name ? f->crs_name : "");
        for (int k = 0; k < 3 && !rc; k++) rc = exr_attr_set_double(ctx, part, origin_names[k], f->origin[k]);
        if (rc) return exr_fail(s, rc, "adding the site's CRS and origin");
    }
    if (f->has_exposure) {
        rc = exr_attr_set_double(ctx, part, "exposureStops", f->exposure_stops);
        if (rc) return exr_fail(s, rc, "adding the exposure");
    }
    rc = exr_write_header(ctx);
    if (rc) return exr_fail(s, rc, "writing the header");

    int32_t lines_per_chunk = 0;
    rc = exr_get_scanlines_per_chunk(ctx, part, &lines_per_chunk);
    if (rc) return exr_fail(s, rc, "querying the scanlines per chunk");

    const size_t width = f->width;
    /* Half R, G, B of one chunk; owned here. */
    uint16_t *half_rows = NULL;
    if (f->rgb && f->rgb_half) {
        half_rows = malloc(width * (size_t)lines_per_chunk * 3u * sizeof *half_rows);
        if (!half_rows)
            return err_nomem(s->err, "%s: out of memory for a chunk of %d half-float scanlines",
                           s->path, (int)lines_per_chunk);
    }
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int started = 0, status = 0;
    for (int32_t y = 0; y < (int32_t)f->height; y += lines_per_chunk) {
        exr_chunk_info_t cinfo;
        rc = exr_write_scanline_chunk_info(ctx, part, y, &cinfo);
        if (rc) {
            status = exr_fail(s, rc, "preparing a chunk");
            break;
        }
        rc = started ? exr_encoding_update(ctx, part, &cinfo, &enc)
                     : exr_encoding_initialize(ctx, part, &cinfo, &enc);
        if (rc) {
            status = exr_fail(s, rc, "preparing the encoder");
            break;
        }
        const size_t first_px = (size_t)y * width;
        const size_t chunk_px = (size_t)cinfo.height * width;
        if (half_rows)
            for (size_t i = 0; i < 3 * chunk_px; i++)
                half_rows[i] = half_from_float(f->rgb[3 * first_px + i]);

        for (int16_t c = 0; c < enc.channel_count; c++) {
            exr_coding_channel_info_t *out = &enc.channels[c];
            const exr_channel_src *src = NULL;
            for (int i = 0; i < n_ch && !src; i++)
                if (!strcmp(out->channel_name, ch[i].name)) src = &ch[i];
            if (!src) {
                status = err_set(s->err, "%s: the EXR part lists a channel \"%s\" that the frame "
                                 "does not provide", s->path, out->channel_name);
                s->reported = 1;
                break;
            }
            out->user_data_type = (uint16_t)src->type;
            out->user_bytes_per_element = src->type == EXR_PIXEL_HALF ? 2 : 4;
            out->user_pixel_stride = src->pixel_stride;
            out->user_line_stride = (int32_t)(width * (size_t)src->pixel_stride);
            out->encode_from_ptr = src->rgb_index >= 0
                                       ? (const uint8_t *)(half_rows + src->rgb_index)
                                       : src->base + first_px * (size_t)src->pixel_stride;
        }
        if (status) break;
        if (!started) {
            started = 1;
            rc = exr_encoding_choose_default_routines(ctx, part, &enc);
            if (rc) {
                status = exr_fail(s, rc, "choosing the encoder");
                break;
            }
        }
        rc = exr_encoding_run(ctx, part, &enc);
        if (rc) {
            status = exr_fail(s, rc, "compressing and writing scanlines");
            break;
        }
    }
    if (enc.channels) exr_encoding_destroy(ctx, &enc);
    free(half_rows);
    return status;
}

int exr_write_into(atomic_file *out, const exr_frame *f, err_buf *err)
{
    if (!out || out->fd < 0 || !f) return err_set(err, "exr_write_into needs an open temporary and a frame");
    const char *path = out->path;
    if (f->width == 0 || f->height == 0 || f->width > EXR_MAX_SIDE || f->height > EXR_MAX_SIDE)
        return err_set(err, "%s: a frame of %ux%u pixels cannot be written; width and height "
                       "must be between 1 and %d", path, (unsigned)f->width, (unsigned)f->height,
                       EXR_MAX_SIDE);
    exr_channel_src ch[EXR_MAX_CHANNELS];
    int n_ch = exr_frame_channels(f, ch);
    if (n_ch == 0)
        return err_set(err, "%s: the frame has no layers; give at least one of rgb, depth, "
                       "normal, albedo, instance_id, species_id, object_id, development, development_rgb", path);

    exr_stream s = {.fd = out->fd, .path = path, .err = err};

    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = exr_on_error;
    init.user_data = &s;
    init.write_fn = exr_stream_write;

    exr_context_t ctx = NULL;
    int status = 0;
    exr_stream_now = &s;
    exr_result_t rc = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rc) status = exr_fail(&s, rc, "starting the file");
    if (!status) status = exr_write_part(ctx, &s, f, ch, n_ch);
    if (ctx) {
        rc = exr_finish(&ctx); /* writes the chunk offset table */
        if (rc && !status) status = exr_fail(&s, rc, "writing the chunk offset table");
    }
    exr_stream_now = NULL;
    return status ? -1 : 0;
}

int exr_write(const char *path, const exr_frame *f, err_buf *err)
{
    if (!path || !f) return err_set(err, "exr_write needs an output path and a frame");
    atomic_file out;
    if (atomic_file_open(&out, path, err)) return -1;
    if (exr_write_into(&out, f, err)) {
        atomic_file_abort(&out);
        return -1;
    }
    return atomic_file_commit(&out, err);
}
