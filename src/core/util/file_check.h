/* file_check.h — what a scene may name as an input file: a regular file on the local disk.
 *
 * A FIFO, a device (/dev/zero), a socket or a folder named where a file is read would block
 * the open or feed a reader without end, so inputs are checked before any reader sees them.
 * Paths that GDAL would take for something other than a local file (its virtual file systems
 * "/vsi...", URLs "scheme://", connection strings "DRIVER:...") are refused unless the user
 * allowed them on the command line (--allow-gdal-virtual), because they can make sylva reach
 * the network. Messages name the path and what kind of thing it is, never its content. */
#ifndef SYLVA_FILE_CHECK_H
#define SYLVA_FILE_CHECK_H

#include "util/err.h"

/* 0 when path (after symbolic links) is a regular file; otherwise -1 with err set to
 * "LABEL: not a regular file: it is a FIFO (named pipe)" or "LABEL: cannot open: <reason>",
 * where label is the text before the reason (NULL: the path itself). */
int file_check_regular(const char *path, const char *label, err_buf *err);

/* Opens path for reading without blocking on a FIFO or device (O_NONBLOCK open, then fstat on
 * the descriptor, then back to blocking mode). Returns the descriptor (the caller closes it)
 * or -1 with err set as by file_check_regular. */
int file_open_regular(const char *path, const char *label, err_buf *err);

/* 1 when text is a GDAL virtual file path ("/vsicurl/..."), a URL ("https://...") or a GDAL
 * connection string ("PG:...", "WMS:..."): anything GDAL would not read as a local file. */
int file_is_gdal_virtual(const char *text);

/* The process-wide choice of the command line: 1 lets scenes name GDAL virtual paths. Set once
 * by the command-line parser before any scene is read; 0 by default. */
void file_allow_gdal_virtual(int allow);
int file_gdal_virtual_allowed(void);

#endif
