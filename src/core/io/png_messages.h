/* png_messages.h — libpng's error and warning handlers for sylva's own readers and writers of
 * PNGs (png_read_check.c, png_write.c): libpng's defaults print on stderr, these keep the error's
 * words for sylva's sentence and let warnings pass in silence. */
#ifndef SYLVA_PNG_MESSAGES_H
#define SYLVA_PNG_MESSAGES_H

#include <png.h>

#define PNG_MESSAGE_MAX 160 /* the room of the error pointer's buffer, in bytes */

/* Keeps the message in the PNG_MESSAGE_MAX bytes the error pointer gives and jumps back to the
 * setjmp of png_jmpbuf. */
void png_keep_error(png_structp png, png_const_charp message);

/* Ignores a warning: what libpng only warns of (an ancillary chunk it skips, a compression
 * setting it changes) is no damage. */
void png_ignore_warning(png_structp png, png_const_charp message);

#endif
