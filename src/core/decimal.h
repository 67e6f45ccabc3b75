/* decimal.h — certified decimal strings for arb balls, and back.
 *
 * A decimal string d with k significant digits is *certified* for the ball x
 * when x lies inside [d - u/2, d + u/2], u = one unit in the last digit of d:
 * then d is a correct rounding of the exact value, whatever it is in x, and a
 * reader may take d as the ball of radius u/2 (vigen_decimal_parse_rounded).
 */
#ifndef VIGEN_DECIMAL_H
#define VIGEN_DECIMAL_H

#include <arb.h>

/* The largest decimal exponent read from input ("1e100000000"; the exact
 * expression parser refuses more, the rounded-decimal reader does not read
 * it as a rounded decimal): 10^(10^8) is 2^(3.3 10^8), far inside arb's
 * range, and far beyond the precision cap. */
#define VIGEN_DECIMAL_EXP_MAX 100000000L

/* The smallest exponent vigen_decimal_format_zero writes: a ball smaller than
 * 10^-VIGEN_DECIMAL_ZERO_EXP_MIN is written as 0e-VIGEN_DECIMAL_ZERO_EXP_MIN
 * (still certified), so that a ball of radius 2^-(10^9) costs nothing to
 * format. */
#define VIGEN_DECIMAL_ZERO_EXP_MIN 1000000L

/* Formats x with `digits` significant digits ("-0.1234", "1.2345e-7").  Returns
 * a heap string, or NULL when the ball is too wide to certify that many digits
 * (or contains 0, or |x| is beyond 10^+-VIGEN_DECIMAL_EXP_MAX).  Exact zero
 * gives "0". */
char *vigen_decimal_format(const arb_t x, slong digits);

/* For a ball containing 0: the string "0eK" (K <= 0 the largest exponent such
 * that |x| <= 10^K / 2 is certified, but at least -VIGEN_DECIMAL_ZERO_EXP_MIN),
 * or NULL when |x| may exceed 1/2. */
char *vigen_decimal_format_zero(const arb_t x);

/* 1 if text is a plain decimal with a point or an exponent: [+-]digits[.digits][e[+-]digits]. */
int vigen_decimal_is_rounded(const char *text);

/* Parses a plain decimal as the ball of radius half a unit in its last digit.
 * Returns 1 on success, 0 if text is not a plain decimal. */
int vigen_decimal_parse_rounded(arb_t res, const char *text, slong prec);

/* Number of significant digits of a plain decimal ("0.0012300" -> 5). */
slong vigen_decimal_significant_digits(const char *text);

/* For an exact integer ball (radius 0, integral midpoint, |x| < 2^256): its
 * decimal digits ("1", "-3", "0"), an exact literal.  NULL otherwise. */
char *vigen_decimal_format_integer(const arb_t x);

/* The exact value of a plain decimal as a fraction in lowest terms ("0.25" ->
 * "1/4", "-1.50" -> "-3/2", "2.0" -> "2", "5e-1" -> "1/2"), or NULL when text
 * is not a plain decimal or its exponent is beyond +-1000. */
char *vigen_decimal_exact_fraction(const char *text);

/* Half a unit in the last digit of a plain decimal, the radius it is read
 * with, as a decimal ("0.5" -> "0.05", "0.25" -> "0.005", "1.5e-8" ->
 * "5e-10", "12" is not a plain decimal), or NULL. */
char *vigen_decimal_half_unit(const char *text);

#endif
