/* gltf_check.c — every "mimeType" value of a glTF (JSON) or GLB (its JSON chunk is text in the
 * file) must hold a '/' (gltf_check.h). */
#include "model/gltf_check.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
        static const char key[] = "\"mimeType\"";
        rc = 0;
        for (size_t at = 0; !rc && at + sizeof key - 1 <= (size_t)size; at++) {
            if (memcmp(data + at, key, sizeof key - 1)) continue;
            size_t p = at + sizeof key - 1;
            while (p < (size_t)size && strchr(" \t\r\n", data[p]) && data[p]) p++;
            if (p >= (size_t)size || data[p] != ':') continue;
            for (p++; p < (size_t)size && strchr(" \t\r\n", data[p]) && data[p]; p++) {}
            if (p >= (size_t)size || data[p] != '"') continue;
            size_t start = ++p;
            while (p < (size_t)size && data[p] != '"' && data[p] != '/') p += data[p] == '\\' ? 2 : 1;
            if (p < (size_t)size && data[p] == '/') continue;
            size_t n = (p < (size_t)size ? p : (size_t)size) - start;
            rc = err_fail(err, ERR_INPUT, "%s: an image's mimeType is '%.*s'; image/png or image/jpeg is valid", path,
                          (int)(n > 40 ? 40 : n), data + start);
        }
    }
    free(data);
    fclose(f);
    return rc;
}
