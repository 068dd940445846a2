/* lsys_symbols.c — byte classes of the L-parser alphabet and the argument group reader. */
#include "lsys_symbols.h"

#include <math.h>

int lsys_is_command(unsigned char c)
{
    switch (c) {
    case 'F': case 'Z': case 'f': case 'z': case 'g': case '.':
    case '+': case '-': case '&': case '^': case '<': case '>': case '|': case '%': case '$':
    case 't': case '~': case '[': case ']': case '{': case '}': case 'c':
    case '"': case '\'': case ';': case ':': case '?': case '!': case '_':
        return 1;
    default:
        return 0;
    }
}

int lsys_is_variable(unsigned char c)
{
    if (c >= 0x80) return 1;
    if (c >= '0' && c <= '9') return 1;
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')) return !lsys_is_command(c);
    return 0;
}

size_t lsys_parse_number(const unsigned char *s, size_t n, double *value)
{
    size_t i = 0;
    int negative = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
    /* Digits are gathered as an integer mantissa and a decimal exponent; the quotient of two
     * exactly representable numbers is then correctly rounded, so "15.652" reads exactly as
     * strtod would read it for every argument the language uses. */
    double mantissa = 0.0;
    int exponent = 0, digits = 0;
    while (i < n && s[i] >= '0' && s[i] <= '9') {
        if (digits < 18) mantissa = mantissa * 10.0 + (s[i] - '0');
        else exponent++;
        digits++, i++;
    }
    if (i < n && s[i] == '.') {
        i++;
        while (i < n && s[i] >= '0' && s[i] <= '9') {
            if (digits < 18) mantissa = mantissa * 10.0 + (s[i] - '0'), exponent--;
            digits++, i++;
        }
    }
    if (!digits) return 0;
    if (i + 1 < n && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        int eneg = 0, e = 0, edigits = 0;
        if (j < n && (s[j] == '+' || s[j] == '-')) eneg = s[j++] == '-';
        while (j < n && s[j] >= '0' && s[j] <= '9') {
            if (e < 10000) e = e * 10 + (s[j] - '0');
            edigits++, j++;
        }
        if (edigits) {
            exponent += eneg ? -e : e;
            i = j;
        }
    }
    double v;
    if (mantissa == 0.0 || exponent == 0) v = mantissa; /* 0e400 is 0, not 0 * inf */
    else if (exponent > 0 && exponent <= 22) v = mantissa * pow(10.0, exponent);
    else if (exponent < 0 && exponent >= -22) v = mantissa / pow(10.0, -exponent);
    else v = mantissa * pow(10.0, exponent);
    if (value) *value = negative ? -v : v;
    return i;
}

/* The length of the group at s and its number, finite or not; 0 when s does not start one. */
static size_t arg_group_any(const unsigned char *s, size_t n, double *value)
{
    if (n < 3 || s[0] != '(') return 0;
    if (n > LSYS_ARG_MAX) n = LSYS_ARG_MAX;
    size_t i = 1;
    while (i < n && (s[i] == ' ' || s[i] == '\t')) i++;
    double v = 0.0;
    size_t k = lsys_parse_number(s + i, n - i, &v);
    if (!k) return 0;
    i += k;
    while (i < n && (s[i] == ' ' || s[i] == '\t')) i++;
    if (i >= n || s[i] != ')') return 0;
    if (value) *value = v;
    return i + 1;
}

size_t lsys_arg_group(const unsigned char *s, size_t n, double *value)
{
    double v = 0.0;
    size_t g = arg_group_any(s, n, &v);
    if (!g || !isfinite(v)) return 0;
    if (value) *value = v;
    return g;
}

size_t lsys_arg_out_of_range(const unsigned char *s, size_t n)
{
    double v = 0.0;
    size_t g = arg_group_any(s, n, &v);
    return g && !isfinite(v) ? g : 0;
}
