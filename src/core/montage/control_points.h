/* control_points.h — a camera match's control points read from a file: pairs of a pixel in the
 * photograph and the position of the same thing in the world. Two formats (docs/photomontage.md):
 *
 *  - CSV with a header line naming the columns: `u`, `v` (the pixel), then `easting`, `northing`,
 *    `height` (map coordinates) or `x`, `y`, `z` (local metres), optionally `id`; blank lines and
 *    lines starting with '#' are skipped.
 *  - ImGRAFT's text format: whitespace-separated columns X Y Z U V (map coordinates, then the
 *    pixel), '%' starting a comment; U and V may be written as sums such as `1951+9` (numbers
 *    joined by + and -, nothing else). ImGRAFT counts pixels from 1 at the centre of the top-left
 *    pixel, so 0.5 is taken off U and V to give sylva's pixel.
 *
 * A file whose first line that is not blank or a comment holds a comma is CSV; otherwise it is
 * the ImGRAFT format. Pixels are continuous: x right, y down, (0, 0) the top-left corner of the
 * image (render/camera.h). Every problem is reported at file:line:column. */
#ifndef SYLVA_CONTROL_POINTS_H
#define SYLVA_CONTROL_POINTS_H

#include <stdint.h>

#include "util/err.h"

#define CONTROL_POINTS_MAX 100000u

typedef struct control_point {
    const char *id;      /* the id column, or the point's number in the file ("1", "2", ...) */
    double pixel[2];     /* continuous pixel: x right, y down from the top-left corner */
    double world[3];     /* map (easting, northing, height) or local (x, y, z) metres, as read */
    uint32_t line;       /* where it was read, for messages */
    uint32_t column;     /* where its u (ImGRAFT: U) starts on that line */
} control_point;

typedef struct control_points {
    control_point *points;
    uint32_t n;
    int map;             /* 1: world is in map coordinates (local = map - site origin); 0: local */
    double pixel_shift;  /* the file's pixel minus sylva's: 0.5 for ImGRAFT's, 0 for CSV */
    struct arena *arena; /* owns points and their ids */
} control_points;

/* Reads path (shown as `shown` in messages; NULL: path itself). Returns a new set (caller frees
 * with control_points_free) or NULL with err set. An empty file, or one without points, is an
 * error. */
control_points *control_points_read(const char *path, const char *shown, err_buf *err);
void control_points_free(control_points *cp); /* accepts NULL */

/* Every point's pixel must lie on the photograph `photo` of width x height pixels (upright):
 * 0 when they do, else -1 with err at the first point outside (file:line:column, ERR_INPUT)
 * naming the point, its pixel as the file writes it and the photograph's size. `shown` names
 * the control-point file. */
int control_points_check_image(const control_points *cp, const char *shown, const char *photo, uint32_t width,
                               uint32_t height, err_buf *err);

#endif
