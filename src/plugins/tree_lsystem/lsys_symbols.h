/* lsys_symbols.h — the alphabet of the L-parser language: which bytes are turtle commands,
 * which are rule variables, and the argument group "(number)" that may follow any symbol.
 * The reader, the derivation and the turtle all classify bytes through these functions, so
 * the three agree on what a symbol is. */
#ifndef LSYS_SYMBOLS_H
#define LSYS_SYMBOLS_H

#include <stddef.h>

/* Longest argument group accepted, "(" and ")" included. */
#define LSYS_ARG_MAX 64

/* 1 when byte c is a turtle command: F Z f z g . + - & ^ < > | % $ t ~ [ ] { } c " ' ; : ? ! _ */
int lsys_is_command(unsigned char c);

/* 1 when c may name a rule without being a command: A-Z and a-z other than the command letters,
 * the digits, and every byte from 0x80 (Latin-1 letters). Commands may name rules too. */
int lsys_is_variable(unsigned char c);

/* When s[0] == '(' starts an argument group — optional blanks, a number as lsys_parse_number
 * reads it, optional blanks, ')' — returns the group's length in bytes (at most LSYS_ARG_MAX)
 * and stores the number in *value (may be NULL). Returns 0 when s does not start one; a number
 * beyond the range of doubles (such as 1e400) starts none, so no caller sees inf or NaN. */
size_t lsys_arg_group(const unsigned char *s, size_t n, double *value);

/* The length of the group at s when it would be one but for its number being beyond the range
 * of doubles (about ±1.8e308), else 0: lets the reader say so instead of "not an argument". */
size_t lsys_arg_out_of_range(const unsigned char *s, size_t n);

/* Reads a decimal number from s[0..n): optional sign, digits, optional fraction (".95" and
 * "3." included), optional exponent. Returns the bytes read (0: no number) and the value. */
size_t lsys_parse_number(const unsigned char *s, size_t n, double *value);

#endif
