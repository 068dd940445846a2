/* pov_file.c — streamed scene files and text builders for the POV-Ray exporter. */
#include "pov/pov_file.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "pov/pov_number.h"

#define POV_FILE_BUFFER (1u << 20)

int pov_file_open(pov_file *pf, const char *path, err_buf *err)
{
    memset(pf, 0, sizeof *pf);
    if (strlen(path) >= POV_PATH_MAX) return err_set(err, "%s: output path is too long", path);
    if (!(pf->f = atomic_file_open_stream(&pf->out, path, err))) return -1;
    pf->buffer = malloc(POV_FILE_BUFFER);
    if (pf->buffer) setvbuf(pf->f, pf->buffer, _IOFBF, POV_FILE_BUFFER);
    return 0;
}

int pov_file_finish(pov_file *pf, uint64_t *bytes, err_buf *err)
{
    if (!pf->f) return err_set(err, "%s: the file was not open", pf->out.path);
    long size = ftell(pf->f);
    int rc = atomic_file_commit(&pf->out, err); /* closes the stream before its buffer goes */
    pf->f = NULL;
    free(pf->buffer);
    pf->buffer = NULL;
    if (rc) return -1;
    if (bytes && size > 0) *bytes += (uint64_t)size;
    return 0;
}

void pov_file_abort(pov_file *pf)
{
    atomic_file_abort(&pf->out);
    pf->f = NULL;
    free(pf->buffer);
    pf->buffer = NULL;
}

void pov_put(pov_file *pf, const char *text)
{
    fputs(text, pf->f);
}

void pov_printf(pov_file *pf, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(pf->f, fmt, ap);
    va_end(ap);
}

char *pov_append_text(char *p, const char *text)
{
    size_t n = strlen(text);
    memcpy(p, text, n + 1);
    return p + n;
}

char *pov_append_uint(char *p, uint64_t v)
{
    char digits[24];
    int n = 0;
    do {
        digits[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (n) *p++ = digits[--n];
    *p = '\0';
    return p;
}

/* The end of a number of length n written at p; a non-finite one (n < 0, written "0") counted. */
static char *number_end(char *p, int n, int *bad)
{
    if (n >= 0) return p + n;
    if (bad) (*bad)++;
    return p + 1;
}

char *pov_append_real(char *p, double v, int digits, int *bad)
{
    return number_end(p, pov_format_real(p, v, digits), bad);
}

char *pov_append_float(char *p, float v, int *bad)
{
    return number_end(p, pov_format_float(p, v), bad);
}

char *pov_append_position(char *p, float v, int *bad)
{
    return number_end(p, pov_format_position(p, v), bad);
}

char *pov_append_vec3(char *p, const double v[3], int digits, int *bad)
{
    *p++ = '<';
    p = pov_append_real(p, v[0], digits, bad);
    p = pov_append_text(p, ", ");
    p = pov_append_real(p, v[1], digits, bad);
    p = pov_append_text(p, ", ");
    p = pov_append_real(p, v[2], digits, bad);
    return pov_append_text(p, ">");
}

char *pov_append_vec3f(char *p, float x, float y, float z, int *bad)
{
    *p++ = '<';
    p = pov_append_float(p, x, bad);
    p = pov_append_text(p, ", ");
    p = pov_append_float(p, y, bad);
    p = pov_append_text(p, ", ");
    p = pov_append_float(p, z, bad);
    return pov_append_text(p, ">");
}
