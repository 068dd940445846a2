/* gltf_check.c — the mimeType, uri and mode values of a glTF (JSON) or GLB (its JSON chunk is text
 * in the file) checked before Assimp reads it (gltf_check.h). */
#include "model/gltf_check.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Where the value of the key that starts at data[at] (its quotes included) starts, past the colon
 * and the white space; size when the key is followed by no colon. */
static size_t value_at(const char *data, size_t size, size_t at, size_t key_len)
{
    size_t p = at + key_len;
    while (p < size && data[p] && strchr(" \t\r\n", data[p])) p++;
    if (p >= size || data[p] != ':') return size;
    for (p++; p < size && data[p] && strchr(" \t\r\n", data[p]); p++) {}
    return p;
}

/* The string value of the key that starts at data[at] (its quotes included), as [*start, *end)
 * of data, escapes left as they are; 0 when the key has no string value there. */
static int string_value(const char *data, size_t size, size_t at, size_t key_len, size_t *start, size_t *end)
{
    size_t p = value_at(data, size, at, key_len);
    if (p >= size || data[p] != '"') return 0;
    *start = ++p;
    while (p < size && data[p] != '"') p += data[p] == '\\' ? 2 : 1;
    *end = p < size ? p : size;
    return 1;
}

/* Whether the value of the key that starts at data[at] (its quotes included) is the JSON number 2,
 * written so (an integer, as Assimp's reader takes a primitive's mode). */
static int number_two(const char *data, size_t size, size_t at, size_t key_len)
{
    size_t p = value_at(data, size, at, key_len);
    return p < size && data[p] == '2' && (p + 1 >= size || !data[p + 1] || !strchr("0123456789.eE", data[p + 1]));
}

/* Whether the JSON string text[0..n) (escapes as written) decodes to a path that Assimp's path
 * filter reads past: 1 when it ends with "://", 2 when it is two backslashes alone, else 0.
 * Escapes other than \/ and \\ decode to some other byte, which is all the test needs. */
static int unsafe_uri(const char *text, size_t n)
{
    char first[2] = {0}, last[3] = {0};
    size_t len = 0;
    for (size_t i = 0; i < n; i++) {
        char c = text[i];
        if (c == '\\' && i + 1 < n) c = text[++i] == '/' || text[i] == '\\' ? text[i] : '?';
        if (len < 2) first[len] = c;
        memmove(last, last + 1, 2), last[2] = c;
        len++;
    }
    if (len >= 3 && !memcmp(last, "://", 3)) return 1;
    return len == 2 && first[0] == '\\' && first[1] == '\\' ? 2 : 0;
}

int gltf_check(const char *path, err_buf *err)
{
    FILE *f = fopen(path, "rb");
    if (!f) return err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, strerror(errno));
    char *data = NULL; /* owned here */
    int rc = -1;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) {
        err_fail(err, ERR_INPUT, "%s: cannot read the model: %s", path, strerror(errno));
    } else if (!(data = malloc((size_t)size + 1))) {
        err_nomem(err, "%s: out of memory reading %ld bytes", path, size);
    } else if (fread(data, 1, (size_t)size, f) != (size_t)size) {
        err_fail(err, ERR_INPUT, "%s: cannot read the model: a read error", path);
    } else {
        static const char mime[] = "\"mimeType\"", uri[] = "\"uri\"", mode[] = "\"mode\"";
        rc = 0;
        size_t start, end;
        for (size_t at = 0; !rc && at < (size_t)size; at++) {
            int bad;
            if (at + sizeof mime - 1 <= (size_t)size && !memcmp(data + at, mime, sizeof mime - 1) &&
                string_value(data, (size_t)size, at, sizeof mime - 1, &start, &end) &&
                !memchr(data + start, '/', end - start)) {
                size_t n = end - start;
                rc = err_fail(err, ERR_INPUT, "%s: an image's mimeType is '%.*s'; image/png or image/jpeg is valid",
                              path, (int)(n > 40 ? 40 : n), data + start);
            } else if (at + sizeof uri - 1 <= (size_t)size && !memcmp(data + at, uri, sizeof uri - 1) &&
                       string_value(data, (size_t)size, at, sizeof uri - 1, &start, &end) &&
                       (bad = unsafe_uri(data + start, end - start))) {
                rc = err_fail(err, ERR_INPUT, "%s: a uri %s; name a file beside the model (model.bin)", path,
                              bad == 2 ? "is two backslashes" : "ends with \"://\"");
            } else if (at + sizeof mode - 1 <= (size_t)size && !memcmp(data + at, mode, sizeof mode - 1) &&
                       number_two(data, (size_t)size, at, sizeof mode - 1)) {
                rc = err_fail(err, ERR_INPUT, "%s: a mesh primitive is a line loop (mode 2), on which the model "
                              "reader can crash; sylva draws triangles: export the mesh as "
                              "triangles (mode 4) or leave the line loop out", path);
            }
        }
    }
    free(data);
    fclose(f);
    return rc;
}
