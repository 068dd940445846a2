/* png_messages.c — libpng's handlers for sylva (png_messages.h). */
#include "io/png_messages.h"

#include <stdio.h>

void png_keep_error(png_structp png, png_const_charp message)
{
    char *keep = png_get_error_ptr(png);
    snprintf(keep, PNG_MESSAGE_MAX, "%s", message);
    png_longjmp(png, 1);
}

void png_ignore_warning(png_structp png, png_const_charp message)
{
    (void)png, (void)message;
}
