/* gltf_check.c — the keys, the mimeType, uri and mode values and the byte layout (gltf_layout.h)
 * of a glTF (JSON) or GLB (its JSON chunk is text in the file) checked before Assimp reads it
 * (gltf_check.h). */
#include "model/gltf_check.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/gltf_layout.h"

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

/* Where the first key written with an escape ("mod\u0065") starts in the JSON text[0..n), n when
 * there is none. The text's strings are followed from its start, so that what a string value
 * holds is never taken for a key; a key is a string followed by a colon. */
static size_t escaped_key(const char *text, size_t n)
{
    for (size_t p = 0; p < n; p++) {
        if (text[p] != '"') continue;
        size_t start = p;
        int escaped = 0;
        for (p++; p < n && text[p] != '"'; p++)
            if (text[p] == '\\') escaped = 1, p++;
        if (p >= n) break;
        size_t q = p + 1;
        while (q < n && text[q] && strchr(" \t\r\n", text[q])) q++;
        if (escaped && q < n && text[q] == ':') return start;
    }
    return n;
}

static uint64_t le32(const char *p)
{
    const unsigned char *b = (const unsigned char *)p;
    return (uint64_t)b[0] | (uint64_t)b[1] << 8 | (uint64_t)b[2] << 16 | (uint64_t)b[3] << 24;
}

/* The JSON of a glTF file: all of it, or a GLB's first chunk (glb_check has found its length
 * within the file). *bin: the length of a GLB's BIN chunk, found as Assimp finds it (after the
 * JSON chunk padded to 4 bytes, when the length the header states reaches past its header; 0
 * when it does not), GLTF_NO_BIN when the file is not a GLB. */
static void json_text(const char *data, size_t size, const char **text, size_t *n, uint64_t *bin)
{
    *text = data, *n = size, *bin = GLTF_NO_BIN;
    if (size >= 20 && !memcmp(data, "glTF", 4) && !memcmp(data + 16, "JSON", 4)) {
        uint64_t len = le32(data + 12), body = 20 + ((len + 3) & ~(uint64_t)3);
        *text = data + 20, *n = len < size - 20 ? (size_t)len : size - 20;
        *bin = le32(data + 8) >= body + 8 && body + 8 <= size ? le32(data + body) : 0;
    }
}

/* 0 when no key of the JSON text[0..n) is written with an escape; -1 with err set naming the
 * first, with its line and column in the JSON (glb: the JSON is a GLB's chunk, named so). */
static int keys_plain(const char *path, const char *text, size_t n, int glb, err_buf *err)
{
    size_t at = escaped_key(text, n), line = 1, column = 1, end = at + 1;
    if (at >= n) return 0;
    for (size_t i = 0; i < at; i++) column = text[i] == '\n' ? (line++, 1) : column + 1;
    while (end < n && text[end] != '"') end += text[end] == '\\' ? 2 : 1;
    int len = (int)((end < n ? end + 1 : n) - at > 40 ? 40 : (end < n ? end + 1 : n) - at);
    char where[80];
    snprintf(where, sizeof where, glb ? ": the JSON chunk, line %zu, column %zu" : ":%zu:%zu", line, column);
    return err_fail(err, ERR_INPUT,
                    "%s%s: the key %.*s is written with an escape; a glTF's keys are plain names (\"uri\", "
                    "\"mode\", \"mimeType\"): write it without one",
                    path, where, len, text + at);
}

/* 0 when every "mimeType" value holds a '/', no "uri" value is one Assimp's path filter reads past
 * and no "mode" is 2; -1 with err set naming the first that fails. */
static int values_checked(const char *path, const char *data, size_t size, err_buf *err)
{
    static const char mime[] = "\"mimeType\"", uri[] = "\"uri\"", mode[] = "\"mode\"";
    size_t start, end;
    for (size_t at = 0; at < size; at++) {
        int bad;
        if (at + sizeof mime - 1 <= size && !memcmp(data + at, mime, sizeof mime - 1) &&
            string_value(data, size, at, sizeof mime - 1, &start, &end) && !memchr(data + start, '/', end - start)) {
            size_t n = end - start;
            return err_fail(err, ERR_INPUT, "%s: an image's mimeType is '%.*s'; image/png or image/jpeg is valid",
                            path, (int)(n > 40 ? 40 : n), data + start);
        }
        if (at + sizeof uri - 1 <= size && !memcmp(data + at, uri, sizeof uri - 1) &&
            string_value(data, size, at, sizeof uri - 1, &start, &end) &&
            (bad = unsafe_uri(data + start, end - start)))
            return err_fail(err, ERR_INPUT, "%s: a uri %s; name a file beside the model (model.bin)", path,
                            bad == 2 ? "is two backslashes" : "ends with \"://\"");
        if (at + sizeof mode - 1 <= size && !memcmp(data + at, mode, sizeof mode - 1) &&
            number_two(data, size, at, sizeof mode - 1))
            return err_fail(err, ERR_INPUT, "%s: a mesh primitive is a line loop (mode 2), on which the model "
                            "reader can crash; sylva draws triangles: export the mesh as "
                            "triangles (mode 4) or leave the line loop out", path);
    }
    return 0;
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
        const char *text;
        size_t n;
        uint64_t bin;
        json_text(data, (size_t)size, &text, &n, &bin);
        char where[ERR_FILE_MAX + 32];
        snprintf(where, sizeof where, bin != GLTF_NO_BIN ? "%s (its JSON chunk)" : "%s", path);
        rc = keys_plain(path, text, n, bin != GLTF_NO_BIN, err) || values_checked(path, data, (size_t)size, err) ||
                     gltf_layout_check(text, n, bin, where, err)
                 ? -1
                 : 0;
    }
    free(data);
    fclose(f);
    return rc;
}
