/* pov_number.h — numbers as POV-Ray scene text: short, exact enough and fast, since an export
 * formats tens of millions of them. Plain decimal notation (no exponent) for magnitudes in
 * [1e-5, 1e9), trailing zeros dropped, "0" for zero of either sign; other magnitudes in
 * exponent notation, which POV-Ray reads too.
 *
 * Nothing here allocates; every function writes at most POV_NUMBER_MAX bytes including the
 * terminating NUL. */
#ifndef SYLVA_POV_NUMBER_H
#define SYLVA_POV_NUMBER_H

#define POV_NUMBER_MAX 32

/* v with `digits` significant digits (1..9). Returns the text's length, or -1 (buf holds "0")
 * when v is not finite. */
int pov_format_real(char *buf, double v, int digits);

/* The shortest text of at most 9 significant digits that a reader rounding to float gets back
 * as exactly f. Returns the length, or -1 (buf holds "0") when f is not finite. */
int pov_format_float(char *buf, float f);

/* A position in metres that POV-Ray keeps in double precision (a matrix's translation): the
 * text of pov_format_float when its value lies within POV_POSITION_TOLERANCE of f, else f to
 * six decimals. The shortest text for a float is only within half a float step of it, a
 * quarter of a millimetre 7 km from the origin, where the renderer's float stands exactly.
 * Returns the length, or -1 (buf holds "0") when f is not finite. */
#define POV_POSITION_TOLERANCE 5e-7
int pov_format_position(char *buf, float f);

#endif
