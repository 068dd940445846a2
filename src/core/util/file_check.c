/* file_check.c — regular-file checks before reading, and the GDAL virtual-path rule. */
#include "util/file_check.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static atomic_int gdal_virtual_allowed;

static int not_regular(const char *label, mode_t m, err_buf *err)
{
    const char *kind = S_ISDIR(m)    ? "a folder"
                       : S_ISFIFO(m) ? "a FIFO (named pipe)"
                       : S_ISCHR(m)  ? "a character device"
                       : S_ISBLK(m)  ? "a block device"
                       : S_ISSOCK(m) ? "a socket"
                                     : "a special file";
    return err_set(err, "%s: not a regular file: it is %s", label, kind);
}

int file_check_regular(const char *path, const char *label, err_buf *err)
{
    if (!label) label = path;
    struct stat st;
    if (stat(path, &st) != 0) return err_set(err, "%s: cannot open: %s", label, strerror(errno));
    if (!S_ISREG(st.st_mode)) return not_regular(label, st.st_mode, err);
    return 0;
}

int file_open_regular(const char *path, const char *label, err_buf *err)
{
    if (!label) label = path;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return err_set(err, "%s: cannot open: %s", label, strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return err_set(err, "%s: cannot open: %s", label, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return not_regular(label, st.st_mode, err);
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0) {
        int e = errno;
        close(fd);
        return err_set(err, "%s: cannot open: %s", label, strerror(e));
    }
    return fd;
}

int file_is_gdal_virtual(const char *text)
{
    if (!text) return 0;
    if (!strncmp(text, "/vsi", 4)) return 1;
    /* "scheme://..." or "DRIVER:..." : letters (and digits, '+', '-', '.') before a colon, with
     * no slash before it; a one-letter prefix is a Windows drive, not a driver */
    size_t n = 0;
    while (isalnum((unsigned char)text[n]) || text[n] == '_' || text[n] == '+' ||
           text[n] == '-' || text[n] == '.')
        n++;
    return n >= 2 && text[n] == ':' && isalpha((unsigned char)text[0]);
}

void file_allow_gdal_virtual(int allow) { atomic_store(&gdal_virtual_allowed, allow ? 1 : 0); }

int file_gdal_virtual_allowed(void) { return atomic_load(&gdal_virtual_allowed); }
